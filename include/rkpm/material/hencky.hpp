#pragma once
// Hencky (logarithmic) elasticity on tensors with the 2D block structure
// [[a11, a12, 0], [a12, a22, 0], [0, 0, a33]] (docs/method.md (22), section 4.2):
//   b = sum_i lambda_i^2 n_i n_i^T,  eps_i = ln(lambda_i),  tau_i = lambda tr(eps) + 2 mu eps_i,
//   tau = sum_i tau_i n_i n_i^T.
// The out-of-plane direction e3 is always principal, so only the in-plane 2x2 block needs an
// eigen-decomposition, done here in closed form. Shared by material::elastic and
// material::j2_plasticity, and by nothing else.

#include <Eigen/Core>
#include <cmath>
#include <string_view>

#include <rkpm/core/error.hpp>
#include <rkpm/core/hot_inline.hpp>
#include <rkpm/core/types.hpp>

namespace rkpm::material {

using vec3 = Eigen::Vector3d;

// Eigen-decomposition of a symmetric positive definite block-structured tensor. values(0) >=
// values(1) are the in-plane eigenvalues, values(2) = a33. The in-plane frame is stored as
// (cos 2 theta, sin 2 theta) of the first direction n1 = (cos theta, sin theta): that is all
// assemble() needs, and it avoids atan2/cos/sin in the stress update.
struct principal_frame {
  vec3 values;
  double cos2 = 1.0;
  double sin2 = 0.0;

  static principal_frame of(const mat3& a) {
    const double a12 = 0.5 * (a(0, 1) + a(1, 0));
    const double mean = 0.5 * (a(0, 0) + a(1, 1));
    const double half_diff = 0.5 * (a(0, 0) - a(1, 1));
    // sqrt(x^2 + y^2), not std::hypot: glibc's hypot guards against overflow and underflow that
    // the entries of b_e (order 1) never reach, and took 12% of a Taylor bar step's time.
    const double radius = std::sqrt(half_diff * half_diff + a12 * a12);
    principal_frame frame;
    const double larger = mean + radius;
    // det / larger instead of mean - radius: no cancellation for strongly stretched b.
    const double smaller = (a(0, 0) * a(1, 1) - a12 * a12) / larger;
    frame.values = vec3(larger, smaller, a(2, 2));
    if (radius > 0.0) {
      frame.cos2 = half_diff / radius;
      frame.sin2 = a12 / radius;
    }
    return frame;
  }

  // sum_i v_i n_i n_i^T; with v(0) == v(1) the result is independent of the frame, so the
  // arbitrary frame of a repeated eigenvalue does no harm.
  RKPM_HOT_INLINE mat3 assemble(const vec3& v) const {
    const double mean = 0.5 * (v(0) + v(1));
    const double half_diff = 0.5 * (v(0) - v(1));
    mat3 m;
    m << mean + half_diff * cos2, half_diff * sin2, 0.0,  //
        half_diff * sin2, mean - half_diff * cos2, 0.0,   //
        0.0, 0.0, v(2);
    return m;
  }
};

// Principal logarithmic strains eps_i = ln(lambda_i) = ln(lambda_i^2) / 2.
inline vec3 principal_log_strains(const vec3& squared_stretches) {
  return vec3(0.5 * std::log(squared_stretches(0)), 0.5 * std::log(squared_stretches(1)),
              0.5 * std::log(squared_stretches(2)));
}

// tau = K tr(eps_e) 1 + 2 mu dev(eps_e) in the principal frame of b_e (the Hencky law of every
// elastic-plastic material here: J2, Johnson-Cook, Zerilli-Armstrong).
RKPM_HOT_INLINE mat3 hencky_stress(const principal_frame& frame, double volumetric, const vec3& dev, double bulk,
                                   double mu) {
  return frame.assemble(vec3::Constant(bulk * volumetric) + 2.0 * mu * dev);
}

// The logarithmic elastic strains of b_e: its principal frame, the volumetric strain and the
// principal deviatoric strains (what a material's current_kirchhoff_stress recomputes tau from).
struct hencky_strains {
  principal_frame frame;
  double volumetric;
  vec3 dev;
  static hencky_strains of(const mat3& b_e) {
    const principal_frame frame = principal_frame::of(b_e);
    const vec3 eps = principal_log_strains(frame.values);
    const double volumetric = eps.sum();
    return {frame, volumetric, eps - vec3::Constant(volumetric / 3.0)};
  }
};

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
