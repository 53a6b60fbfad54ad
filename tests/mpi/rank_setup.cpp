// The set-up in parts (parallel/rank_setup.hpp; run by ctest as mpi.rank_setup.ranks_N): each
// rank builds its part of the bar of mpi/bar_impact.hpp from the model's layout (particles,
// cells, points, bodies), evaluating shape functions only at its own points and the particles
// its plan reads, never a table of the whole model. Against the part cut from the whole model
// (local_model): the same plan and the same model, entry by entry and bit for bit (positions,
// weights, rows and values, gradients, traversal, rows at the particles, lumped volumes with
// the ghosts' forwarded); the step from it equals one process's, bit for bit, for METIS's
// partition and the coordinate bisection. Each rank holds its share of the particles and points
// plus its ghosts (asserted from the local counts). The same for two bodies, the rods of
// cases/rod_on_rod.hpp touching at z = 0 (each body's rows within the body, as
// build_model_of_bodies builds them; the points body by body; the bodies' surfaces and their
// rows in the shared region, where the contact between the rods reads them). VCI and SCNI rules
// and cracks are refused.

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
#include <rkpm/solver/body_models.hpp>

#include "cases/rod_on_rod.hpp"
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

// The bar of mpi/bar_impact.hpp on the anvil: one body.
struct bar_case {
  static discrete_model model() { return test::bar::model(); }
  static model_layout layout() { return bar_layout(); }
  static auto problem() { return test::bar::impact(); }
};

// Two rods of 5 x 9 particles meeting head on (cases/rod_on_rod.hpp): two bodies whose rows
// touch (the faces' particles coincide at z = 0), each a slave of the other's surface. Their
// particles (the mesh nodes) and cells are dealt alternately, so that neither a body's particles
// nor its cells are consecutive.
struct rods_case {
  using rods = cases::rod_on_rod;
  // 0, n, 1, n + 1, ...: the old index of each new one, for two halves of n.
  static std::vector<index_t> alternate(index_t n) {
    std::vector<index_t> old;
    for (index_t k = 0; k < n; ++k) old.insert(old.end(), {k, n + k});
    return old;
  }
  static auto problem() {
    rods::parameters p;
    p.radial_particles = 5;
    p.axial_particles = 9;
    p.lower_height_m = p.upper_height_m = 16.2e-3;
    p.friction = 0.2;
    auto rod = rods::build<test::bar::contact_type>(p, 1);
    const std::vector<index_t> node = alternate(rod.particles.size() / 2), cell = alternate(rod.mesh.cells() / 2);
    std::vector<stored_index> renamed(node.size());
    particle_set<2> particles;
    background_mesh mesh;
    for (index_t J = 0; J < static_cast<index_t>(node.size()); ++J) {
      renamed[node[J]] = static_cast<stored_index>(J);
      particles.position.push_back(rod.particles.position[node[J]]);
      particles.volume.push_back(rod.particles.volume[node[J]]);
      particles.support.push_back(rod.particles.support[node[J]]);
      mesh.node.push_back(rod.mesh.node[node[J]]);
    }
    for (const index_t c : cell) {
      std::array<stored_index, 4> nodes = rod.mesh.cell[c];
      for (stored_index& k : nodes) k = renamed[k];
      mesh.cell.push_back(nodes);
    }
    rod.particles = std::move(particles);
    rod.mesh = std::move(mesh);
    // The slaves: the two faces only, so that the rest of the surfaces is in the shared region
    // because the contact reads the surfaces.
    for (index_t J = 0; J < rod.particles.size(); ++J)
      if (rod.particles.position[J][1] == 0.0) rod.slave_particles.push_back(J);
    rod.initial_particle_velocity = [v = rod.initial_particle_velocity, node](index_t J, const vec2& X) {
      return v(node[J], X);
    };
    return rod;
  }
  static discrete_model model() {
    const auto p = problem();
    return build_model_of_bodies<kernel::cubic_spline, correction::linear, quadrature::q2, rods::geometry_type>(
        p.particles, p.mesh);
  }
  static model_layout layout() {
    auto p = problem();
    return make_model_layout<kernel::cubic_spline, correction::linear, quadrature::q2, rods::geometry_type>(
        std::move(p.particles), std::move(p.mesh));
  }
};

template <class Case>
void check_partition(communicator& world, const particle_partition& partition, const std::string& name) {
  CAPTURE(name);
  const solver_type one(Case::model(), Case::problem(), test::bar::options());
  distributed_solver<solver_type> cut(world, Case::model(), Case::problem(), test::bar::options(), partition);
  distributed_solver<solver_type> built(world, Case::layout(), Case::problem(), test::bar::options(), partition);
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
  CHECK(a.bodies.count() == b.bodies.count());
  CHECK(a.bodies.particle_body() == b.bodies.particle_body());
  CHECK(a.bodies.point_body() == b.bodies.point_body());
  if (one.model().bodies.count() > 1) {
    // The contact between the rods reads both surfaces: the part holds each chain's particles
    // (with their rows, the shared region; beyond the slaves, the faces), in local ids as the cut
    // part has them.
    std::vector<std::vector<index_t>> chains_a, chains_b;
    for (const boundary_chain& c : a.bodies.surface("test")) chains_a.push_back(c.node);
    for (const boundary_chain& c : b.bodies.surface("test")) chains_b.push_back(c.node);
    CHECK(chains_a == chains_b);
    CHECK(chains_a.size() == one.model().bodies.surface("test").size());
  }
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
  solver_type whole(Case::model(), Case::problem(), test::bar::options());
  index_t most_contacts = 0;
  for (int step = 1; step <= 30; ++step) {
    whole.step();
    built.solver().step();
    most_contacts = std::max(most_contacts, whole.last_contact().active);
  }
  CHECK(test::bar::same_totals(whole, built.solver()));
  const test::bar::differing_particles differ = test::bar::differing(world, built, whole);
  CHECK(differ.coefficients == 0);
  CHECK(differ.velocities == 0);
  CHECK(most_contacts > 0);
  CHECK(whole.energy().plastic > 0.0);
}

}  // namespace

TEST_CASE("set-up in parts: each rank's plan and model equal the part cut from the whole, and so does the step") {
  communicator world;
  const discrete_model m = test::bar::model();
  check_partition<bar_case>(world, partition_particles(m.at_points, m.particle_count(), world.size()), "METIS");
  check_partition<bar_case>(world, bisect_coordinates(m.particles.position, world.size()), "coordinate bisection");
}

TEST_CASE("set-up in parts of two bodies: each body's rows within it, the surfaces in the shared region") {
  communicator world;
  const discrete_model m = rods_case::model();
  REQUIRE(m.bodies.count() == 2);
  // Where the rods touch, a row of one rod finds the other's particles unless kept within its body.
  const neighbor_search<2> blind(m.particles);
  index_t mixed = 0;
  for (index_t q = 0; q < m.point_count(); ++q)
    for (const index_t I : blind.query(m.points.position[q])) mixed += m.bodies.of_particle(I) != m.bodies.of_point(q);
  CHECK(mixed > 0);
  check_partition<rods_case>(world, partition_particles(m.at_points, m.particle_count(), world.size()), "METIS");
  check_partition<rods_case>(world, bisect_coordinates(m.particles.position, world.size()), "coordinate bisection");
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
  // A body whose particles do not fill its cells, named as one process's builder checks each body.
  auto rods = rods_case::problem();
  for (index_t I = 0; I < rods.particles.size(); ++I)
    if (rods.particles.position[I][1] > 1e-9) rods.particles.volume[I] *= 1.5;
  CHECK(contains(error_message([&] {
                   make_model_layout<kernel::cubic_spline, correction::linear, quadrature::q2, test::bar::geometry_type>(
                       rods.particles, rods.mesh);
                 }),
                 "body 1: particle volumes add up to"));
}

}  // namespace test_mpi_rank_setup
