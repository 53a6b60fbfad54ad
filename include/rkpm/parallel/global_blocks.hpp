#pragma once
// global_block_plan: how P processes add per-particle terms to the totals that one process's
// block_sums (core/block_sums.hpp) gives, bit for bit (docs/method.md section 9.8), and the same
// for per-point terms over point_owners (below), whose blocks are the traversal's tiles. One process
// cuts the global index range into blocks of block_sums<K>::block_size, sums each block in index
// order from zero and adds the blocks' sums in block order. A partition does not respect the
// blocks (a block of 2048 consecutive particles usually straddles a cut), and a block's sum
// rounds differently if its parts are added on different processes, so:
//   collector   #blocks: the rank that sums block b, the one owning most of its particles
//               (ties: the lowest rank); it receives the terms of the block's other particles
//   sends       for each collecting rank (rank order): our owned particles (local ids,
//               increasing global id) in the blocks it collects
//   collected   the blocks this rank collects (increasing)
//   member_term for each collected block, its particles in index order as slots of the term
//               array [owned particles' terms | terms received from each contributor, in rank
//               order]: member_offset[k] .. member_offset[k+1]-1 are block collected[k]'s
//   receives    for each contributing rank (rank order): how many terms it sends
//   whole       the blocks all of whose particles this rank owns (a subset of collected): the
//               first owned item of each and its length, and for each collected block its
//               position in `whole` (-1 if it is not whole). A whole block's items are
//               consecutive owned items, so its sum can be taken where its terms are made
//               (block_sums with a process group), and no term of it is stored.
// Every rank then has the blocks' sums (an all-gather of blocks x K values) and adds them in
// block order. Pure C++: no MPI call. What moves per sum is K values per owned particle in a
// block collected elsewhere (the particles of straddling blocks), plus the blocks' sums.

#include <algorithm>
#include <vector>

#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/parallel/halo.hpp>
#include <rkpm/parallel/partition.hpp>

namespace rkpm::parallel {

// The number of terms received from one rank.
struct term_count {
  int rank = 0;
  index_t count = 0;
};

struct global_block_plan {
  int rank = 0, ranks = 1;
  index_t global_count = 0, block_size = 1, owned = 0;
  std::vector<int> collector;
  std::vector<halo_link> sends;
  std::vector<term_count> receives;
  std::vector<stored_index> collected;
  std::vector<index_t> member_offset{0};
  std::vector<index_t> member_term;
  std::vector<index_t> whole_first, whole_size, whole_of_collected;
  std::vector<stored_index> partial;  // owned items in blocks that are not whole, increasing

  index_t blocks() const { return static_cast<index_t>(collector.size()); }
};

// The plan of `rank` for the particles of `partition` (owned particles numbered in increasing
// global id, as in halo_plan) and blocks of `block_size` consecutive global ids.
inline global_block_plan make_global_block_plan(const particle_partition& partition, int rank, index_t block_size) {
  if (rank < 0 || rank >= partition.parts)
    fail("global block plan: rank {} of a partition into {} parts; run on as many processes as parts", rank,
         partition.parts);
  if (block_size < 1) fail("global block plan: block size {} must be at least 1", block_size);
  const std::vector<stored_index>& part = partition.part;
  global_block_plan g;
  g.rank = rank;
  g.ranks = static_cast<int>(partition.parts);
  g.global_count = partition.particles();
  g.block_size = block_size;
  const index_t n = g.global_count, blocks = (n + block_size - 1) / block_size;
  std::vector<index_t> local(n, -1);
  for (index_t I = 0; I < n; ++I)
    if (part[I] == rank) local[I] = g.owned++;
  // The collector of each block: the rank owning most of it.
  g.collector.resize(blocks);
  std::vector<index_t> count(g.ranks, 0);
  for (index_t b = 0; b < blocks; ++b) {
    std::ranges::fill(count, 0);
    const index_t last = std::min(n, (b + 1) * block_size);
    for (index_t I = b * block_size; I < last; ++I) ++count[part[I]];
    g.collector[b] = static_cast<int>(std::ranges::max_element(count) - count.begin());
  }
  // What we send: our particles in blocks others collect, by collector, in global order.
  std::vector<std::vector<stored_index>> to(g.ranks);
  // What we receive: per contributor, its terms' positions among the received ones.
  std::vector<index_t> received(g.ranks, 0);
  for (index_t b = 0; b < blocks; ++b) {
    const index_t last = std::min(n, (b + 1) * block_size);
    if (g.collector[b] != rank) {
      for (index_t I = b * block_size; I < last; ++I)
        if (part[I] == rank) to[g.collector[b]].push_back(static_cast<stored_index>(local[I]));
      continue;
    }
    g.collected.push_back(static_cast<stored_index>(b));
    bool whole = true;
    for (index_t I = b * block_size; I < last; ++I)
      if (part[I] != rank) {
        ++received[part[I]];
        whole = false;
      }
    g.whole_of_collected.push_back(whole ? static_cast<index_t>(g.whole_first.size()) : -1);
    if (whole) {
      g.whole_first.push_back(local[b * block_size]);
      g.whole_size.push_back(last - b * block_size);
    }
  }
  for (index_t b = 0; b < blocks; ++b) {
    const bool whole = g.collector[b] == rank && g.whole_of_collected[static_cast<std::size_t>(
                                                     std::ranges::lower_bound(g.collected, b) - g.collected.begin())] >= 0;
    if (whole) continue;
    const index_t last = std::min(n, (b + 1) * block_size);
    for (index_t I = b * block_size; I < last; ++I)
      if (part[I] == rank) g.partial.push_back(static_cast<stored_index>(local[I]));
  }
  for (int r = 0; r < g.ranks; ++r) {
    if (!to[r].empty()) g.sends.push_back({r, std::move(to[r])});
    if (received[r] > 0) g.receives.push_back({r, received[r]});
  }
  // Slots of the term array: owned terms first, then each contributor's in rank order.
  std::vector<index_t> next(g.ranks, 0);
  index_t base = g.owned;
  for (const term_count& c : g.receives) {
    next[c.rank] = base;
    base += c.count;
  }
  for (const stored_index b : g.collected) {
    const index_t last = std::min(n, (b + 1) * block_size);
    for (index_t I = b * block_size; I < last; ++I)
      g.member_term.push_back(part[I] == rank ? local[I] : next[part[I]]++);
    g.member_offset.push_back(static_cast<index_t>(g.member_term.size()));
  }
  return g;
}

// The owner of each point for sums over the points (the plastic work): the owner of the first
// particle of its row, which computes it (the point touches that particle). Every point has
// one owner, as every particle does, so per-point terms can be summed in one process's order by
// a global block plan (make_global_block_plan, above) made from this partition of the points.
template <ColumnRows Rows>
particle_partition point_owners(const particle_partition& particles, const Rows& table) {
  particle_partition points;
  points.parts = particles.parts;
  points.part.resize(table.points());
  for (index_t q = 0; q < table.points(); ++q) {
    const std::span<const particle_index> row = table.columns(q);
    if (row.empty())
      fail("point owners: point {} has no particle in its support; build the table from particles that cover the "
           "points",
           q);
    points.part[q] = particles.part[row.front()];
  }
  return points;
}

// The plan's points that this rank owns (point_owners), as positions in plan.points, in
// increasing global id: the owned items of a global block plan made from point_owners.
inline std::vector<stored_index> owned_point_positions(const halo_plan& plan, const particle_partition& point_owner) {
  if (point_owner.particles() != plan.global_points)
    fail("owned points: the point owners cover {} points but the plan was made for {}; make both from one table",
         point_owner.particles(), plan.global_points);
  std::vector<stored_index> out;
  for (std::size_t k = 0; k < plan.points.size(); ++k)
    if (point_owner.part[plan.points[k]] == plan.rank) out.push_back(static_cast<stored_index>(k));
  return out;
}

}  // namespace rkpm::parallel
