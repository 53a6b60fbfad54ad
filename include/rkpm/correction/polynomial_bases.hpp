#pragma once
// Correction orders: the complete polynomial bases of degree 1 and 2 in 1D and 2D.
//   linear:    [1, z1, z2]
//   quadratic: [1, z1, z2, z1^2, z1 z2, z2^2]
// The offset z is scaled by the support, so every entry is of order one and the moment
// matrix stays well conditioned whatever the units (docs/method.md (7)-(8)).

#include <Eigen/Core>
#include <string_view>

#include <rkpm/core/types.hpp>

namespace rkpm::correction {

struct linear {
  static constexpr std::string_view name = "linear";
  static constexpr int order = 1;
  template <int Dim>
  static constexpr int size = 1 + Dim;

  template <int Dim>
  static void evaluate(const vec<Dim>& z, Eigen::Matrix<double, size<Dim>, 1>& h,
                       Eigen::Matrix<double, size<Dim>, Dim>& dh) {
    h[0] = 1.0;
    dh.row(0).setZero();
    for (int k = 0; k < Dim; ++k) {
      h[1 + k] = z[k];
      dh.row(1 + k).setZero();
      dh(1 + k, k) = 1.0;
    }
  }
};

struct quadratic {
  static constexpr std::string_view name = "quadratic";
  static constexpr int order = 2;
  template <int Dim>
  static constexpr int size = 1 + Dim + Dim * (Dim + 1) / 2;

  template <int Dim>
  static void evaluate(const vec<Dim>& z, Eigen::Matrix<double, size<Dim>, 1>& h,
                       Eigen::Matrix<double, size<Dim>, Dim>& dh) {
    dh.setZero();
    h[0] = 1.0;
    for (int k = 0; k < Dim; ++k) {
      h[1 + k] = z[k];
      dh(1 + k, k) = 1.0;
    }
    int row = 1 + Dim;
    for (int i = 0; i < Dim; ++i) {
      for (int j = i; j < Dim; ++j, ++row) {
        h[row] = z[i] * z[j];
        dh(row, i) += z[j];
        dh(row, j) += z[i];
      }
    }
  }
};

}  // namespace rkpm::correction
