// The force loop on 1, 2 and 3 processes (run by ctest as mpi.distributed_force.ranks_N): each
// rank builds its plan and local model (parallel/local_model.hpp) of the axisymmetric J2 bar of
// mpi/bar_problem.hpp, sets its owned coefficients, gets its ghosts' through halo_exchange::
// forward, and evaluates point_materials<axisymmetric, J2>::internal_force three times into
// yield. Against one process's evaluation, bit for bit (memcmp): the owned forces gathered on
// rank 0; the plastic work, summed per point owner (point_owners) through global_block_sums
// with the traversal's tiles as blocks, so in the one-process order; and the smallest support
// stretch, a minimum over the ranks. For METIS's partition and for stripes forced across the bar.
// The plastic work summed per rank and then across the ranks (the obvious way) counts the
// redundant points twice: the test checks that it differs, so the comparison can fail.
// A bar with one particle pushed through it: the ranks stop together with one message, naming
// the failing rank and the point by its index in the whole model (as one process names it).

#include <doctest/doctest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <rkpm/parallel/communicator.hpp>
#include <rkpm/parallel/gather.hpp>
#include <rkpm/parallel/global_blocks.hpp>
#include <rkpm/parallel/halo.hpp>
#include <rkpm/parallel/local_model.hpp>
#include <rkpm/parallel/mpi_block_sums.hpp>
#include <rkpm/parallel/mpi_exchange.hpp>
#include <rkpm/parallel/partition.hpp>
#include <rkpm/solver/body_materials.hpp>
#include <rkpm/solver/point_materials.hpp>

#include "mpi/bar_problem.hpp"

namespace test_mpi_distributed_force {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;
using namespace rkpm::parallel;

namespace {

using G = test::bar::geometry_type;
using M = test::bar::material_type;
using test::bar::evaluations;
using test::bar::step;

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

struct one_process {
  std::vector<std::vector<vec2>> force;
  std::vector<double> plastic, stretch;
};

one_process evaluate_whole(const discrete_model& m) {
  const materials_by_body<M> material(m, test::bar::copper(), {});
  point_materials<G, M> points(m, material);
  one_process out;
  for (int k = 0; k < evaluations; ++k) {
    std::vector<vec2> f(m.particle_count());
    points.internal_force(m, material, test::bar::coefficients(m, k), f, step(k));
    out.force.push_back(f);
    out.plastic.push_back(points.plastic_work());
    out.stretch.push_back(points.min_stretch());
  }
  return out;
}

void check_on_ranks(communicator& world, const discrete_model& m, const one_process& whole,
                    const particle_partition& partition, const std::string& name) {
  CAPTURE(name);
  const int rank = world.rank();
  const halo_plan plan = make_halo_plan(partition, m.at_points, rank);
  const discrete_model local = local_force_model(m, plan);
  const particle_partition point_owner = point_owners(partition, m.at_points);
  const std::vector<stored_index> owned_points = owned_point_positions(plan, point_owner);
  global_block_sums<1> plastic_sum(world, make_global_block_plan(point_owner, rank, traversal_tile_points),
                                   traversal_tile_points);
  const materials_by_body<M> material(local, test::bar::copper(), {});
  point_materials<G, M> points(local, material);
  halo_exchange exchange(world, plan);
  for (int k = 0; k < evaluations; ++k) {
    CAPTURE(k);
    // Owners set theirs; ghosts start as NaN, so one that forward() missed would show.
    std::vector<vec2> x = test::bar::coefficients(local, k, static_cast<index_t>(plan.owned.size())),
                      f(local.particle_count());
    exchange.forward(x);
    points.internal_force(local, material, x, f, step(k));
    const std::vector<vec2> gathered = rkpm::parallel::gather_owned(world, plan, f);
    if (rank == 0) {
      index_t differ = 0;
      for (index_t I = 0; I < m.particle_count(); ++I)
        differ += std::memcmp(gathered[I].data(), whole.force[k][I].data(), sizeof(vec2)) != 0;
      CHECK(differ == 0);
    }
    const double plastic = plastic_sum([&](index_t i, global_block_sums<1>::sums& t) {
      const stored_index j = owned_points[i];
      t[0] += points.states()[j].plastic_work * local.points.weight[j];
    })[0];
    CHECK(same_bits(plastic, whole.plastic[k]));
    CHECK(world.min(points.min_stretch()) == whole.stretch[k]);
    // Each rank's own per-tile sum, added over the ranks: redundant points counted twice.
    if (world.size() > 1 && k == evaluations - 1) {
      double naive = points.plastic_work();
      MPI_Allreduce(MPI_IN_PLACE, &naive, 1, MPI_DOUBLE, MPI_SUM, world.get());
      CHECK(naive > whole.plastic[k] * (1.0 + 1e-6));
    }
  }
}

}  // namespace

TEST_CASE("the force loop on 1, 2 or 3 ranks: one process's forces, plastic work and support stretch, bit for bit") {
  communicator world;
  const int P = world.size();
  const discrete_model m = test::bar::model();
  const one_process whole = evaluate_whole(m);
  REQUIRE(whole.plastic.back() > 0.0);
  REQUIRE(m.traversal.tiles() >= 3);  // several blocks: the plastic work's order is exercised

  check_on_ranks(world, m, whole, partition_particles(m.at_points, m.particle_count(), P), "METIS");
  std::vector<stored_index> stripes(m.particle_count());
  for (index_t I = 0; I < m.particle_count(); ++I)
    stripes[I] = static_cast<stored_index>(
        std::min<double>(P - 1, std::floor(P * m.particles.position[I][1] / test::bar::height)));
  check_on_ranks(world, m, whole, given_partition(stripes, P), "stripes across the bar");
}

TEST_CASE("an inverted point on the ranks: every rank stops with the same message, naming the rank and the point") {
  communicator world;
  const int P = world.size();
  const discrete_model m = test::bar::model();
  // One particle pushed 6 spacings down through the bar (at mid-height, by the axis): the points
  // of its support invert. On one process the loop stops at the first of them in its order.
  const index_t J = m.particle_count() / 2 - 4;
  const auto inverted = [&](index_t I) {
    vec2 x = m.particles.position[I];
    if (I == J) x[1] -= 6.0 * test::bar::height / 30.0;
    return x;
  };
  std::string serial;
  {
    const materials_by_body<M> material(m, test::bar::copper(), {});
    point_materials<G, M> points(m, material);
    std::vector<vec2> x(m.particle_count()), f(m.particle_count());
    for (index_t I = 0; I < m.particle_count(); ++I) x[I] = inverted(I);
    try {
      points.internal_force(m, material, x, f, step(0));
    } catch (const error& e) {
      serial = e.what();
    }
  }
  REQUIRE(serial.find("det F") != std::string::npos);

  const auto check = [&](const particle_partition& partition, const std::string& name) {
    CAPTURE(name);
    const halo_plan plan = make_halo_plan(partition, m.at_points, world.rank());
    const discrete_model local = local_force_model(m, plan);
    const materials_by_body<M> material(local, test::bar::copper(), {});
    point_materials<G, M> points(local, material);
    std::vector<vec2> x(local.particle_count()), f(local.particle_count());
    for (index_t i = 0; i < local.particle_count(); ++i) x[i] = inverted(plan.global_particle(i));
    std::string agreed;
    try {
      world.guarded([&] { points.internal_force(local, material, x, f, step(0)); });
      world.agree();
    } catch (const rank_failure& e) {
      agreed = e.what();
    }
    // The same line on every rank (rank 0's, sent to all, compared).
    int length = static_cast<int>(agreed.size());
    MPI_Bcast(&length, 1, MPI_INT, 0, world.get());
    std::string first(static_cast<std::size_t>(length), ' ');
    if (world.rank() == 0) first = agreed;
    MPI_Bcast(first.data(), length, MPI_CHAR, 0, world.get());
    CHECK(agreed == first);
    if (world.rank() == 0) MESSAGE(agreed);
    // "rank r of P: <the one-process message for the point that rank found first>": the point
    // is named by its index in the whole model, with its position.
    REQUIRE(agreed.rfind("rank ", 0) == 0);
    const std::string message = agreed.substr(agreed.find(": ") + 2);
    const auto at = message.find("quadrature point ");
    REQUIRE(at != std::string::npos);
    const index_t q = std::stol(message.substr(at + 17));
    const vec2& X = m.points.position[q];
    CHECK(message.find(fmt::format("quadrature point {} (X = {:.6g}, {:.6g})", q, X[0], X[1])) != std::string::npos);
    CHECK(message.find("det F") != std::string::npos);
    if (P == 1) CHECK(message == serial);
  };
  check(partition_particles(m.at_points, m.particle_count(), P), "METIS");
  // Stripes numbered from the top, so that rank 0 holds the top of the bar: its local point
  // numbers then differ from the whole model's at the failure.
  std::vector<stored_index> from_top(m.particle_count());
  for (index_t I = 0; I < m.particle_count(); ++I)
    from_top[I] = static_cast<stored_index>(
        std::min<double>(P - 1, std::floor(P * (1.0 - m.particles.position[I][1] / test::bar::height))));
  check(given_partition(from_top, P), "stripes from the top");
}

}  // namespace test_mpi_distributed_force
