// Re-referencing on 1, 2 and 3 processes (parallel/distributed_rereference.hpp; run by ctest as
// mpi.distributed_rereference.ranks_N): the bar impact of mpi/bar_impact.hpp built through
// make_solver (the builder a re-reference calls), re-referenced every 10 steps and, apart, by
// the kernels' stretch (a threshold that fires at least three times in 45 steps), on P ranks,
// against the one-process run every rank also steps. Every 15 steps the ranks' owned
// coefficients, velocities and current positions equal one process's bit for bit, and so do the
// totals (time, step size, every energy including the remap, the impulse) and the re-references'
// times. A checkpoint written on P ranks after the re-references is one process's file byte for
// byte; read on P ranks (through the whole solver, which rebuilds the re-referenced model), and
// a checkpoint in parts likewise (parallel/checkpoint_parts.hpp), it continues to the
// uninterrupted run's bits across more re-references. From a lopsided partition with the load
// bound (rereference.rebalance_above) just above 1, every re-reference on several ranks
// partitions the particles again (the owned counts change, the load falls) and the run stays
// one process's bits; a bound never passed keeps the partition. Without the whole solver's maker the
// re-reference is refused on every rank alike; a part stepped past a pending re-reference is
// refused.

#include <doctest/doctest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <rkpm/parallel/checkpoint_parts.hpp>
#include <rkpm/parallel/communicator.hpp>
#include <rkpm/parallel/distributed_checkpoint.hpp>
#include <rkpm/parallel/distributed_solver.hpp>
#include <rkpm/parallel/gather.hpp>
#include <rkpm/parallel/partition.hpp>
#include <rkpm/solver/checkpoint.hpp>
#include <rkpm/solver/config.hpp>
#include <rkpm/solver/make_solver.hpp>

#include "mpi/bar_impact.hpp"
#include "support/bits_and_bytes.hpp"
#include "support/error_message.hpp"

namespace test_mpi_distributed_rereference {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;
using namespace rkpm::parallel;
using test::bar::solver_type;

namespace {

using rkpm::test::file_bytes;

using method = config<kernel::cubic_spline, correction::linear, quadrature::q2, test::bar::geometry_type,
                      test::bar::material_type, test::bar::contact_type>;
constexpr std::string_view configuration = "bar impact, re-referenced";

problem_for<method> bar() {
  problem_for<method> p = test::bar::impact();
  const vec2 lo(0.0, 0.0), hi(test::bar::radius, test::bar::height);
  const Eigen::Vector2i n(9, 31);
  p.particles = make_grid_particles<2>(lo, hi, n, 2.0);
  p.mesh = make_grid_mesh(lo, hi, n);
  return p;
}

run_options options(rereference_policy when) {
  run_options o = test::bar::options();
  o.rereference = when;
  return o;
}

// The run on the ranks, the whole model as make_solver builds it.
distributed_solver<solver_type> on_ranks(communicator& world, const run_options& o) {
  const discrete_model whole = make_solver<method>(bar(), o).model();
  distributed_solver<solver_type> run(world, whole, bar(), o,
                                      partition_particles(whole.at_points, whole.particle_count(), world.size()));
  run.rereference_through([o] { return make_solver<method>(bar(), o); });
  return run;
}

// Whether the ranks' owned values and every total are one process's bits (collective).
bool same_run(communicator& world, const distributed_solver<solver_type>& run, const solver_type& one) {
  const test::bar::differing_particles n = test::bar::differing(world, run, one);
  const std::vector<vec2> x = gather_owned(world, run.plan(), run.solver().particle_positions()),
                          x1 = one.particle_positions();
  index_t positions = 0;
  for (std::size_t I = 0; I < x.size(); ++I) positions += std::memcmp(x[I].data(), x1[I].data(), sizeof(vec2)) != 0;
  const solver_type& s = run.solver();
  const bool totals = test::bar::same_totals(s, one) &&
                      std::memcmp(&s.energy().remap, &one.energy().remap, sizeof(double)) == 0 &&
                      s.rereference_times() == one.rereference_times();
  CHECK(n.coefficients == 0);
  CHECK(n.velocities == 0);
  CHECK(positions == 0);
  CHECK(totals);
  return n.coefficients == 0 && n.velocities == 0 && positions == 0 && totals;
}

// A lopsided partition: part 0 owns the first three quarters of the particles (by index), the
// other parts share the rest.
particle_partition lopsided(index_t n, int parts) {
  std::vector<stored_index> part(n, 0);
  const index_t rest = n / 4;
  for (index_t k = 0; k < rest && parts > 1; ++k)
    part[n - rest + k] = static_cast<stored_index>(1 + k * (parts - 1) / rest);
  return given_partition(std::move(part), parts);
}

}  // namespace

TEST_CASE("a run re-referenced on P ranks is one process's, bit for bit, and restarts from its checkpoint") {
  communicator world;
  // One folder per process count: ctest runs ranks_1, _2 and _3 side by side, each removing its own.
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / fmt::format("rkpm_test_distributed_rereference_{}", world.size());
  if (world.rank() == 0) std::filesystem::create_directories(folder);
  MPI_Barrier(world.get());
  for (const rereference_policy when : {rereference_policy{.every_steps = 10}, rereference_policy{.max_stretch = 1.05}}) {
    CAPTURE(when.every_steps);
    const run_options o = options(when);
    solver_type one = make_solver<method>(bar(), o);
    distributed_solver<solver_type> run = on_ranks(world, o);
    for (int n = 1; n <= 45; ++n) {
      one.step();
      run.step();
      if (n % 15 == 0) {
        CAPTURE(n);
        same_run(world, run, one);
      }
    }
    CHECK(one.rereferences() >= 3);  // what the test is for: several re-references, in contact
    CHECK(one.last_contact().active > 0);
    CHECK(run.rebuilds() == one.rereferences());

    // A checkpoint after the re-references: one process's file; read on the ranks, it goes on as
    // the uninterrupted run.
    const std::filesystem::path from_ranks = folder / fmt::format("ranks_{}_{}.rkpm", world.size(), when.every_steps),
                                from_one = folder / fmt::format("one_{}_{}_{}.rkpm", world.size(), world.rank(),
                                                                when.every_steps);
    write_checkpoint(run, from_ranks, configuration);
    write_checkpoint(one, from_one, configuration);
    CHECK(file_bytes(from_ranks) == file_bytes(from_one));
    const std::filesystem::path parts = folder / fmt::format("parts_{}_{}.rkpmcp", world.size(), when.every_steps);
    write_checkpoint_parts(run, parts, configuration);
    distributed_solver<solver_type> again = on_ranks(world, o), again_in_parts = on_ranks(world, o);
    read_checkpoint(again, from_ranks, configuration);
    read_checkpoint_parts(again_in_parts, parts, configuration);
    for (int n = 0; n < 25; ++n) {
      one.step();
      again.step();
      again_in_parts.step();
    }
    CHECK(one.rereferences() >= 4);
    same_run(world, again, one);
    same_run(world, again_in_parts, one);
    std::filesystem::remove(from_one);
  }
  MPI_Barrier(world.get());
  if (world.rank() == 0) std::filesystem::remove_all(folder);
}

TEST_CASE("past the load bound a re-reference partitions the particles again, with one process's bits") {
  const rereference_policy unbounded{.every_steps = 1, .rebalance_above = 0.9};
  CHECK(test::contains(test::error_message([&] { unbounded.validate(); }), "rebalance_above 0.9 must be at least 1"));
  communicator world;
  run_options o = options({.every_steps = 10});
  o.rereference.rebalance_above = 1.0 + 1e-12;  // every re-reference on several ranks repartitions
  solver_type one = make_solver<method>(bar(), o);
  const discrete_model whole = one.model();
  const particle_partition start = lopsided(whole.particle_count(), world.size());
  const double before = load_imbalance(whole.at_points, start);
  distributed_solver<solver_type> run(world, whole, bar(), o, start);
  run.rereference_through([o] { return make_solver<method>(bar(), o); });
  for (int n = 1; n <= 30; ++n) {
    one.step();
    run.step();
    if (n % 15 == 0) {
      CAPTURE(n);
      same_run(world, run, one);
    }
  }
  CHECK(one.rereferences() >= 2);
  CHECK(run.rebuilds() == one.rereferences());
  if (world.size() == 1) {
    CHECK(run.repartitions() == 0);  // one part is balanced
    return;
  }
  // What the test is for: the parts were built on a new partition, whose load is the partitioner's.
  CHECK(run.repartitions() >= 1);
  CHECK(run.partition().sizes() != start.sizes());
  CHECK(static_cast<index_t>(run.plan().owned.size()) == run.partition().sizes()[world.rank()]);
  CHECK(load_imbalance(one.model().at_points, run.partition()) < before);
  // A bound never passed keeps the set-up's partition.
  o.rereference.rebalance_above = 1e300;
  distributed_solver<solver_type> kept(world, whole, bar(), o, start);
  kept.rereference_through([o] { return make_solver<method>(bar(), o); });
  for (int n = 1; n <= 10; ++n) kept.step();
  CHECK(kept.rebuilds() == 1);
  CHECK(kept.repartitions() == 0);
  CHECK(kept.partition().part == start.part);
}

TEST_CASE("a re-reference on P ranks without the whole solver is refused on every rank; so is a part stepped past it") {
  communicator world;
  const run_options o = options({.every_steps = 2});
  const discrete_model whole = make_solver<method>(bar(), o).model();
  distributed_solver<solver_type> run(world, whole, bar(), o,
                                      partition_particles(whole.at_points, whole.particle_count(), world.size()));
  run.step();
  std::string message;
  try {
    run.step();
  } catch (const rank_failure& e) {
    message = e.what();
  }
  CHECK(message.find("rereference_through") != std::string::npos);
  CHECK(run.solver().rereference_pending());
  std::string stepped;
  try {
    run.solver().step();
  } catch (const error& e) {
    stepped = e.what();
  }
  CHECK(stepped.find("a re-reference is due on several processes") != std::string::npos);
}

}  // namespace test_mpi_distributed_rereference
