#pragma once
// Stable time step of the central-difference scheme, dt_crit = 2 / omega_max, with
// omega_max^2 the largest eigenvalue of M^-1 K (docs/method.md (45)-(49), section 5.6).
// K is the elastic tangent stiffness of the discretization about a configuration given by
// the deformation gradient at each quadrature point (the reference configuration when none is
// given), applied matrix-free:
//   dH = sum_I x_I (x) grad_X N_I,  de = sym(dH F^-1),  de33 = (dx_r / R) / F33,
//   ds = lambda tr(de) I + 2 mu de,  f_I = sum_q [J ds F^-T grad_X N_I + e_r J ds33 N_I /(R F33)] w_q
// Power iteration finds omega_max; it approaches it from below, so callers keep a safety
// fraction. Warm-started from the previous run's vector, a few iterations follow the spectrum
// as the body deforms (the Taylor bar's impact face is crushed to a tenth of its spacing).
// With several bodies of different constants (point_moduli) K is block diagonal, one block per
// body, so omega_max is the largest over the bodies: the fastest body governs the step.

#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <type_traits>
#include <vector>

#include <rkpm/concepts/geometry.hpp>
#include <rkpm/core/execution.hpp>
#include <rkpm/material/elastic_constants.hpp>
#include <rkpm/solver/discrete_model.hpp>
#include <rkpm/solver/point_forces.hpp>

namespace rkpm {

// Scratch of the matrix-free stiffness and the power iteration, sized once (no allocation per call).
struct stiffness_workspace {
  std::vector<vec2> kx;
  block_sums<2> sums;  // x.Kx and x.Mx, in a fixed order
  explicit stiffness_workspace(const discrete_model& m)
      : kx(m.particle_count()), sums(m.own.particles.size(), m.own.group) {}
};

// The Lame moduli (lambda, mu) at each quadrature point: one pair per body and the body of
// each point (solver/body_materials.hpp fills them; empty point_body: one body everywhere).
struct point_moduli {
  std::vector<std::array<double, 2>> body;  // lambda, mu (Pa) of body b
  std::vector<stored_index> point_body;     // #points, or empty

  point_moduli() = default;
  explicit point_moduli(const material::elastic_constants& c) : body{{c.lame_lambda(), c.shear_modulus()}} {}
  const std::array<double, 2>& at(index_t q) const { return point_body.empty() ? body[0] : body[point_body[q]]; }
};

namespace detail {

// out = K x about the configuration F_at(q) (a callable q -> mat3), or the reference one
// (F_at = nullptr).
template <Geometry G, class PointF>
void elastic_stiffness(const discrete_model& m, const point_moduli& moduli, const PointF& F_at,
                       const std::vector<vec2>& x, std::vector<vec2>& out) {
  constexpr bool reference = std::is_same_v<PointF, std::nullptr_t>;
  assemble_point_forces<G>(m, x, out, [&](index_t /*tile*/, index_t q, const point_gradient& g, mat2& S, double& hoop) {
    const auto [lambda, mu] = moduli.at(q);
    const vec2& X = m.points.position[q];
    mat3 F = mat3::Identity();
    if constexpr (!reference) F = F_at(q);
    const mat2 Fi = reference ? mat2::Identity() : mat2(F.topLeftCorner<2, 2>().inverse());
    const double F33 = reference ? 1.0 : F(2, 2);
    const double J = reference ? 1.0 : F.determinant();
    const mat2 L = g.H * Fi;
    const mat2 de = 0.5 * (L + L.transpose());
    const double de33 = (G::out_of_plane_stretch(g.u, X) - 1.0) / F33;
    const double tr = de.trace() + de33;
    const mat2 ds = lambda * tr * mat2::Identity() + 2.0 * mu * de;
    S = J * ds * Fi.transpose() * m.points.weight[q];
    hoop = G::is_axisymmetric ? J * (lambda * tr + 2.0 * mu * de33) / F33 * m.points.weight[q] / X[0] : 0.0;
  });
}

}  // namespace detail

// out = K x about the configuration F (#points; empty: the reference configuration).
template <Geometry G>
void apply_elastic_stiffness(const discrete_model& m, const point_moduli& moduli, const std::vector<mat3>& F,
                             const std::vector<vec2>& x, std::vector<vec2>& out) {
  if (F.empty()) detail::elastic_stiffness<G>(m, moduli, nullptr, x, out);
  else detail::elastic_stiffness<G>(m, moduli, [&](index_t q) -> const mat3& { return F[q]; }, x, out);
}
template <Geometry G>
void apply_elastic_stiffness(const discrete_model& m, const material::elastic_constants& c,
                             const std::vector<mat3>& F, const std::vector<vec2>& x, std::vector<vec2>& out) {
  apply_elastic_stiffness<G>(m, point_moduli(c), F, x, out);
}

// out = K x about the configuration F_at(q), a callable (point_materials::deformation_gradients()).
template <Geometry G, std::invocable<index_t> PointF>
void apply_elastic_stiffness(const discrete_model& m, const point_moduli& moduli, const PointF& F_at,
                             const std::vector<vec2>& x, std::vector<vec2>& out) {
  detail::elastic_stiffness<G>(m, moduli, F_at, x, out);
}

// Reference configuration: out = K0 x.
template <Geometry G>
void apply_elastic_stiffness(const discrete_model& m, const material::elastic_constants& c,
                             const std::vector<vec2>& x, std::vector<vec2>& out) {
  static const std::vector<mat3> reference;
  apply_elastic_stiffness<G>(m, c, reference, x, out);
}

// A start vector with every frequency present (deterministic, so runs repeat exactly); its
// entry I alone, for callers that mix it back in without keeping a copy.
inline vec2 power_iteration_start(std::size_t I) {
  return vec2(std::sin(12.9898 * static_cast<double>(I) + 1.0), std::cos(78.233 * static_cast<double>(I) + 2.0));
}
inline void power_iteration_start(std::vector<vec2>& x) {
  for (std::size_t I = 0; I < x.size(); ++I) x[I] = power_iteration_start(I);
}
// The same over a model's particles, by their index in the whole model (the same vector on any
// number of processes).
inline void power_iteration_start(const discrete_model& m, std::vector<vec2>& x) {
  x.resize(m.particle_count());
  for (index_t I = 0; I < m.particle_count(); ++I) x[I] = power_iteration_start(m.global_particle(I));
}

// omega_max^2 of M^-1 K(F) by `iterations` power steps from (and into) x. No allocation. F: a
// std::vector<mat3> (empty: the reference configuration) or a callable q -> mat3. On several
// processes x's owned values are iterated: its ghosts are forwarded before each product, and
// the sums and the norm taken over every process's owned particles.
template <Geometry G, class PointF>
double largest_frequency_squared(const discrete_model& m, const point_moduli& c, const PointF& F,
                                 const std::vector<double>& mass, std::vector<vec2>& x, stiffness_workspace& w,
                                 int iterations) {
  const index_range owned = m.own.particles;
  double omega2 = 0.0;
  for (int it = 0; it < iterations; ++it) {
    exec::exchange(exchange_point::stiffness_product, m.own, x);
    apply_elastic_stiffness<G>(m, c, F, x, w.kx);
    const auto [xkx, xmx] = w.sums([&](index_t I, block_sums<2>::sums& s) {
      s[0] += x[I].dot(w.kx[I]);
      s[1] += mass[I] * x[I].squaredNorm();
    });
    omega2 = xkx / xmx;
    const double norm = exec::max_over_owned(
        m.own,
        [&](index_t I) {
          x[I] = w.kx[I] / mass[I];
          return x[I].cwiseAbs().maxCoeff();
        },
        0.0);
    if (!(norm > 0.0)) break;
    exec::parallel_for(owned, [&](index_t I) { x[I] /= norm; });
  }
  if (!(omega2 > 0.0) || !std::isfinite(omega2))
    fail("could not estimate the stable time step (omega^2 = {}): check the material constants "
         "and the particle masses", omega2);
  return omega2;
}

// dt_crit = 2 / omega_max of the reference configuration.
template <Geometry G>
double reference_stable_time_step(const discrete_model& m, const material::elastic_constants& c,
                                  const std::vector<double>& mass, int iterations = 100) {
  std::vector<vec2> x;
  power_iteration_start(m, x);
  stiffness_workspace w(m);
  static const std::vector<mat3> reference;
  return 2.0 / std::sqrt(largest_frequency_squared<G>(m, point_moduli(c), reference, mass, x, w, iterations));
}

}  // namespace rkpm
