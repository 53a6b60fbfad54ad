#pragma once
// The end of the point rule for simd_lanes points at once (solver/point_materials.hpp, its
// batched path): from F_q and tau_q in lanes,
//   S_q = tau_q F_q^-T w_q (in-plane),  h_q = tau33_q / F33_q w_q / R_q (axisymmetric),
// and the support stretch of the time-step controller. Each formula is the one point_materials
// evaluates point by point with Eigen's 2x2 arithmetic, written out in Eigen's order (the
// inverse through 1 / det, products summed over k in order, the squared norm's packet sums), so
// each lane gets the bits of the point-by-point rule (tests/unit/solver/point_force_lanes.cpp).

#include <rkpm/concepts/geometry.hpp>
#include <rkpm/core/block_matrix.hpp>
#include <rkpm/core/simd.hpp>
#include <rkpm/core/types.hpp>

namespace rkpm {

// F^-1's in-plane block, as Eigen's 2x2 inverse computes it: 1 / det, then the adjugate's
// entries times it.
inline basic_block_matrix<simd_double> in_plane_inverse(const basic_block_matrix<simd_double>& F) {
  const simd_double inverse_det = 1.0 / (F.xx * F.yy - F.yx * F.xy);
  return {F.yy * inverse_det, -F.xy * inverse_det, -F.yx * inverse_det, F.xx * inverse_det, simd_double(1.0)};
}

// The support stretch of point_materials::support_stretch: B = F^-T diag(support_inverse), the
// largest singular value of B, and the reference's largest gradient scale over it.
inline simd_double support_stretch_lanes(const basic_block_matrix<simd_double>& Fi, const vec2& support_inverse) {
  // B(i, j) = Fi(j, i) / a_j.
  const simd_double b00 = Fi.xx * support_inverse[0], b01 = Fi.yx * support_inverse[1];
  const simd_double b10 = Fi.xy * support_inverse[0], b11 = Fi.yy * support_inverse[1];
  // Eigen's squared norm of a 2x2 sums the columns as packets, then the two lanes.
  const simd_double s = (b00 * b00 + b01 * b01) + (b10 * b10 + b11 * b11);
  const simd_double det = b00 * b11 - b10 * b01;
  const simd_double discriminant = s * s - 4.0 * det * det;
  simd_double root(0.0);
  stdx::where(0.0 < discriminant, root) = discriminant;  // std::max(0.0, discriminant)
  const simd_double largest = stdx::sqrt(0.5 * (s + stdx::sqrt(root)));
  return support_inverse.maxCoeff() / largest;
}

// S_q and h_q of the lanes (weight w_q, radius R_q); returns F^-1's in-plane block.
template <Geometry G>
basic_block_matrix<simd_double> point_forces_in_lanes(const basic_block_matrix<simd_double>& F,
                                                      const basic_block_matrix<simd_double>& tau,
                                                      const simd_double& weight, const simd_double& radius,
                                                      mat2* S, double* hoop) {
  const basic_block_matrix<simd_double> Fi = in_plane_inverse(F);
  // (tau F^-T)_ij = tau_i0 Fi_j0 + tau_i1 Fi_j1, then times w.
  const simd_double s00 = (tau.xx * Fi.xx + tau.xy * Fi.xy) * weight;
  const simd_double s01 = (tau.xx * Fi.yx + tau.xy * Fi.yy) * weight;
  const simd_double s10 = (tau.yx * Fi.xx + tau.yy * Fi.xy) * weight;
  const simd_double s11 = (tau.yx * Fi.yx + tau.yy * Fi.yy) * weight;
  simd_double h(0.0);
  if constexpr (G::is_axisymmetric) h = tau.zz / F.zz * weight / radius;
  for (int k = 0; k < simd_lanes; ++k) {
    S[k] << s00[k], s01[k], s10[k], s11[k];
    hoop[k] = h[k];
  }
  return Fi;
}

}  // namespace rkpm
