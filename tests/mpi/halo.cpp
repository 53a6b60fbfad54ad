// The halo plans (parallel/halo.hpp) and the global block plans (parallel/global_blocks.hpp) of
// every rank, built on one process for METIS partitions into 1 to 4 parts and for cuts forced
// along lines: the owned sets cover the particles once; a rank has every neighbour of every point
// it computes, and computes every point of every particle it owns (and no other point); the
// ghosts are exactly the other ranks' particles those points need; rank a's send list to b is
// b's receive list from a; the local table is the global one renamed; every block is collected
// by one rank, from every particle of it, in index order, and the blocks a rank owns whole and
// the rest of its items cover its items once. The halo sizes are printed (MESSAGE).

#include <doctest/doctest.h>

#include <algorithm>
#include <numeric>
#include <string>
#include <vector>

#include <rkpm/parallel/global_blocks.hpp>
#include <rkpm/parallel/halo.hpp>
#include <rkpm/parallel/partition.hpp>

#include "mpi/grid_problem.hpp"
#include "support/error_message.hpp"

namespace test_mpi_halo {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;
using namespace rkpm::parallel;

namespace {

std::vector<stored_index> global_ids(const halo_plan& h, const std::vector<stored_index>& local) {
  std::vector<stored_index> out;
  for (const stored_index i : local) out.push_back(h.global_particle(i));
  return out;
}

bool increasing(const std::vector<stored_index>& v) { return std::ranges::adjacent_find(v, std::greater_equal{}) == v.end(); }

// Every property of the plans of all ranks of `p` on the table of `g`.
void check_plans(const test::grid_problem& g, const particle_partition& p, const std::string& name) {
  CAPTURE(name);
  const index_t n = g.size(), np = g.table.points();
  std::vector<halo_plan> plans;
  for (int r = 0; r < p.parts; ++r) plans.push_back(make_halo_plan(p, g.table, r));
  std::vector<int> owners(n, 0);
  std::string sizes;
  index_t computed_total = 0;
  for (const halo_plan& h : plans) {
    CAPTURE(h.rank);
    REQUIRE(h.ranks == p.parts);
    CHECK(increasing(h.owned));
    CHECK(increasing(h.ghosts));
    CHECK(increasing(h.points));
    for (const stored_index I : h.owned) ++owners[I];
    std::vector<char> here(n, 0), owned(n, 0);
    for (const stored_index I : h.owned) here[I] = owned[I] = 1;
    for (const stored_index I : h.ghosts) {
      CHECK(p.part[I] != h.rank);
      here[I] = 1;
    }
    // Every computed point has all of its neighbours here and holds an owned particle; every
    // ghost is some computed point's neighbour.
    std::vector<char> computed(np, 0), needed(n, 0);
    index_t missing = 0, without_owned = 0;
    for (const stored_index q : h.points) {
      computed[q] = 1;
      bool holds_owned = false;
      for (index_t e = g.table.offset[q]; e < g.table.offset[q + 1]; ++e) {
        const index_t I = g.table.neighbor[e];
        missing += !here[I];
        needed[I] = 1;
        holds_owned = holds_owned || owned[I];
      }
      without_owned += !holds_owned;
    }
    CHECK(missing == 0);
    CHECK(without_owned == 0);
    for (const stored_index I : h.ghosts) CHECK(needed[I]);
    // Every point of an owned particle is computed here.
    index_t uncomputed = 0;
    for (index_t q = 0; q < np; ++q)
      for (index_t e = g.table.offset[q]; e < g.table.offset[q + 1]; ++e)
        uncomputed += owned[g.table.neighbor[e]] && !computed[q];
    CHECK(uncomputed == 0);
    // The ranges of the execution layer.
    const ownership own = h.own();
    CHECK(own.particles.size() == static_cast<index_t>(h.owned.size()));
    CHECK(own.ghost_particles.size() == static_cast<index_t>(h.ghosts.size()));
    CHECK_NOTHROW(own.validate(h.local_particles(), static_cast<index_t>(h.points.size())));
    // The local table: the global rows of the plan's points, columns renamed, entries in order.
    const shape_table<2> local = local_shape_table(h, g.table);
    REQUIRE(local.points() == static_cast<index_t>(h.points.size()));
    index_t renamed_wrong = 0;
    for (index_t k = 0; k < local.points(); ++k) {
      const index_t q = h.points[k];
      REQUIRE(local.offset[k + 1] - local.offset[k] == g.table.offset[q + 1] - g.table.offset[q]);
      for (index_t e = 0; e < local.offset[k + 1] - local.offset[k]; ++e) {
        const index_t le = local.offset[k] + e, ge = g.table.offset[q] + e;
        renamed_wrong += h.global_particle(local.neighbor[le]) != g.table.neighbor[ge] || local.N[le] != g.table.N[ge] ||
                         local.grad[le] != g.table.grad[ge];
      }
    }
    CHECK(renamed_wrong == 0);
    // Its points that another rank computes too (their support straddles a cut).
    index_t shared = 0;
    for (const stored_index q : h.points) {
      bool straddles = false;
      for (index_t e = g.table.offset[q]; e < g.table.offset[q + 1]; ++e) straddles = straddles || !owned[g.table.neighbor[e]];
      shared += straddles;
    }
    computed_total += static_cast<index_t>(h.points.size());
    sizes += fmt::format(" rank {}: {} owned + {} ghosts ({:.0f}% of owned), {} points, {} of them shared ({:.0f}%);",
                         h.rank, h.owned.size(), h.ghosts.size(), 100.0 * static_cast<double>(h.ghosts.size()) / static_cast<double>(h.owned.size()),
                         h.points.size(), shared, 100.0 * static_cast<double>(shared) / static_cast<double>(h.points.size()));
  }
  CHECK(std::ranges::all_of(owners, [](int c) { return c == 1; }));
  // Send and receive lists match pairwise, and a rank's ghosts are what it receives.
  for (const halo_plan& a : plans) {
    std::vector<stored_index> received;
    for (const halo_link& l : a.receives) {
      CHECK(l.rank != a.rank);
      CHECK(increasing(global_ids(a, l.particles)));
      for (const stored_index i : l.particles) {
        CHECK(i >= static_cast<stored_index>(a.owned.size()));
        CHECK(p.part[a.global_particle(i)] == l.rank);
        received.push_back(a.global_particle(i));
      }
      const halo_plan& b = plans[l.rank];
      const auto sent = std::ranges::find_if(b.sends, [&](const halo_link& s) { return s.rank == a.rank; });
      REQUIRE(sent != b.sends.end());
      CHECK(global_ids(b, sent->particles) == global_ids(a, l.particles));
    }
    std::ranges::sort(received);
    CHECK(received == a.ghosts);
    for (const halo_link& s : a.sends) {
      CHECK(std::ranges::all_of(s.particles, [&](stored_index i) { return i < static_cast<stored_index>(a.owned.size()); }));
      const halo_plan& b = plans[s.rank];
      CHECK(std::ranges::any_of(b.receives, [&](const halo_link& l) { return l.rank == a.rank; }));
    }
  }
  MESSAGE(name << ":" << sizes << fmt::format(" {} points computed for {} ({:.0f}% redundant work)", computed_total, np,
                                              100.0 * (static_cast<double>(computed_total) / static_cast<double>(np) - 1.0)));

  // The global block plans, with small blocks so that the grid has several and they straddle the cuts.
  for (const index_t block : {index_t{7}, index_t{2048}}) {
    CAPTURE(block);
    std::vector<global_block_plan> bp;
    for (int r = 0; r < p.parts; ++r) bp.push_back(make_global_block_plan(p, r, block));
    const index_t blocks = (n + block - 1) / block;
    std::vector<int> collected(blocks, 0);
    for (const global_block_plan& b : bp) {
      CAPTURE(b.rank);
      REQUIRE(b.blocks() == blocks);
      CHECK(b.collector == bp[0].collector);
      CHECK(b.owned == static_cast<index_t>(plans[b.rank].owned.size()));
      for (const stored_index k : b.collected) {
        ++collected[k];
        CHECK(b.collector[k] == b.rank);
      }
      // Each collected block's members, in index order, come from the right place.
      index_t wrong = 0;
      std::vector<index_t> from(p.parts, 0), base(p.parts, 0);
      index_t at = b.owned;
      for (const term_count& c : b.receives) {
        base[c.rank] = at;
        at += c.count;
        // What c sends to b is as long as what b expects from c.
        const auto sent = std::ranges::find_if(bp[c.rank].sends, [&](const halo_link& l) { return l.rank == b.rank; });
        REQUIRE(sent != bp[c.rank].sends.end());
        CHECK(static_cast<index_t>(sent->particles.size()) == c.count);
      }
      for (std::size_t k = 0; k < b.collected.size(); ++k) {
        const index_t first = b.collected[k] * block, last = std::min(n, first + block);
        REQUIRE(b.member_offset[k + 1] - b.member_offset[k] == last - first);
        for (index_t I = first; I < last; ++I) {
          const index_t slot = b.member_term[b.member_offset[k] + (I - first)];
          const int owner = p.part[I];
          if (owner == b.rank)
            wrong += plans[b.rank].owned[slot] != I;
          else
            wrong += slot != base[owner] + from[owner]++;
        }
      }
      CHECK(wrong == 0);
      // The whole blocks and the partial items cover the owned items once each; a whole block is
      // its particles, consecutive owned items from its first.
      std::vector<int> covered(static_cast<std::size_t>(b.owned), 0);
      for (std::size_t w = 0; w < b.whole_first.size(); ++w)
        for (index_t i = b.whole_first[w]; i < b.whole_first[w] + b.whole_size[w]; ++i) ++covered[i];
      for (const stored_index i : b.partial) ++covered[i];
      CHECK(std::ranges::all_of(covered, [](int c) { return c == 1; }));
      for (std::size_t k = 0; k < b.collected.size(); ++k)
        if (const index_t w = b.whole_of_collected[k]; w >= 0) {
          const index_t first = b.collected[k] * block, last = std::min(n, first + block);
          CHECK(b.whole_size[w] == last - first);
          for (index_t i = 0; i < b.whole_size[w]; ++i) wrong += plans[b.rank].owned[b.whole_first[w] + i] != first + i;
        }
      CHECK(wrong == 0);
    }
    CHECK(std::ranges::all_of(collected, [](int c) { return c == 1; }));
  }
}

}  // namespace

TEST_CASE("halo plans: METIS partitions into 1 to 4 parts and cuts forced along lines") {
  const test::grid_problem g;
  for (const index_t parts : {1, 2, 3, 4}) check_plans(g, partition_particles(g.table, g.size(), parts), fmt::format("METIS {}", parts));
  check_plans(g, g.stripes(2, 1.0, 0.0), "vertical cut");
  check_plans(g, g.stripes(3), "two slanted cuts");
  // Every other particle on another rank: every point straddles, the plans' worst case.
  std::vector<stored_index> alternate(g.size());
  for (index_t I = 0; I < g.size(); ++I) alternate[I] = static_cast<stored_index>(I % 3);
  check_plans(g, given_partition(alternate, 3), "interleaved");
}

TEST_CASE("halo plans: one part has no ghosts and computes every point; a bad rank is an error") {
  const test::grid_problem g;
  const halo_plan h = make_halo_plan(partition_particles(g.table, g.size(), 1), g.table, 0);
  CHECK(h.ghosts.empty());
  CHECK(h.sends.empty());
  CHECK(h.receives.empty());
  CHECK(static_cast<index_t>(h.points.size()) == g.table.points());
  CHECK(static_cast<index_t>(h.owned.size()) == g.size());
  const particle_partition two = partition_particles(g.table, g.size(), 2);
  CHECK(test::contains(test::error_message([&] { make_halo_plan(two, g.table, 2); }), "rank 2 of a partition into 2 parts"));
  CHECK(test::contains(test::error_message([&] { make_global_block_plan(two, -1, 2048); }), "rank -1"));
  CHECK(test::contains(test::error_message([&] { make_global_block_plan(two, 0, 0); }), "block size 0"));
  const test::grid_problem other(13, 8);
  CHECK(test::contains(test::error_message([&] { make_halo_plan(two, other.table, 0); }), "the same particles"));
}

}  // namespace test_mpi_halo
