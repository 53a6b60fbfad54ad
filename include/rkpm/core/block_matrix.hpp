#pragma once
// block_matrix: a 3x3 tensor of the two-dimensional bodies, whose F, b_e and tau all have the
// shape [[a11, a12, 0], [a21, a22, 0], [0, 0, a33]] (docs/method.md section 4.1), stored as its
// five entries: 40 bytes instead of a mat3's 72. The solver keeps such tensors at every
// quadrature point (F, tau and the J2 state's b_e and F_n), which made them a third of a run's
// memory. full() gives back the mat3 the computations use, with exact zeros off the block, so a
// value stored and read back is the same matrix bit for bit: every product and inverse of the
// materials sees the same numbers as before. The in-plane block is kept whole (a12 and a21
// separately): b_e's elastic predictor f b_e f^T is symmetric only up to rounding.

#include <rkpm/core/types.hpp>

namespace rkpm {

struct block_matrix {
  double xx = 1.0, xy = 0.0, yx = 0.0, yy = 1.0, zz = 1.0;  // the identity by default

  static block_matrix of(const mat3& a) { return {a(0, 0), a(0, 1), a(1, 0), a(1, 1), a(2, 2)}; }
  mat3 full() const {
    mat3 a;
    a << xx, xy, 0.0,  //
        yx, yy, 0.0,   //
        0.0, 0.0, zz;
    return a;
  }
  bool operator==(const block_matrix&) const = default;
};

}  // namespace rkpm
