// Checkpoints on P processes (parallel/distributed_checkpoint.hpp; run by ctest as
// mpi.distributed_restart.ranks_N): the impact of mpi/distributed_step.cpp's bar, 12 steps on
// P ranks, then a checkpoint. The file written from P ranks equals, byte for byte, the one a
// single process writes at the same step (so a checkpoint does not depend on the process count
// it came from), and read back on the P ranks and, on every rank alone, into a one-process
// solver, both runs continue to 24 steps with the coefficients, velocities and energies of the
// uninterrupted run, bit for bit. With ranks_1..3 this covers a checkpoint from 2 processes
// continued on 1 and on 3: the file from 2 is the file from 1 and from 3.
// A checkpoint of another problem (a finer bar) is refused on every rank with one message.
// A checkpoint in parts (parallel/checkpoint_parts.hpp) written on the P ranks continues on
// every q = 1..P ranks of them and in a one-process solver to the uninterrupted run's bits (with
// ranks_3: from 3 processes on 3, 2 and 1); a part with a flipped byte and a missing part are
// refused on every rank, naming the part.

#include <doctest/doctest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/io/checkpoint_parts.hpp>
#include <rkpm/parallel/checkpoint_parts.hpp>
#include <rkpm/parallel/communicator.hpp>
#include <rkpm/parallel/distributed_checkpoint.hpp>
#include <rkpm/parallel/distributed_solver.hpp>
#include <rkpm/parallel/partition.hpp>
#include <rkpm/solver/checkpoint.hpp>
#include <rkpm/solver/explicit_solver.hpp>

#include "mpi/bar_impact.hpp"

#include "support/bits_and_bytes.hpp"
namespace test_mpi_distributed_restart {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;
using namespace rkpm::parallel;
using test::bar::solver_type;

namespace {

using rkpm::test::file_bytes;

constexpr std::string_view configuration = "bar impact";

// The particles of two solvers of the whole model whose coefficients differ in any bit.
index_t differing_coefficients(const solver_type& a, const solver_type& b) {
  index_t n = 0;
  for (index_t I = 0; I < a.model().particle_count(); ++I)
    n += std::memcmp(a.coefficients()[I].data(), b.coefficients()[I].data(), sizeof(vec2)) != 0;
  return n;
}

// The message every rank throws reading `folder` in parts on the P ranks.
std::string refusal(communicator& world, const std::filesystem::path& folder) {
  const discrete_model m = test::bar::model();
  distributed_solver<solver_type> run(world, test::bar::model(), test::bar::impact(), test::bar::options(),
                                      partition_particles(m.at_points, m.particle_count(), world.size()));
  try {
    read_checkpoint_parts(run, folder, configuration);
  } catch (const rank_failure& e) {
    CHECK(run.solver().steps() == 0);
    return e.what();
  }
  return {};
}

}  // namespace

TEST_CASE("a checkpoint from P ranks is one process's file, and continues on P ranks and on one to the same bits") {
  communicator world;
  const int P = world.size();
  const discrete_model m = test::bar::model();
  const particle_partition partition = partition_particles(m.at_points, m.particle_count(), P);
  // One folder per process count: ctest runs ranks_1, _2 and _3 side by side, each removing its own.
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / fmt::format("rkpm_test_distributed_restart_{}", world.size());
  const std::filesystem::path from_ranks = folder / fmt::format("ranks_{}.rkpm", P),
                              from_one = folder / fmt::format("one_{}_{}.rkpm", P, world.rank());
  if (world.rank() == 0) std::filesystem::create_directories(folder);
  world.agree();
  MPI_Barrier(world.get());

  // The uninterrupted run, on one process (every rank runs it).
  solver_type whole(test::bar::model(), test::bar::impact(), test::bar::options());
  for (int n = 0; n < 12; ++n) whole.step();
  write_checkpoint(whole, from_one, configuration);
  for (int n = 0; n < 12; ++n) whole.step();

  {
    distributed_solver<solver_type> part(world, test::bar::model(), test::bar::impact(), test::bar::options(), partition);
    for (int n = 0; n < 12; ++n) part.solver().step();
    write_checkpoint(part, from_ranks, configuration);
    CHECK(file_bytes(from_ranks) == file_bytes(from_one));
  }
  {
    distributed_solver<solver_type> again(world, test::bar::model(), test::bar::impact(), test::bar::options(), partition);
    read_checkpoint(again, from_ranks, configuration);
    CHECK(again.solver().steps() == 12);
    for (int n = 0; n < 12; ++n) again.solver().step();
    const test::bar::differing_particles n = test::bar::differing(world, again, whole);
    CHECK(n.coefficients == 0);
    CHECK(n.velocities == 0);
    CHECK(test::bar::same_totals(again.solver(), whole));
  }
  {
    solver_type alone(test::bar::model(), test::bar::impact(), test::bar::options());
    read_checkpoint(alone, from_ranks, configuration);
    for (int n = 0; n < 12; ++n) alone.step();
    index_t n = 0;
    for (index_t I = 0; I < m.particle_count(); ++I)
      n += std::memcmp(alone.coefficients()[I].data(), whole.coefficients()[I].data(), sizeof(vec2)) != 0;
    CHECK(n == 0);
    CHECK(test::bar::same_totals(alone, whole));
  }
  // Another problem's checkpoint: every rank refuses it with the same line.
  {
    distributed_solver<solver_type> finer(world, test::bar::model(9, 33), test::bar::impact(), test::bar::options(),
                                          partition_particles(test::bar::model(9, 33).at_points, 9 * 33, P));
    std::string message;
    try {
      read_checkpoint(finer, from_ranks, configuration);
    } catch (const rank_failure& e) {
      message = e.what();
    }
    CHECK(message.find("restart the same problem at the same resolution") != std::string::npos);
  }
  std::filesystem::remove(from_one);
  MPI_Barrier(world.get());
  if (world.rank() == 0) std::filesystem::remove_all(folder);
}

TEST_CASE("a checkpoint in parts from P ranks continues on 1..P ranks and on one process to the same bits") {
  communicator world;
  const int P = world.size();
  const discrete_model m = test::bar::model();
  // One folder per process count: ctest runs ranks_1, _2 and _3 side by side, each removing its own.
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / fmt::format("rkpm_test_checkpoint_parts_{}", world.size());
  const std::filesystem::path parts = folder / fmt::format("ranks_{}.rkpmcp", P);
  if (world.rank() == 0) std::filesystem::create_directories(folder);
  MPI_Barrier(world.get());

  solver_type whole(test::bar::model(), test::bar::impact(), test::bar::options());
  for (int n = 0; n < 24; ++n) whole.step();
  {
    distributed_solver<solver_type> run(world, test::bar::model(), test::bar::impact(), test::bar::options(),
                                        partition_particles(m.at_points, m.particle_count(), P));
    for (int n = 0; n < 12; ++n) run.solver().step();
    write_checkpoint_parts(run, parts, configuration);
    // Each part holds its writer's owned particles, not the whole model's.
    io::checkpoint_reader mine(io::checkpoint_part_path(parts, world.rank(), P));
    std::uint64_t index = 0;
    mine.value("part.index", index);
    CHECK(index == static_cast<std::uint64_t>(world.rank()));
    CHECK(mine.sections()[4].count == run.plan().owned.size());
    CHECK(mine.header().identity.particles == m.particle_count());
    CHECK_FALSE(std::filesystem::exists(std::filesystem::path(parts.string() + ".writing")));
  }
  for (int q = 1; q <= P; ++q) {
    MPI_Comm sub = MPI_COMM_NULL;
    MPI_Comm_split(world.get(), world.rank() < q ? 0 : MPI_UNDEFINED, world.rank(), &sub);
    if (sub == MPI_COMM_NULL) continue;
    {
      communicator some(sub);
      distributed_solver<solver_type> again(some, test::bar::model(), test::bar::impact(), test::bar::options(),
                                            partition_particles(m.at_points, m.particle_count(), q));
      read_checkpoint_parts(again, parts, configuration);
      CHECK(again.solver().steps() == 12);
      for (int n = 0; n < 12; ++n) again.solver().step();
      const test::bar::differing_particles n = test::bar::differing(some, again, whole);
      INFO("continued on ", q, " of ", P, " ranks");
      CHECK(n.coefficients == 0);
      CHECK(n.velocities == 0);
      CHECK(test::bar::same_totals(again.solver(), whole));
    }
    MPI_Comm_free(&sub);
  }
  {
    solver_type alone(test::bar::model(), test::bar::impact(), test::bar::options());
    read_checkpoint(alone, parts, configuration);
    for (int n = 0; n < 12; ++n) alone.step();
    CHECK(differing_coefficients(alone, whole) == 0);
    CHECK(test::bar::same_totals(alone, whole));
  }

  // The last part with a flipped byte, then without the last part: refused, naming it.
  const std::filesystem::path damaged = folder / "damaged.rkpmcp", last = io::checkpoint_part_path(damaged, P - 1, P);
  if (world.rank() == 0) {
    std::filesystem::copy(parts, damaged);
    std::string bytes = file_bytes(last);
    bytes[bytes.size() / 2] ^= 0x10;
    std::ofstream(last, std::ios::binary | std::ios::trunc) << bytes;
  }
  MPI_Barrier(world.get());
  std::string message = refusal(world, damaged);
  INFO(message);
  CHECK(message.find(last.string()) != std::string::npos);
  CHECK(message.find("restart from an earlier checkpoint") != std::string::npos);
  {
    solver_type alone(test::bar::model(), test::bar::impact(), test::bar::options());
    CHECK_THROWS_WITH_AS(read_checkpoint(alone, damaged, configuration),
                         doctest::Contains(last.string().c_str()), io::checkpoint_damaged);
    CHECK(alone.steps() == 0);
  }
  MPI_Barrier(world.get());
  if (world.rank() == 0) std::filesystem::remove(last);
  MPI_Barrier(world.get());
  message = refusal(world, damaged);
  CHECK(message.find(P > 1 ? last.string() + "': it is missing" : std::string("a folder without checkpoint parts")) !=
        std::string::npos);

  MPI_Barrier(world.get());
  if (world.rank() == 0) std::filesystem::remove_all(folder);
}

}  // namespace test_mpi_distributed_restart
