#pragma once
// The end of the point rule (solver/point_materials.hpp), from F_q and tau_q:
//   S_q = tau_q F_q^-T w_q (in-plane),  h_q = tau33_q / F33_q w_q / R_q (axisymmetric),
// and the support stretch the time-step controller reads. Written once for a number type T
// (core/simd.hpp): double for one point, a vector V of doubles for the lanes of the batched path,
// so each lane gets its point's bits by construction (tests/unit/solver/point_force_terms.cpp, at
// 2, 4 and 8 lanes and the native width). The formulas are Eigen's 2x2 arithmetic written out in
// its order (the inverse through 1 / det, products summed over k in order, the squared norm's
// packet sums), which the one-point form computed before with Eigen.

#include <cmath>

#include <rkpm/concepts/geometry.hpp>
#include <rkpm/core/block_matrix.hpp>
#include <rkpm/core/hot_inline.hpp>
#include <rkpm/core/simd.hpp>
#include <rkpm/core/types.hpp>

namespace rkpm {

// F^-1's in-plane block, as Eigen's 2x2 inverse computes it: 1 / det, then the adjugate's entries
// times it (the 33 entry is not used).
template <class T>
RKPM_HOT_INLINE basic_block_matrix<T> in_plane_inverse(const basic_block_matrix<T>& F) {
  const T inverse_det = 1.0 / (F.xx * F.yy - F.yx * F.xy);
  return {F.yy * inverse_det, -F.xy * inverse_det, -F.yx * inverse_det, F.xx * inverse_det, T(1.0)};
}

// S_q (in-plane block) and h_q of the point(s) (weight w_q, radius R_q); returns F^-1's in-plane
// block.
template <Geometry G, class T>
RKPM_HOT_INLINE basic_block_matrix<T> point_force_terms(const basic_block_matrix<T>& F, const basic_block_matrix<T>& tau,
                                                        const T& weight, const T& radius, basic_block_matrix<T>& S,
                                                        T& hoop) {
  const basic_block_matrix<T> Fi = in_plane_inverse(F);
  // (tau F^-T)_ij = tau_i0 Fi_j0 + tau_i1 Fi_j1, then times w.
  S = {(tau.xx * Fi.xx + tau.xy * Fi.xy) * weight, (tau.xx * Fi.yx + tau.xy * Fi.yy) * weight,
       (tau.yx * Fi.xx + tau.yy * Fi.xy) * weight, (tau.yx * Fi.yx + tau.yy * Fi.yy) * weight, T(0.0)};
  if constexpr (G::is_axisymmetric) hoop = tau.zz / F.zz * weight / radius;
  else hoop = T(0.0);
  return Fi;
}

// point_force_terms of one point with the force loop's mat3 and mat2.
template <Geometry G>
RKPM_HOT_INLINE mat2 point_forces_of(const mat3& F, const mat3& tau, double weight, double radius, mat2& S, double& hoop) {
  block_matrix S_block;
  const block_matrix Fi = point_force_terms<G>(block_matrix::of(F), block_matrix::of(tau), weight, radius, S_block, hoop);
  S << S_block.xx, S_block.xy, S_block.yx, S_block.yy;
  mat2 in_plane;
  in_plane << Fi.xx, Fi.xy, Fi.yx, Fi.yy;
  return in_plane;
}

// point_force_terms of the lanes: S[k] and hoop[k] of lane k; returns F^-1's in-plane blocks.
template <Geometry G, class V>
basic_block_lanes<V> point_forces_in_lanes(const basic_block_lanes<V>& F, const basic_block_lanes<V>& tau,
                                           const V& weight, const V& radius, mat2* S, double* hoop) {
  basic_block_lanes<V> S_lanes;
  V h;
  const basic_block_lanes<V> Fi = point_force_terms<G>(F, tau, weight, radius, S_lanes, h);
  for (int k = 0; k < lanes_of<V>; ++k) {
    S[k] << S_lanes.xx[k], S_lanes.xy[k], S_lanes.yx[k], S_lanes.yy[k];
    hoop[k] = h[k];
  }
  return Fi;
}

// How much the support has narrowed, as the highest frequency sees it: current gradients are
// grad_x N = F^-T grad_X N with |grad_X N| ~ 1/a_k per direction, so the largest current gradient
// scale is the largest singular value of B = F^-T diag(1/a). Relative to the reference (1/min a_k)
// this is 1 at F = I and follows the thinnest direction of the deformed support, not merely the
// smallest stretch (the Taylor bar's supports are 4:1). Fi: F^-1's in-plane block;
// support_inverse: 1/a per direction.
template <class T>
RKPM_HOT_INLINE T support_stretch(const basic_block_matrix<T>& Fi, const vec2& support_inverse) {
  // B(i, j) = Fi(j, i) / a_j.
  const T b00 = Fi.xx * support_inverse[0], b01 = Fi.yx * support_inverse[1];
  const T b10 = Fi.xy * support_inverse[0], b11 = Fi.yy * support_inverse[1];
  // Eigen's squared norm of a 2x2 sums the columns as packets, then the two lanes.
  const T s = (b00 * b00 + b01 * b01) + (b10 * b10 + b11 * b11);
  const T det = b00 * b11 - b10 * b01;
  const T discriminant = s * s - 4.0 * det * det;
  T root(0.0);
  assign_where(0.0 < discriminant, root, discriminant);  // std::max(0.0, discriminant)
  const T largest = sqrt_of(0.5 * (s + sqrt_of(root)));
  return support_inverse.maxCoeff() / largest;
}
RKPM_HOT_INLINE double support_stretch(const mat2& F_inverse, const vec2& support_inverse) {
  return support_stretch(block_matrix{F_inverse(0, 0), F_inverse(0, 1), F_inverse(1, 0), F_inverse(1, 1), 1.0},
                         support_inverse);
}

}  // namespace rkpm
