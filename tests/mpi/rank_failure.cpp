// A failure on one rank reaches every rank (parallel/communicator.hpp), run by ctest on 1, 2 and
// 3 processes with a timeout, so a rank left waiting fails the test instead of hanging it. An
// error kept by guarded() on rank 1 (rank 0 on one process) is thrown on every rank, with the
// same message naming that rank, by the next forward(), block sum or max; the ranks then go on
// exchanging normally. Several failing ranks: the lowest one's message and how many failed. A
// field of the wrong length, or a plan of another rank, on one rank: an error on every rank.
// (The unguarded case, an exception that leaves one rank outside guarded(): ctest
// mpi.unguarded_error, tests/mpi/unguarded_error.cpp.)

#include <doctest/doctest.h>

#include <string>
#include <vector>

#include <rkpm/core/block_sums.hpp>
#include <rkpm/parallel/communicator.hpp>
#include <rkpm/parallel/global_blocks.hpp>
#include <rkpm/parallel/halo.hpp>
#include <rkpm/parallel/mpi_block_sums.hpp>
#include <rkpm/parallel/mpi_exchange.hpp>
#include <rkpm/parallel/partition.hpp>

#include "mpi/grid_problem.hpp"
#include "support/error_message.hpp"

namespace test_mpi_rank_failure {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;
using namespace rkpm::parallel;
using rkpm::test::contains;

namespace {

// The message of the rank_failure that f throws on this rank, or "" (and a failed check) if none.
template <class F>
std::string agreed_failure(F&& f) {
  try {
    f();
  } catch (const rank_failure& e) {
    return e.what();
  }
  FAIL_CHECK("no rank_failure was thrown");
  return {};
}

struct exchange_setup {
  test::grid_problem g;
  particle_partition partition;
  halo_plan plan;
  std::vector<vec2> d;
  explicit exchange_setup(int ranks, int rank)
      : partition(partition_particles(g.table, g.size(), ranks)), plan(make_halo_plan(partition, g.table, rank)),
        d(plan.local_particles(), vec2::Zero()) {}
};

}  // namespace

TEST_CASE("an error kept on one rank is thrown on every rank by the next exchange, sum or max") {
  communicator world;
  const int P = world.size(), failing = P > 1 ? 1 : 0;
  exchange_setup s(P, world.rank());
  halo_exchange exchange(world, s.plan);
  global_block_sums<1> sums(world, make_global_block_plan(s.partition, world.rank(), block_sums<1>::block_size));
  const auto total = [&] { return sums([](index_t, global_block_sums<1>::sums& t) { t[0] += 1.0; })[0]; };
  const std::string expected = fmt::format("rank {} of {}: NaN in the stress at point 17", failing, P);

  world.guarded([&] {
    if (world.rank() == failing) fail("NaN in the stress at point 17");
  });
  CHECK(world.failed() == (world.rank() == failing));
  CHECK(contains(agreed_failure([&] { exchange.forward(s.d); }), expected));
  CHECK_FALSE(world.failed());
  CHECK_NOTHROW(exchange.forward(s.d));  // agreed and cleared: the ranks go on together

  world.guarded([&] {
    if (world.rank() == failing) fail("NaN in the stress at point 17");
  });
  CHECK(contains(agreed_failure(total), expected));
  CHECK(total() == static_cast<double>(s.g.size()));

  world.guarded([&] {
    if (world.rank() == failing) throw std::runtime_error("NaN in the stress at point 17");  // any std::exception
  });
  CHECK(contains(agreed_failure([&] { world.max(1.0); }), expected));
  CHECK(world.max(static_cast<double>(world.rank())) == P - 1);
}

TEST_CASE("several failing ranks: the lowest one's message, and how many failed") {
  communicator world;
  const int P = world.size();
  world.guarded([&] {
    if (world.rank() > 0 || P == 1) fail("inverted point on rank {}", world.rank());
  });
  world.guarded([&] {
    if (world.failed()) fail("a second error on rank {}: only the first is kept", world.rank());
  });
  const std::string message = agreed_failure([&] { world.min(0.0); });
  if (P == 1) CHECK(contains(message, "rank 0 of 1: inverted point on rank 0"));
  if (P == 2) CHECK(contains(message, "rank 1 of 2: inverted point on rank 1"));
  if (P == 3) CHECK(contains(message, "rank 1 (and 1 more of 3 ranks): inverted point on rank 1"));
  CHECK_FALSE(contains(message, "second"));
}

TEST_CASE("a field of the wrong length, or a plan of another rank, on one rank: an error on every rank") {
  communicator world;
  const int P = world.size(), failing = P > 1 ? 1 : 0;
  exchange_setup s(P, world.rank());
  halo_exchange exchange(world, s.plan);
  std::vector<double> temperature(s.plan.local_particles() - (world.rank() == failing ? 1 : 0), 293.0);
  const std::string message = agreed_failure([&] { exchange.forward(s.d, temperature); });
  CHECK(contains(message, fmt::format("rank {} of {}: forward: a field has", failing, P)));
  CHECK(contains(message, "local particles (owned and ghosts)"));
  // Rank `failing` is handed rank 0's plan (on one process: a plan for two).
  const particle_partition other = P > 1 ? s.partition : partition_particles(s.g.table, s.g.size(), 2);
  const halo_plan wrong = world.rank() == failing ? make_halo_plan(other, s.g.table, P > 1 ? 0 : 1) : s.plan;
  CHECK(contains(agreed_failure([&] { halo_exchange(world, wrong); }), "halo exchange: the plan is rank"));
  CHECK_NOTHROW(exchange.forward(s.d));
}

}  // namespace test_mpi_rank_failure
