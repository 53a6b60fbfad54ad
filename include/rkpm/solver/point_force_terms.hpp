#pragma once
// The end of the point rule (solver/point_materials.hpp), from F_q and tau_q:
//   S_q = tau_q F_q^-T w_q (in-plane),  h_q = tau33_q / F33_q w_q / R_q (axisymmetric),
// and the support stretch the time-step controller reads, each for one point (Eigen's 2x2
// arithmetic) and for the lanes of a vector V at once (the batched path, core/simd.hpp). The lane forms
// write Eigen's evaluation out in its order (the inverse through 1 / det, products summed over k
// in order, the squared norm's packet sums), so each lane gets the bits of the one-point form
// (tests/unit/solver/point_force_terms.cpp, at 2, 4 and 8 lanes and the native width).

#include <algorithm>
#include <cmath>

#include <Eigen/LU>

#include <rkpm/concepts/geometry.hpp>
#include <rkpm/core/block_matrix.hpp>
#include <rkpm/core/hot_inline.hpp>
#include <rkpm/core/simd.hpp>
#include <rkpm/core/types.hpp>

namespace rkpm {

// S_q and h_q of one point (weight w_q, radius R_q); returns F^-1's in-plane block.
template <Geometry G>
RKPM_HOT_INLINE mat2 point_forces_of(const mat3& F, const mat3& tau, double weight, double radius, mat2& S, double& hoop) {
  const mat2 Fi = F.topLeftCorner<2, 2>().inverse();
  S = tau.topLeftCorner<2, 2>() * Fi.transpose() * weight;
  hoop = G::is_axisymmetric ? tau(2, 2) / F(2, 2) * weight / radius : 0.0;
  return Fi;
}

// How much the support has narrowed, as the highest frequency sees it: current gradients are
// grad_x N = F^-T grad_X N with |grad_X N| ~ 1/a_k per direction, so the largest current gradient
// scale is the largest singular value of B = F^-T diag(1/a). Relative to the reference (1/min a_k)
// this is 1 at F = I and follows the thinnest direction of the deformed support, not merely the
// smallest stretch (the Taylor bar's supports are 4:1). support_inverse: 1/a per direction.
RKPM_HOT_INLINE double support_stretch(const mat2& F_inverse, const vec2& support_inverse) {
  const mat2 B = F_inverse.transpose() * support_inverse.asDiagonal();
  const double s = B.squaredNorm(), det = B.determinant();
  const double largest = std::sqrt(0.5 * (s + std::sqrt(std::max(0.0, s * s - 4.0 * det * det))));
  return support_inverse.maxCoeff() / largest;
}

// F^-1's in-plane block of the lanes, as Eigen's 2x2 inverse computes it: 1 / det, then the
// adjugate's entries times it (the 33 entry is not used).
template <class V>
basic_block_lanes<V> in_plane_inverse(const basic_block_lanes<V>& F) {
  const V inverse_det = 1.0 / (F.xx * F.yy - F.yx * F.xy);
  return {F.yy * inverse_det, -F.xy * inverse_det, -F.yx * inverse_det, F.xx * inverse_det, V(1.0)};
}

// support_stretch of the lanes.
template <class V>
V support_stretch(const basic_block_lanes<V>& Fi, const vec2& support_inverse) {
  // B(i, j) = Fi(j, i) / a_j.
  const V b00 = Fi.xx * support_inverse[0], b01 = Fi.yx * support_inverse[1];
  const V b10 = Fi.xy * support_inverse[0], b11 = Fi.yy * support_inverse[1];
  // Eigen's squared norm of a 2x2 sums the columns as packets, then the two lanes.
  const V s = (b00 * b00 + b01 * b01) + (b10 * b10 + b11 * b11);
  const V det = b00 * b11 - b10 * b01;
  const V discriminant = s * s - 4.0 * det * det;
  V root(0.0);
  stdx::where(0.0 < discriminant, root) = discriminant;  // std::max(0.0, discriminant)
  const V largest = stdx::sqrt(0.5 * (s + stdx::sqrt(root)));
  return support_inverse.maxCoeff() / largest;
}

// point_forces_of for the lanes: S[k] and hoop[k] of lane k; returns F^-1's in-plane blocks.
template <Geometry G, class V>
basic_block_lanes<V> point_forces_in_lanes(const basic_block_lanes<V>& F, const basic_block_lanes<V>& tau,
                                           const V& weight, const V& radius, mat2* S, double* hoop) {
  const basic_block_lanes<V> Fi = in_plane_inverse(F);
  // (tau F^-T)_ij = tau_i0 Fi_j0 + tau_i1 Fi_j1, then times w.
  const V s00 = (tau.xx * Fi.xx + tau.xy * Fi.xy) * weight;
  const V s01 = (tau.xx * Fi.yx + tau.xy * Fi.yy) * weight;
  const V s10 = (tau.yx * Fi.xx + tau.yy * Fi.xy) * weight;
  const V s11 = (tau.yx * Fi.yx + tau.yy * Fi.yy) * weight;
  V h(0.0);
  if constexpr (G::is_axisymmetric) h = tau.zz / F.zz * weight / radius;
  for (int k = 0; k < lanes_of<V>; ++k) {
    S[k] << s00[k], s01[k], s10[k], s11[k];
    hoop[k] = h[k];
  }
  return Fi;
}

}  // namespace rkpm
