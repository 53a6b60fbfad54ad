#pragma once
// config<Kernel, Correction, Quadrature, Geometry, Material, Contact>: one type that names a
// whole method (docs/method.md section 9.2), with defaults for the paper's common case and
// rebinding aliases so that a tutorial swaps one choice in one line:
//   using paper_q4 = config<>::with_quadrature<quadrature::q4>;

#include <string>

#include <rkpm/correction/polynomial_bases.hpp>
#include <rkpm/concepts/contact.hpp>
#include <rkpm/concepts/correction.hpp>
#include <rkpm/concepts/geometry.hpp>
#include <rkpm/concepts/kernel.hpp>
#include <rkpm/concepts/material.hpp>
#include <rkpm/concepts/quadrature.hpp>
#include <rkpm/contact/none.hpp>
#include <rkpm/quadrature/cell_rules.hpp>
#include <rkpm/quadrature/shaped_rules.hpp>
#include <rkpm/quadrature/vci.hpp>
#include <rkpm/quadrature/scni.hpp>
#include <rkpm/geometry/axisymmetric.hpp>
#include <rkpm/geometry/plane_strain.hpp>
#include <rkpm/kernel/cubic_spline.hpp>
#include <rkpm/kernel/quartic_spline.hpp>
#include <rkpm/material/j2_plasticity.hpp>

namespace rkpm {

template <class K = kernel::cubic_spline, class C = correction::linear, class Q = quadrature::q2,
          class G = geometry::plane_strain,
          class M = material::j2_plasticity<material::hardening::linear>, class Ct = contact::none>
struct config {
  static_assert(Kernel<K>, "rkpm::config: parameter 1 must be a Kernel (kernel::cubic_spline, kernel::quartic_spline)");
  static_assert(Correction<C>, "rkpm::config: parameter 2 must be a Correction (correction::linear, correction::quadratic)");
  static_assert(Quadrature<Q>, "rkpm::config: parameter 3 must be a Quadrature rule (quadrature::q2, q4, q9, q2_split, q2_tri, q2_vci, q4_vci, vci<Rule>, scni<Beta>, scni_plain)");
  static_assert(Geometry<G>, "rkpm::config: parameter 4 must be a Geometry (geometry::plane_strain, geometry::axisymmetric)");
  static_assert(Material<M>, "rkpm::config: parameter 5 must be a Material (material::elastic, material::j2_plasticity<H>)");
  static_assert(Contact<Ct>, "rkpm::config: parameter 6 must be a Contact policy (contact::none, contact::particle_to_segment<E, F>)");

  using kernel_type = K;
  using correction_type = C;
  using quadrature_type = Q;
  using geometry_type = G;
  using material_type = M;
  using contact_type = Ct;

  template <class X> using with_kernel = config<X, C, Q, G, M, Ct>;
  template <class X> using with_correction = config<K, X, Q, G, M, Ct>;
  template <class X> using with_quadrature = config<K, C, X, G, M, Ct>;
  template <class X> using with_geometry = config<K, C, Q, X, M, Ct>;
  template <class X> using with_material = config<K, C, Q, G, X, Ct>;
  template <class X> using with_contact = config<K, C, Q, G, M, X>;

  // "cubic-linear-q2-plane_strain-j2+linear-none": one name per configuration (composed
  // policies join their parts with '+'), for messages, file names and benchmarks.
  static std::string name() {
    return std::string(K::name) + "-" + std::string(C::name) + "-" + std::string(Q::name) + "-" +
           std::string(G::name) + "-" + std::string(M::name) + "-" + std::string(Ct::name);
  }
};

}  // namespace rkpm
