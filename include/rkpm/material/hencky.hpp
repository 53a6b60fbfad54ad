#pragma once
// Hencky (logarithmic) elasticity on tensors with the 2D block structure
// [[a11, a12, 0], [a12, a22, 0], [0, 0, a33]] (docs/method.md (22), section 4.2):
//   b = sum_i lambda_i^2 n_i n_i^T,  eps_i = ln(lambda_i),  tau_i = lambda tr(eps) + 2 mu eps_i,
//   tau = sum_i tau_i n_i n_i^T.
// The out-of-plane direction e3 is always principal, so only the in-plane 2x2 block needs an
// eigen-decomposition, done here in closed form. Shared by the materials with Hencky
// elasticity (elastic, J2, Johnson-Cook, Zerilli-Armstrong, Rankine fracture).
// Written once for a number type T (core/simd.hpp): double for one point, a vector V of doubles
// for J2's batched update (material/j2_batch.hpp), so each lane gets its point's bits by
// construction. principal_frame, hencky_strains and hencky_stress are the one-point forms.

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <concepts>
#include <string_view>

#include <rkpm/core/block_matrix.hpp>
#include <rkpm/core/error.hpp>
#include <rkpm/core/hot_inline.hpp>
#include <rkpm/core/simd.hpp>
#include <rkpm/core/types.hpp>

namespace rkpm::material {

using vec3 = Eigen::Vector3d;

// Three principal values: a vec3 for one point, one vector per value for the lanes.
template <class T>
struct principal_values_of {
  using type = std::array<T, 3>;
};
template <>
struct principal_values_of<double> {
  using type = vec3;
};
template <class T>
using principal_values = typename principal_values_of<T>::type;

// Eigen-decomposition of a symmetric positive definite block-structured tensor. values[0] >=
// values[1] are the in-plane eigenvalues, values[2] = a33. The in-plane frame is stored as
// (cos 2 theta, sin 2 theta) of the first direction n1 = (cos theta, sin theta): that is all
// assemble() needs, and it avoids atan2/cos/sin in the stress update.
template <class T>
struct basic_principal_frame {
  principal_values<T> values;
  T cos2 = T(1.0);
  T sin2 = T(0.0);

  RKPM_HOT_INLINE static basic_principal_frame of(const basic_block_matrix<T>& a) {
    const T a12 = 0.5 * (a.xy + a.yx);
    const T mean = 0.5 * (a.xx + a.yy);
    const T half_diff = 0.5 * (a.xx - a.yy);
    // sqrt(x^2 + y^2), not std::hypot: glibc's hypot guards against overflow and underflow that
    // the entries of b_e (order 1) never reach, at a cost the stress update would feel.
    const T radius = sqrt_of(half_diff * half_diff + a12 * a12);
    basic_principal_frame frame;
    const T larger = mean + radius;
    // det / larger instead of mean - radius: no cancellation for strongly stretched b.
    const T smaller = (a.xx * a.yy - a12 * a12) / larger;
    frame.values = principal_values<T>{larger, smaller, a.zz};
    const mask_of<T> turned = radius > 0.0;
    assign_where(turned, frame.cos2, T(half_diff / radius));
    assign_where(turned, frame.sin2, T(a12 / radius));
    return frame;
  }
  static basic_principal_frame of(const mat3& a)
    requires std::same_as<T, double>
  {
    return of(block_matrix::of(a));
  }

  // sum_i v_i n_i n_i^T; with v[0] == v[1] the result is independent of the frame, so the
  // arbitrary frame of a repeated eigenvalue does no harm.
  RKPM_HOT_INLINE basic_block_matrix<T> assemble_block(const principal_values<T>& v) const {
    const T mean = 0.5 * (v[0] + v[1]);
    const T half_diff = 0.5 * (v[0] - v[1]);
    const T off_diagonal = half_diff * sin2;
    return {mean + half_diff * cos2, off_diagonal, off_diagonal, mean - half_diff * cos2, v[2]};
  }
  RKPM_HOT_INLINE mat3 assemble(const vec3& v) const
    requires std::same_as<T, double>
  {
    return assemble_block(v).full();
  }
};

using principal_frame = basic_principal_frame<double>;

// The first in-plane principal direction n1 = (cos theta, sin theta), theta in (-90, 90], from
// the frame's (cos 2 theta, sin 2 theta): the crack normal of the laws that break
// (rankine_fracture, johnson_cook's damage with opens_cracks).
inline vec2 principal_direction(const principal_frame& frame) {
  const double c = std::sqrt(std::max(0.0, 0.5 * (1.0 + frame.cos2)));
  const double s = std::sqrt(std::max(0.0, 0.5 * (1.0 - frame.cos2)));
  const vec2 n(c, frame.sin2 < 0.0 ? -s : s);
  return n / n.norm();
}

// Principal logarithmic strains eps_i = ln(lambda_i) = ln(lambda_i^2) / 2, by the C library's
// log lane by lane.
template <class T>
RKPM_HOT_INLINE principal_values<T> principal_log_strains_of(const principal_values<T>& squared_stretches) {
  const auto log_strain = [](double x) { return 0.5 * std::log(x); };
  return {lanewise(squared_stretches[0], log_strain), lanewise(squared_stretches[1], log_strain),
          lanewise(squared_stretches[2], log_strain)};
}
inline vec3 principal_log_strains(const vec3& squared_stretches) {
  return principal_log_strains_of<double>(squared_stretches);
}

// tau = K tr(eps_e) 1 + 2 mu dev(eps_e) in the principal frame of b_e (the Hencky law of every
// elastic-plastic material here: J2, Johnson-Cook, Zerilli-Armstrong).
template <class T>
RKPM_HOT_INLINE basic_block_matrix<T> hencky_stress_block(const basic_principal_frame<T>& frame, const T& volumetric,
                                                         const principal_values<T>& dev, double bulk, double mu) {
  const T mean_stress = bulk * volumetric;
  const double two_mu = 2.0 * mu;
  return frame.assemble_block(
      principal_values<T>{mean_stress + two_mu * dev[0], mean_stress + two_mu * dev[1], mean_stress + two_mu * dev[2]});
}
RKPM_HOT_INLINE mat3 hencky_stress(const principal_frame& frame, double volumetric, const vec3& dev, double bulk,
                                   double mu) {
  return hencky_stress_block(frame, volumetric, dev, bulk, mu).full();
}

// The logarithmic elastic strains of b_e: its principal frame, the volumetric strain and the
// principal deviatoric strains (what a material's current_kirchhoff_stress recomputes tau from).
template <class T>
struct basic_hencky_strains {
  basic_principal_frame<T> frame;
  T volumetric;
  principal_values<T> dev;

  RKPM_HOT_INLINE static basic_hencky_strains of(const basic_block_matrix<T>& b_e) {
    const basic_principal_frame<T> frame = basic_principal_frame<T>::of(b_e);
    const principal_values<T> eps = principal_log_strains_of<T>(frame.values);
    const T volumetric = eps[0] + eps[1] + eps[2];
    const T third = volumetric / 3.0;
    return {frame, volumetric, principal_values<T>{eps[0] - third, eps[1] - third, eps[2] - third}};
  }
  static basic_hencky_strains of(const mat3& b_e)
    requires std::same_as<T, double>
  {
    return of(block_matrix::of(b_e));
  }

  // The von Mises stress of the deviator, q = sqrt(3/2) 2 mu |dev|.
  RKPM_HOT_INLINE T von_mises(double mu) const {
    return std::sqrt(1.5) * 2.0 * mu * sqrt_of(dev[0] * dev[0] + dev[1] * dev[1] + dev[2] * dev[2]);
  }
};

using hencky_strains = basic_hencky_strains<double>;
// The inverse of a block-structured F, written out so the zero blocks stay exactly zero.
inline mat3 block_inverse(const mat3& F) {
  const double det2 = F(0, 0) * F(1, 1) - F(0, 1) * F(1, 0);
  mat3 inv;
  inv << F(1, 1) / det2, -F(0, 1) / det2, 0.0,  //
      -F(1, 0) / det2, F(0, 0) / det2, 0.0,     //
      0.0, 0.0, 1.0 / F(2, 2);
  return inv;
}

namespace detail {

// The refusals of check_deformation_gradient, out of the force loop's code (called only on failure).
[[noreturn, gnu::cold, gnu::noinline]] inline void bad_deformation_gradient(const mat3& F, std::string_view who) {
  if (!F.allFinite())
    fail("{}: the deformation gradient is not finite (F11 = {}, F12 = {}, F21 = {}, F22 = {}, "
         "F33 = {}): the step diverged upstream; reduce the time step",
         who, F(0, 0), F(0, 1), F(1, 0), F(1, 1), F(2, 2));
  if (F(0, 2) != 0.0 || F(1, 2) != 0.0 || F(2, 0) != 0.0 || F(2, 1) != 0.0)
    fail("{}: the deformation gradient has out-of-plane shear (F13 = {}, F23 = {}, F31 = {}, "
         "F32 = {}): 2D materials need F = [[F11, F12, 0], [F21, F22, 0], [0, 0, F33]]",
         who, F(0, 2), F(1, 2), F(2, 0), F(2, 1));
  const double J = (F(0, 0) * F(1, 1) - F(0, 1) * F(1, 0)) * F(2, 2);
  fail("{}: det F = {} <= 0 (F11 = {}, F12 = {}, F21 = {}, F22 = {}, F33 = {}): the material "
       "point is inverted or collapsed; reduce the time step or refine the particles",
       who, J, F(0, 0), F(0, 1), F(1, 0), F(1, 1), F(2, 2));
}

}  // namespace detail

// The solver guarantees a finite, block-structured F with det F > 0; checking costs a few
// comparisons and turns a silent NaN stress into an error that says where it came from.
RKPM_HOT_INLINE void check_deformation_gradient(const mat3& F, std::string_view who) {
  const double J = (F(0, 0) * F(1, 1) - F(0, 1) * F(1, 0)) * F(2, 2);
  if (!F.allFinite() || F(0, 2) != 0.0 || F(1, 2) != 0.0 || F(2, 0) != 0.0 || F(2, 1) != 0.0 || !(J > 0.0))
    detail::bad_deformation_gradient(F, who);
}

}  // namespace rkpm::material
