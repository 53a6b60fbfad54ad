#pragma once
// block_matrix: a 3x3 tensor of the two-dimensional bodies, whose F, b_e and tau all have the
// shape [[a11, a12, 0], [a21, a22, 0], [0, 0, a33]] (docs/method.md section 1), stored as its
// five entries: 40 bytes instead of a mat3's 72. The solver keeps such tensors at every
// quadrature point (F, tau and the J2 state's b_e and F_n), which made them a third of a run's
// memory. full() gives back the mat3 the computations use, with exact zeros off the block, so a
// value stored and read back is the same matrix bit for bit: every product and inverse of the
// materials sees the same numbers as before. The in-plane block is kept whole (a12 and a21
// separately): b_e's elastic predictor f b_e f^T is symmetric only up to rounding.
// The products, inverse and determinant below are the mat3 ones with the terms that are zero
// by the block structure left out (a 3x3 product costs 45 flops, its block 13): each entry
// sums the same nonzero terms in the same order, so the values are those of the mat3
// arithmetic (x + 0 = x); only the sign of an exact zero could differ, which no sum, product
// or quotient of the material updates turns into a different nonzero value.

#include <concepts>

#include <rkpm/core/hot_inline.hpp>
#include <rkpm/core/types.hpp>

namespace rkpm {

// T: double, or a SIMD vector of doubles holding one entry of several points (core/simd.hpp):
// the formulas written once for a number type (material/hencky.hpp, material/j2_plasticity.hpp,
// solver/point_force_terms.hpp) take it for one point or for the lanes of the batched update.
template <class T>
struct basic_block_matrix {
  T xx = T(1.0), xy = T(0.0), yx = T(0.0), yy = T(1.0), zz = T(1.0);  // the identity by default

  static basic_block_matrix of(const mat3& a)
    requires std::same_as<T, double>
  {
    return {a(0, 0), a(0, 1), a(1, 0), a(1, 1), a(2, 2)};
  }
  mat3 full() const
    requires std::same_as<T, double>
  {
    mat3 a;
    a << xx, xy, 0.0,  //
        yx, yy, 0.0,   //
        0.0, 0.0, zz;
    return a;
  }
  bool operator==(const basic_block_matrix&) const
    requires std::same_as<T, double>
  = default;

  basic_block_matrix transpose() const { return {xx, yx, xy, yy, zz}; }
  // Eigen's 3x3 determinant, a00 (a11 a22 - a12 a21) - a01 (a10 a22 - a12 a20) + ..., without
  // its zero terms.
  T determinant() const { return xx * (yy * zz) - xy * (yx * zz); }
};

using block_matrix = basic_block_matrix<double>;

// (a b)_ij = sum_k a_ik b_kj, k in order, the zero terms left out.
template <class T>
RKPM_HOT_INLINE basic_block_matrix<T> operator*(const basic_block_matrix<T>& a, const basic_block_matrix<T>& b) {
  return {a.xx * b.xx + a.xy * b.yx, a.xx * b.xy + a.xy * b.yy,  //
          a.yx * b.xx + a.yy * b.yx, a.yx * b.xy + a.yy * b.yy, a.zz * b.zz};
}

// The inverse, as material/hencky.hpp's block_inverse writes it out for a mat3.
template <class T>
RKPM_HOT_INLINE basic_block_matrix<T> inverse(const basic_block_matrix<T>& a) {
  const T det2 = a.xx * a.yy - a.xy * a.yx;
  return {a.yy / det2, -a.xy / det2, -a.yx / det2, a.xx / det2, T(1.0) / a.zz};
}

}  // namespace rkpm
