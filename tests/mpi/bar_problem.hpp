#pragma once
// The bar of the distributed force tests (tests/mpi/local_force.cpp, distributed_force.cpp): an
// axisymmetric copper bar, 3.2 x 16 mm, 9 x 31 particles, cubic kernel, linear correction, Q2
// points, J2 with linear hardening, and a smooth deformation (a barrelling squash, not a
// polynomial) that yields most of it at full amplitude, and its coefficients at three amplitudes.

#include <cmath>
#include <limits>
#include <vector>

#include <rkpm/correction/polynomial_bases.hpp>
#include <rkpm/geometry/axisymmetric.hpp>
#include <rkpm/kernel/cubic_spline.hpp>
#include <rkpm/material/j2_plasticity.hpp>
#include <rkpm/quadrature/cell_rules.hpp>
#include <rkpm/solver/discrete_model.hpp>
#include <rkpm/solver/point_materials.hpp>

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

// The amplitudes of the evaluations the tests make, and the step each is told it belongs to.
inline constexpr double amplitudes[] = {0.4, 0.8, 1.2};
inline constexpr int evaluations = 3;
inline step_context step(int k) { return {k + 1, 1e-7 * (k + 1), 1e-7}; }

// The coefficients of evaluation k at the first `count` particles of m (all when count < 0),
// from m's own positions (a rank's model holds its particles' reference positions), NaN at the
// rest (ghosts that an exchange must fill).
inline std::vector<vec2> coefficients(const discrete_model& m, int k, index_t count = -1) {
  std::vector<vec2> x(m.particle_count(), vec2::Constant(std::numeric_limits<double>::quiet_NaN()));
  const index_t n = count < 0 ? m.particle_count() : count;
  for (index_t i = 0; i < n; ++i) x[i] = deformed(m.particles.position[i], amplitudes[k]);
  return x;
}

}  // namespace rkpm::test::bar
