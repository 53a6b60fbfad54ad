// Two conditions that degenerate in squeezed layers, and what the solver makes of them: velocity
// constraints whose rows are equal to round-off are projected as one condition (a constraint
// given twice is an error), and a particle whose lumped volume falls below zero keeps its own
// volume in a rebuilt model (in a first model it is an error).

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "support/error_message.hpp"
#include "support/solver_fixtures.hpp"

namespace test_unit_solver_constraints_and_rebuilt_models {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

// Velocity constraints (docs/method.md section 5.7): the same particle and direction twice is an
// error; rows equal to round-off are one condition, projected through (51a). Here seven rows of
// particles squeezed into one line (the limit of a layer squeezed against a tool and
// re-referenced, as the Taylor bar's at 400 m/s): their axis particles have equal rows, and the
// plain Cholesky factor of Lambda M^-1 Lambda^T fails or divides by round-off.
TEST_CASE("velocity constraints: a particle twice is an error, rows equal to round-off are one condition") {
  auto particles = make_grid_particles<2>(vec2(0, 0), vec2(1, 1), Eigen::Vector2i(6, 10), 2.0);
  const double h = 1.0 / 9.0;
  for (index_t I = 0; I < particles.size(); ++I)  // rows 0 to 6 onto one line under row 7
    if (const index_t row = I / 6; row < 7) particles.position[I][1] = 6.0 * h;
  const neighbor_search<2> search(particles);
  const auto table = build_shape_table<kernel::cubic_spline, correction::linear>(search, particles.position);
  std::vector<velocity_constraint> axis;
  for (index_t row = 0; row < 10; ++row) axis.push_back({6 * row, 0, {}});
  const std::vector<double> mass(particles.size(), 1.0);
  const auto residual = [&](const std::vector<vec2>& v) {
    double worst = 0.0;
    for (const auto& c : axis) {
      double lv = 0.0;
      for (index_t e = table.offset[c.particle]; e < table.offset[c.particle + 1]; ++e)
        lv += table.N[e] * v[table.neighbor[e]][0];
      worst = std::max(worst, std::abs(lv));
    }
    return worst;
  };
  std::vector<vec2> v(particles.size());
  for (index_t I = 0; I < particles.size(); ++I) v[I] = vec2(std::sin(3.0 * I + 1.0), std::cos(2.0 * I));
  const std::vector<vec2> given = v;
  REQUIRE(residual(v) > 0.1);
  constraint_projector projector(axis, table, mass);
  projector.apply(0.0, v);
  CHECK(residual(v) < 1e-6);
  // A projection in the mass norm: the kinetic energy never grows, however often it is applied.
  const auto energy = [&](const std::vector<vec2>& w) {
    double e = 0.0;
    for (index_t I = 0; I < particles.size(); ++I) e += 0.5 * mass[I] * w[I].squaredNorm();
    return e;
  };
  const double first = energy(v);
  CHECK(first < energy(given));
  projector.apply(0.0, v);
  CHECK(energy(v) <= first);
  CHECK(residual(v) < 1e-6);

  axis.push_back(axis[2]);
  CHECK(test::error_message([&] { constraint_projector twice(axis, table, mass); }).find("give each once") !=
        std::string::npos);
}

// A lumped volume below zero (docs/method.md section 5.8): in a first model it is an error (the
// masses come from it); a model rebuilt on carried points keeps its masses and gives such a
// particle its own volume. Here the points within the corner particle's support are removed, so
// that no point's row holds it (a layer squeezed thinner than its supports leaves a particle
// with only negative lobes at the points, the same branch).
TEST_CASE("a lumped volume below zero: an error in a first model, the particle's own volume in a rebuilt one") {
  const auto particles = make_grid_particles<2>(vec2(0, 0), vec2(1, 1), Eigen::Vector2i(9, 9), 2.0);
  const auto mesh = make_grid_mesh(vec2(0, 0), vec2(1, 1), Eigen::Vector2i(9, 9));
  const quadrature_points all = make_quadrature_points<quadrature::q4, geometry::plane_strain>(mesh);
  quadrature_points far;
  for (index_t q = 0; q < all.size(); ++q)
    if (all.position[q].cwiseAbs().maxCoeff() >= 2.0 / 8.0) {  // the support: 2 spacings
      far.position.push_back(all.position[q]);
      far.weight.push_back(all.weight[q]);
      far.cell.push_back(all.cell[q]);
    }
  using K = kernel::cubic_spline;
  using C = correction::linear;
  CHECK(test::error_message([&] { build_discrete_model_on<K, C>(particles, mesh, far); }).find("lumped mass") !=
        std::string::npos);
  const discrete_model rebuilt = build_discrete_model_on<K, C>(particles, mesh, far, default_max_moment_condition, true);
  CHECK(rebuilt.lumped_volume[0] == particles.volume[0]);
  for (index_t I = 1; I < rebuilt.particle_count(); ++I) CHECK(rebuilt.lumped_volume[I] > 0.0);
}

}  // namespace test_unit_solver_constraints_and_rebuilt_models
