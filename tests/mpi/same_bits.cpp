// The same bits on any number of processes (parallel/halo.hpp, parallel/mpi_exchange.hpp), run
// by ctest on 1, 2 and 3 processes. On the 12 x 8 grid of tests/mpi/grid_problem.hpp, the
// internal force of a smooth displacement,
//   f_I = sum_q w_q sigma(H_q) grad N_I(X_q),  H_q = sum_J d_J (x) grad N_J(X_q),
// sigma a linear elastic small-strain stress, is computed on one process over the points in
// global order, and on every rank over its plan's points (redundant ghost points included) from
// its owned displacements and the ghosts' that forward() brought; the owned forces gathered on
// rank 0 equal the serial ones bit for bit (memcmp), for METIS's partition and for cuts forced
// along a vertical and two slanted lines. The sums of per-particle terms (an energy) across the
// ranks equal one process's block_sums bit for bit, on the grid and on 10,363 terms of very
// different sizes whose particles are dealt to the ranks in a scattered way (every block
// straddles every rank).

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include <rkpm/core/block_sums.hpp>
#include <rkpm/parallel/communicator.hpp>
#include <rkpm/parallel/gather.hpp>
#include <rkpm/parallel/global_blocks.hpp>
#include <rkpm/parallel/halo.hpp>
#include <rkpm/parallel/mpi_block_sums.hpp>
#include <rkpm/parallel/mpi_exchange.hpp>
#include <rkpm/parallel/partition.hpp>

#include "mpi/grid_problem.hpp"

namespace test_mpi_same_bits {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;
using namespace rkpm::parallel;

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// The internal force of the displacement d over the rows of `table`, point after point in row
// order: the one loop that the serial and the distributed computations share.
std::vector<vec2> internal_force(const shape_table<2>& table, const std::vector<double>& weight,
                                 const std::vector<vec2>& d) {
  constexpr double lambda = 1.2e11, mu = 0.8e11;
  std::vector<vec2> f(d.size(), vec2::Zero());
  for (index_t q = 0; q < table.points(); ++q) {
    mat2 H = mat2::Zero();
    for (index_t e = table.offset[q]; e < table.offset[q + 1]; ++e) H.noalias() += d[table.neighbor[e]] * table.grad[e].transpose();
    const mat2 strain = 0.5 * (H + H.transpose());
    const mat2 S = weight[q] * (lambda * strain.trace() * mat2::Identity() + 2.0 * mu * strain);
    for (index_t e = table.offset[q]; e < table.offset[q + 1]; ++e) f[table.neighbor[e]].noalias() += S * table.grad[e];
  }
  return f;
}

bool same_bits(const vec2& a, const vec2& b) { return std::memcmp(a.data(), b.data(), sizeof(double) * 2) == 0; }
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

struct distributed_force {
  std::vector<vec2> gathered;  // on rank 0
  index_t ghosts_everywhere = 0, wrong_ghosts = 0;
};

// The force on the ranks of `world` for `partition`, from owned displacements and forwarded ghosts.
distributed_force force_on_ranks(communicator& world, const test::grid_problem& g, const particle_partition& partition) {
  const halo_plan plan = make_halo_plan(partition, g.table, world.rank());
  const shape_table<2> local = local_shape_table(plan, g.table);
  std::vector<double> weight(local.points());
  for (index_t k = 0; k < local.points(); ++k) weight[k] = g.points.weight[plan.points[k]];
  // Owners set their particles; ghosts start as NaN, so a ghost that forward() missed shows.
  std::vector<vec2> d(plan.local_particles(), vec2::Constant(nan));
  std::vector<double> tag(plan.local_particles(), nan);  // a second field in the same message
  for (std::size_t i = 0; i < plan.owned.size(); ++i) {
    d[i] = g.displacement(plan.owned[i]);
    tag[i] = 0.5 + plan.owned[i];
  }
  halo_exchange exchange(world, plan);
  exchange.forward(d, tag);
  distributed_force out;
  for (index_t i = plan.own().ghost_particles.begin; i < plan.local_particles(); ++i) {
    const stored_index I = plan.global_particle(i);
    out.wrong_ghosts += !same_bits(d[i], g.displacement(I)) || tag[i] != 0.5 + I;
  }
  out.ghosts_everywhere = static_cast<index_t>(plan.ghosts.size());
  MPI_Allreduce(MPI_IN_PLACE, &out.ghosts_everywhere, 1, MPI_INT64_T, MPI_SUM, world.get());
  out.gathered = rkpm::parallel::gather_owned(world, plan, internal_force(local, weight, d));
  return out;
}

}  // namespace

TEST_CASE("internal force on 1, 2 or 3 ranks: the one-process bits, with METIS's partition and forced cuts") {
  communicator world;
  const int P = world.size();
  const test::grid_problem g;
  std::vector<vec2> d(g.size());
  for (index_t I = 0; I < g.size(); ++I) d[I] = g.displacement(I);
  const std::vector<vec2> serial = internal_force(g.table, g.points.weight, d);
  REQUIRE(std::ranges::any_of(serial, [](const vec2& f) { return f.norm() > 0.0; }));
  // The order matters: the points in reverse order give other bits somewhere, so the comparison can fail.
  shape_table<2> reversed;
  std::vector<double> reversed_weight;
  for (index_t q = g.table.points() - 1; q >= 0; --q) {
    for (index_t e = g.table.offset[q]; e < g.table.offset[q + 1]; ++e) {
      reversed.neighbor.push_back(g.table.neighbor[e]);
      reversed.N.push_back(g.table.N[e]);
      reversed.grad.push_back(g.table.grad[e]);
    }
    reversed.offset.push_back(static_cast<stored_index>(reversed.neighbor.size()));
    reversed_weight.push_back(g.points.weight[q]);
  }
  const std::vector<vec2> backwards = internal_force(reversed, reversed_weight, d);
  index_t differ = 0;
  for (index_t I = 0; I < g.size(); ++I) differ += !same_bits(backwards[I], serial[I]);
  CHECK(differ > 0);

  struct named {
    std::string name;
    particle_partition partition;
  };
  const std::vector<named> partitions{{"METIS", partition_particles(g.table, g.size(), P)},
                                      {"vertical cuts", g.stripes(P, 1.0, 0.0)},
                                      {"slanted cuts", g.stripes(P, 1.0, 0.6)}};
  for (const named& p : partitions) {
    CAPTURE(p.name);
    CAPTURE(P);
    const distributed_force result = force_on_ranks(world, g, p.partition);
    CHECK(result.wrong_ghosts == 0);
    CHECK((P == 1) == (result.ghosts_everywhere == 0));  // a cut exists on more than one rank
    // Checked on rank 0 only; no REQUIRE, which would leave the other ranks waiting in the next exchange.
    if (world.rank() != 0) continue;
    index_t wrong = 0;
    for (index_t I = 0; I < g.size(); ++I) wrong += !same_bits(result.gathered[I], serial[I]);
    CHECK(wrong == 0);
  }
}

TEST_CASE("sums across ranks: one process's block_sums, bit for bit") {
  communicator world;
  const int P = world.size(), rank = world.rank();

  SUBCASE("an energy on the grid, METIS's partition") {
    const test::grid_problem g;
    std::vector<vec2> v(g.size());
    std::vector<double> mass(g.size());
    for (index_t I = 0; I < g.size(); ++I) {
      v[I] = 1e6 * g.displacement(I) + vec2(3.0, -1.0);
      mass[I] = 8930.0 * g.particles.volume[I];
    }
    const block_sums<2> serial(g.size());
    const auto one = serial([&](index_t I, block_sums<2>::sums& s) {
      s[0] += 0.5 * mass[I] * v[I].squaredNorm();
      s[1] += v[I].dot(g.displacement(I));
    });
    const particle_partition p = partition_particles(g.table, g.size(), P);
    const halo_plan plan = make_halo_plan(p, g.table, rank);
    global_block_sums<2> sums(world, make_global_block_plan(p, rank, block_sums<2>::block_size));
    const auto many = sums([&](index_t i, global_block_sums<2>::sums& t) {
      const stored_index I = plan.owned[i];
      t[0] += 0.5 * mass[I] * v[I].squaredNorm();
      t[1] += v[I].dot(g.displacement(I));
    });
    CHECK(same_bits(many[0], one[0]));
    CHECK(same_bits(many[1], one[1]));
  }

  SUBCASE("10,363 terms of many magnitudes, particles dealt to the ranks in a scattered way") {
    const index_t n = 5 * block_sums<2>::block_size + 123;
    std::vector<double> x(n), y(n);
    std::vector<stored_index> part(n);
    for (index_t I = 0; I < n; ++I) {
      const double s = static_cast<double>(I);
      x[I] = std::sin(0.37 * s) * std::exp(0.001 * s) * std::pow(10.0, static_cast<double>(I % 7) - 3.0);
      y[I] = 1.0 / (1.0 + s) - 0.3 * std::cos(s);
      // A scattered deal: consecutive particles on different ranks, and blocks owned unevenly.
      part[I] = static_cast<stored_index>(((I * 7919) % 104729 + I / 1500) % P);
    }
    const particle_partition p = given_partition(part, P);
    std::vector<stored_index> owned;
    for (index_t I = 0; I < n; ++I)
      if (part[I] == rank) owned.push_back(static_cast<stored_index>(I));
    const block_sums<2> serial(n);
    const auto one = serial([&](index_t I, block_sums<2>::sums& s) {
      s[0] += x[I];
      s[1] += x[I] * y[I];
    });
    global_block_sums<2> sums(world, make_global_block_plan(p, rank, block_sums<2>::block_size));
    CHECK(sums.plan().blocks() == 6);
    const auto many = sums([&](index_t i, global_block_sums<2>::sums& t) {
      t[0] += x[owned[i]];
      t[1] += x[owned[i]] * y[owned[i]];
    });
    CHECK(same_bits(many[0], one[0]));
    CHECK(same_bits(many[1], one[1]));
    // Twice: the buffers are reused.
    const auto again = sums([&](index_t i, global_block_sums<2>::sums& t) {
      t[0] += x[owned[i]];
      t[1] += x[owned[i]] * y[owned[i]];
    });
    CHECK(same_bits(again[0], one[0]));
    // Each rank's own sum added over the ranks: what a plain MPI_Allreduce would give, for comparison.
    double plain = 0.0;
    for (const stored_index I : owned) plain += x[I];
    MPI_Allreduce(MPI_IN_PLACE, &plain, 1, MPI_DOUBLE, MPI_SUM, world.get());
    MESSAGE("ranks " << P << ": block sums " << fmt::format("{:.17g}", many[0]) << ", plain all-reduce of per-rank sums "
                     << fmt::format("{:.17g}", plain) << std::string(same_bits(plain, one[0]) ? " (same bits)" : " (other bits)"));
    // Order-free extremes.
    double largest = -1e300;
    for (const stored_index I : owned) largest = std::max(largest, x[I]);
    CHECK(same_bits(world.max(largest), *std::ranges::max_element(x)));
    double smallest = 1e300;
    for (const stored_index I : owned) smallest = std::min(smallest, y[I]);
    CHECK(same_bits(world.min(smallest), *std::ranges::min_element(y)));
  }
}

}  // namespace test_mpi_same_bits
