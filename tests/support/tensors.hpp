#pragma once
// Small tensor helpers of the material tests: a diagonal deformation gradient and the von Mises
// stress q = sqrt(3/2) |dev tau|.

#include <cmath>

#include <rkpm/core/types.hpp>

namespace rkpm::test {

inline mat3 diagonal(double f11, double f22, double f33) {
  mat3 F = mat3::Zero();
  F(0, 0) = f11;
  F(1, 1) = f22;
  F(2, 2) = f33;
  return F;
}

inline double von_mises(const mat3& tau) {
  const mat3 dev = tau - tau.trace() / 3.0 * mat3::Identity();
  return std::sqrt(1.5) * dev.norm();
}

}  // namespace rkpm::test
