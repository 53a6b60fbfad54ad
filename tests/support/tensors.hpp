#pragma once
// Small tensor helpers of the material tests: a diagonal deformation gradient, a loading path
// of deformation gradients and the von Mises stress q = sqrt(3/2) |dev tau|.

#include <cmath>
#include <vector>

#include <rkpm/core/types.hpp>

namespace rkpm::test {

inline mat3 diagonal(double f11, double f22, double f33) {
  mat3 F = mat3::Zero();
  F(0, 0) = f11;
  F(1, 1) = f22;
  F(2, 2) = f33;
  return F;
}

// A plane strain stretch with shear, out and back, then past the first peak, with a hoop
// stretch as in axisymmetric geometry: 121 deformation gradients that load, unload and reload.
inline std::vector<mat3> stretch_shear_path() {
  std::vector<mat3> out;
  for (int i = 0; i <= 120; ++i) {
    const double s = i <= 40 ? i / 40.0 : i <= 70 ? 1.0 - (i - 40) / 60.0 : 0.5 + (i - 70) / 25.0;
    mat3 F = mat3::Identity();
    F(0, 0) = 1.0 + 0.08 * s;
    F(1, 1) = 1.0 / (1.0 + 0.05 * s);
    F(0, 1) = 0.06 * s;
    F(2, 2) = 1.0 + 0.01 * s;
    out.push_back(F);
  }
  return out;
}

inline double von_mises(const mat3& tau) {
  const mat3 dev = tau - tau.trace() / 3.0 * mat3::Identity();
  return std::sqrt(1.5) * dev.norm();
}

}  // namespace rkpm::test
