#pragma once
// The bar of the distributed force tests (tests/mpi/local_force.cpp, distributed_force.cpp): an
// axisymmetric copper bar, 3.2 x 16 mm, 9 x 31 particles, cubic kernel, linear correction, Q2
// points, J2 with linear hardening, and a smooth deformation (a barrelling squash, not a
// polynomial) that yields most of it at full amplitude.

#include <cmath>
#include <vector>

#include <rkpm/correction/polynomial_bases.hpp>
#include <rkpm/geometry/axisymmetric.hpp>
#include <rkpm/kernel/cubic_spline.hpp>
#include <rkpm/material/j2_plasticity.hpp>
#include <rkpm/quadrature/cell_rules.hpp>
#include <rkpm/solver/discrete_model.hpp>

namespace rkpm::test::bar {

using geometry_type = geometry::axisymmetric;
using material_type = material::j2_plasticity<material::hardening::linear>;
constexpr double radius = 3.2e-3, height = 16e-3;

inline discrete_model model(int radial = 9, int axial = 31) {
  const vec2 lo(0.0, 0.0), hi(radius, height);
  const Eigen::Vector2i n(radial, axial);
  return build_discrete_model<kernel::cubic_spline, correction::linear, quadrature::q2, geometry_type>(
      make_grid_particles<2>(lo, hi, n, 2.0), make_grid_mesh(lo, hi, n));
}

inline material_type copper() {
  return material_type(material::elastic_constants{117e9, 0.35, 8930.0}, material::hardening::linear{400e6, 100e6});
}

// x_I = X_I + s u(X_I), 1.5 % strain at s = 1.
inline vec2 deformed(const vec2& X, double s) {
  const double z = X[1] / height, r = X[0] / radius;
  return X + s * 0.015 * vec2(0.5 * X[0] * (1.0 + 0.6 * std::sin(3.0 * z)) * (1.0 + 0.2 * r * r),
                               -X[1] * (1.0 + 0.3 * std::cos(2.0 * z + r)));
}

// The amplitudes of the three evaluations the tests make.
inline constexpr double amplitudes[] = {0.4, 0.8, 1.2};

}  // namespace rkpm::test::bar
