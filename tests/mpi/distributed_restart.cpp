// Checkpoints on P processes (parallel/distributed_checkpoint.hpp; run by ctest as
// mpi.distributed_restart.ranks_N): the impact of mpi/distributed_step.cpp's bar, 12 steps on
// P ranks, then a checkpoint. The file written from P ranks equals, byte for byte, the one a
// single process writes at the same step (so a checkpoint does not depend on the process count
// it came from), and read back on the P ranks and, on every rank alone, into a one-process
// solver, both runs continue to 24 steps with the coefficients, velocities and energies of the
// uninterrupted run, bit for bit. With ranks_1..3 this covers a checkpoint from 2 processes
// continued on 1 and on 3: the file from 2 is the file from 1 and from 3.
// A checkpoint of another problem (a finer bar) is refused on every rank with one message.

#include <doctest/doctest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/parallel/communicator.hpp>
#include <rkpm/parallel/distributed_checkpoint.hpp>
#include <rkpm/parallel/distributed_solver.hpp>
#include <rkpm/parallel/partition.hpp>
#include <rkpm/solver/checkpoint.hpp>
#include <rkpm/solver/explicit_solver.hpp>

#include "mpi/bar_impact.hpp"

namespace test_mpi_distributed_restart {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;
using namespace rkpm::parallel;
using test::bar::solver_type;

namespace {

constexpr std::string_view configuration = "bar impact";

std::string bytes_of(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_CASE("a checkpoint from P ranks is one process's file, and continues on P ranks and on one to the same bits") {
  communicator world;
  const int P = world.size();
  const discrete_model m = test::bar::model();
  const particle_partition partition = partition_particles(m.at_points, m.particle_count(), P);
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "rkpm_test_distributed_restart";
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
    CHECK(bytes_of(from_ranks) == bytes_of(from_one));
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

}  // namespace test_mpi_distributed_restart
