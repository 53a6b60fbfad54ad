// One rank's force loop (parallel/local_model.hpp) against the whole model's, built on one
// process for every rank of METIS partitions into 2 and 3 parts and of cuts forced along and
// across the axis: an axisymmetric bar (cubic kernel, linear correction, Q2 points) of J2
// material with linear hardening, deformed three times by a smooth field that yields most of
// it. Each rank evaluates point_materials<axisymmetric, J2>::internal_force over its local
// model from its owned and ghost coefficients: every owned particle's force equals the whole
// model's bit for bit (memcmp: the local traversal adds the same terms in the same order),
// every local point's material state equals that point's (a redundant ghost point is computed
// alike on both ranks), and the smallest support stretch over the ranks equals the model's.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <rkpm/parallel/halo.hpp>
#include <rkpm/parallel/local_model.hpp>
#include <rkpm/parallel/partition.hpp>
#include <rkpm/solver/body_materials.hpp>
#include <rkpm/solver/point_materials.hpp>

#include "mpi/bar_problem.hpp"

namespace test_mpi_local_force {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;
using namespace rkpm::parallel;

namespace {

using G = test::bar::geometry_type;
using M = test::bar::material_type;
using test::bar::height;
using test::bar::radius;

struct evaluation {
  std::vector<vec2> force;
  std::vector<M::state_type> states;
  double min_stretch;
};

// The force evaluations of mpi/bar_problem.hpp over model m (the whole model or a rank's: the
// coefficients come from its particles' positions).
std::vector<evaluation> evaluate(const discrete_model& m) {
  const materials_by_body<M> material(m, test::bar::copper(), {});
  point_materials<G, M> points(m, material);
  std::vector<evaluation> out;
  for (int k = 0; k < test::bar::evaluations; ++k) {
    std::vector<vec2> f(m.particle_count());
    points.internal_force(m, material, test::bar::coefficients(m, k), f, test::bar::step(k));
    out.push_back({f, points.states(), points.min_stretch()});
  }
  return out;
}

void check_partition(const discrete_model& m, const std::vector<evaluation>& whole, const particle_partition& p,
                     const std::string& name) {
  CAPTURE(name);
  std::vector<double> narrowest(3, 1e300);
  std::vector<int> owners(m.particle_count(), 0);
  index_t redundant = 0;
  for (int r = 0; r < p.parts; ++r) {
    CAPTURE(r);
    const halo_plan plan = make_halo_plan(p, m.at_points, r);
    const discrete_model local = local_force_model(m, plan);
    REQUIRE(local.traversal.tile_start.back() == local.point_count());
    const auto result = evaluate(local);
    redundant += local.point_count();
    for (int k = 0; k < 3; ++k) {
      CAPTURE(k);
      bool forces_equal = true, states_equal = true;
      for (std::size_t i = 0; i < plan.owned.size(); ++i) {
        const index_t I = plan.owned[i];
        ++owners[I];
        forces_equal = forces_equal && std::memcmp(&result[k].force[i], &whole[k].force[I], sizeof(vec2)) == 0;
      }
      for (std::size_t j = 0; j < plan.points.size(); ++j)
        states_equal = states_equal && std::memcmp(&result[k].states[j], &whole[k].states[plan.points[j]],
                                                   sizeof(M::state_type)) == 0;
      CHECK(forces_equal);
      CHECK(states_equal);
      narrowest[k] = std::min(narrowest[k], result[k].min_stretch);
    }
  }
  for (int k = 0; k < 3; ++k) CHECK(narrowest[k] == whole[k].min_stretch);
  CHECK(std::ranges::all_of(owners, [](int o) { return o == 3; }));  // every particle owned once, 3 times checked
  CHECK(redundant > m.point_count());  // the cuts make some points redundant: the check crosses them
}

}  // namespace

TEST_CASE("local force model: each rank's owned forces and point states equal the whole model's, bit for bit") {
  const discrete_model m = test::bar::model();
  const auto whole = evaluate(m);
  // The field yields: the check covers the return mapping, not the elastic branch alone.
  index_t plastic = 0;
  for (const auto& s : whole[2].states) plastic += s.equivalent_plastic_strain > 0.0;
  CHECK(plastic > m.point_count() / 2);
  // More than one tile and colour, so the restriction of the traversal is exercised.
  CHECK(m.traversal.colours() >= 2);

  for (index_t parts : {2, 3})
    check_partition(m, whole, partition_particles(m.at_points, m.particle_count(), parts),
                    "METIS into " + std::to_string(parts));
  // Cuts forced along the axis (r < R / 2 against the rest) and across the bar in three stripes.
  std::vector<stored_index> along(m.particle_count()), across(m.particle_count());
  for (index_t I = 0; I < m.particle_count(); ++I) {
    const vec2& X = m.particles.position[I];
    along[I] = X[0] < 0.5 * radius ? 0 : 1;
    across[I] = static_cast<stored_index>(std::min(2.0, std::floor(3.0 * X[1] / height)));
  }
  check_partition(m, whole, given_partition(along, 2), "along the axis");
  check_partition(m, whole, given_partition(across, 3), "three stripes across");
}

TEST_CASE("local force model: a plan of another model is refused") {
  const discrete_model m = test::bar::model();
  const discrete_model other = test::bar::model(5, 9);
  const halo_plan plan = make_halo_plan(partition_particles(other.at_points, other.particle_count(), 2), other.at_points, 0);
  CHECK_THROWS_WITH_AS(local_force_model(m, plan), doctest::Contains("make the plan from this model's table"),
                       rkpm::error);
}

}  // namespace test_mpi_local_force
