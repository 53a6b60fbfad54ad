// The set-up in parts (parallel/rank_setup.hpp; run by ctest as mpi.rank_setup.ranks_N): each
// rank builds its part of the bar of mpi/bar_impact.hpp from the model's layout (particles,
// cells, points, bodies), evaluating shape functions only at its own points and the particles
// its plan reads, never a table of the whole model. Against the part cut from the whole model
// (local_model): the same plan and the same model, entry by entry and bit for bit (positions,
// weights, rows and values, gradients, traversal, rows at the particles, lumped volumes with
// the ghosts' forwarded); the step from it equals one process's, bit for bit, for METIS's
// partition and the coordinate bisection. Each rank holds its share of the particles and points
// plus its ghosts (asserted from the local counts). VCI and SCNI rules, cracks and several
// bodies are refused.

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <string>
#include <vector>

#include <rkpm/parallel/communicator.hpp>
#include <rkpm/parallel/coordinate_bisection.hpp>
#include <rkpm/parallel/distributed_solver.hpp>
#include <rkpm/parallel/partition.hpp>
#include <rkpm/parallel/rank_setup.hpp>
#include <rkpm/quadrature/scni.hpp>
#include <rkpm/quadrature/vci.hpp>

#include "mpi/bar_impact.hpp"
#include "support/bits_and_bytes.hpp"
#include "support/error_message.hpp"

namespace test_mpi_rank_setup {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;
using namespace rkpm::parallel;

namespace {

using rkpm::test::same_bits;

using test::bar::solver_type;

template <class Q = quadrature::q2>
model_layout bar_layout() {
  const vec2 lo(0.0, 0.0), hi(test::bar::radius, test::bar::height);
  const Eigen::Vector2i n(9, 31);
  return make_model_layout<kernel::cubic_spline, correction::linear, Q, test::bar::geometry_type>(
      make_grid_particles<2>(lo, hi, n, 2.0), make_grid_mesh(lo, hi, n));
}

template <int Dim>
bool same_table(const shape_table<Dim>& a, const shape_table<Dim>& b) {
  return a.offset == b.offset && a.neighbor == b.neighbor && same_bits(a.N, b.N) && same_bits(a.grad, b.grad);
}

bool same_plan(const halo_plan& a, const halo_plan& b) {
  const auto same_links = [](const std::vector<halo_link>& x, const std::vector<halo_link>& y) {
    return std::ranges::equal(x, y, [](const halo_link& p, const halo_link& q) {
      return p.rank == q.rank && p.particles == q.particles;
    });
  };
  return a.owned == b.owned && a.ghosts == b.ghosts && a.points == b.points && same_links(a.sends, b.sends) &&
         same_links(a.receives, b.receives);
}

void check_partition(communicator& world, const particle_partition& partition, const std::string& name) {
  CAPTURE(name);
  const solver_type one(test::bar::model(), test::bar::impact(), test::bar::options());
  distributed_solver<solver_type> cut(world, test::bar::model(), test::bar::impact(), test::bar::options(), partition);
  distributed_solver<solver_type> built(world, bar_layout(), test::bar::impact(), test::bar::options(), partition);
  CHECK(same_plan(built.plan(), cut.plan()));
  CHECK(built.shared_count() == cut.shared_count());
  const discrete_model& a = built.solver().model();
  const discrete_model& b = cut.solver().model();
  CHECK(same_bits(a.particles.position, b.particles.position));
  CHECK(same_bits(a.particles.volume, b.particles.volume));
  CHECK(same_bits(a.particles.support, b.particles.support));
  CHECK(same_bits(a.points.position, b.points.position));
  CHECK(same_bits(a.points.weight, b.points.weight));
  CHECK(a.points.cell == b.points.cell);
  CHECK(same_table(a.at_points, b.at_points));
  CHECK(same_table(a.at_particles, b.at_particles));
  CHECK(same_bits(a.lumped_volume, b.lumped_volume));
  CHECK(a.traversal.tile_start == b.traversal.tile_start);
  CHECK(a.traversal.tile == b.traversal.tile);
  CHECK(a.traversal.colour_start == b.traversal.colour_start);
  CHECK(a.traversal.serial_from == b.traversal.serial_from);
  CHECK(a.traversal.paired_rows == b.traversal.paired_rows);
  CHECK(a.point_id == b.point_id);
  CHECK(a.particle_id == b.particle_id);
  CHECK(same_bits(built.solver().mass(), cut.solver().mass()));
  // The rank's share: its owned particles and their points, plus ghosts; never the whole model
  // on two processes or more.
  const index_t N = one.model().particle_count(), Q = one.model().point_count();
  const index_t owned = static_cast<index_t>(built.plan().owned.size());
  CHECK(a.particle_count() == owned + static_cast<index_t>(built.plan().ghosts.size()));
  CHECK(a.at_points.points() == a.point_count());
  if (world.size() > 1) {
    CHECK(a.particle_count() < N);
    CHECK(a.point_count() < Q);
    CHECK(static_cast<double>(owned) <= 1.1 * static_cast<double>(N) / world.size() + 1.0);
  }
  // The step from the part built alone is one process's, bit for bit.
  solver_type whole(test::bar::model(), test::bar::impact(), test::bar::options());
  for (int step = 1; step <= 30; ++step) {
    whole.step();
    built.solver().step();
  }
  CHECK(test::bar::same_totals(whole, built.solver()));
  const test::bar::differing_particles differ = test::bar::differing(world, built, whole);
  CHECK(differ.coefficients == 0);
  CHECK(differ.velocities == 0);
  CHECK(whole.last_contact().active > 0);
  CHECK(whole.energy().plastic > 0.0);
}

}  // namespace

TEST_CASE("set-up in parts: each rank's plan and model equal the part cut from the whole, and so does the step") {
  communicator world;
  const discrete_model m = test::bar::model();
  check_partition(world, partition_particles(m.at_points, m.particle_count(), world.size()), "METIS");
  check_partition(world, bisect_coordinates(m.particles.position, world.size()), "coordinate bisection");
}

TEST_CASE("set-up in parts: VCI and SCNI rules and cracks are refused with the way out") {
  using test::contains;
  using test::error_message;
  CHECK(contains(error_message([] { bar_layout<quadrature::q2_vci>(); }), "set up a VCI or SCNI model whole"));
  CHECK(contains(error_message([] { bar_layout<quadrature::scni<>>(); }), "set up a VCI or SCNI model whole"));
  const vec2 lo(0.0, 0.0), hi(test::bar::radius, test::bar::height);
  background_mesh cracked = make_grid_mesh(lo, hi, Eigen::Vector2i(9, 31));
  cracked.cracks.add(vec2(0.0, 8e-3), vec2(1e-3, 8e-3));
  CHECK(contains(error_message([&] {
                   make_model_layout<kernel::cubic_spline, correction::linear, quadrature::q2, test::bar::geometry_type>(
                       make_grid_particles<2>(lo, hi, Eigen::Vector2i(9, 31), 2.0), cracked);
                 }),
                 "set up a cracked model whole"));
  // Two bars side by side: two bodies, whose tables the runner builds apart (body_models.hpp).
  particle_set<2> two = make_grid_particles<2>(lo, hi, Eigen::Vector2i(5, 9), 2.0);
  background_mesh cells = make_grid_mesh(lo, hi, Eigen::Vector2i(5, 9));
  const vec2 shift(2.0 * test::bar::radius, 0.0);
  const auto nodes = static_cast<stored_index>(cells.node.size());
  const particle_set<2> other = make_grid_particles<2>(lo + shift, hi + shift, Eigen::Vector2i(5, 9), 2.0);
  const background_mesh other_cells = make_grid_mesh(lo + shift, hi + shift, Eigen::Vector2i(5, 9));
  two.position.insert(two.position.end(), other.position.begin(), other.position.end());
  two.volume.insert(two.volume.end(), other.volume.begin(), other.volume.end());
  two.support.insert(two.support.end(), other.support.begin(), other.support.end());
  cells.node.insert(cells.node.end(), other_cells.node.begin(), other_cells.node.end());
  for (std::array<stored_index, 4> c : other_cells.cell) {
    for (stored_index& k : c) k += nodes;
    cells.cell.push_back(c);
  }
  CHECK(contains(error_message([&] {
                   make_model_layout<kernel::cubic_spline, correction::linear, quadrature::q2, test::bar::geometry_type>(
                       two, cells);
                 }),
                 "set-up in parts of 2 bodies"));
}

}  // namespace test_mpi_rank_setup
