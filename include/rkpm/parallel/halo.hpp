#pragma once
// halo_plan: what one process computes and exchanges, from the partition of the particles and
// the shape table at the quadrature points (docs/method.md section 9.8). Pure C++: no MPI call,
// so every rank's plan can be built and checked on one process.
//   owned     the rank's particles (global ids, increasing): local ids 0 .. owned-1
//   points    every point whose support holds an owned particle (global ids, increasing).
//             A point whose support straddles two ranks is computed by both (a redundant
//             ghost point), so each owned particle's force is summed over all of its points
//             here, in the global point order, as on one process: the same bits, and no force
//             is sent back
//   ghosts    the other ranks' particles in those points' supports (global ids, increasing):
//             local ids owned .. owned+ghosts-1
//   sends     for each rank that holds some of ours as ghosts (rank order): the local ids of
//             those owned particles, in increasing global id
//   receives  for each rank that owns some of our ghosts (rank order): the local ids of those
//             ghosts, in increasing global id
// Rank a's send list to b and b's receive list from a name the same particles in the same
// order; `forward` (parallel/mpi_exchange.hpp) copies owned values to ghosts along them.

#include <algorithm>
#include <span>
#include <utility>
#include <vector>

#include <rkpm/core/error.hpp>
#include <rkpm/core/execution.hpp>
#include <rkpm/discretization/search_rows.hpp>
#include <rkpm/discretization/shape_table.hpp>
#include <rkpm/parallel/partition.hpp>

namespace rkpm::parallel {

// The particles exchanged with one other rank, as local ids.
struct halo_link {
  int rank = 0;
  std::vector<stored_index> particles;
};

struct halo_plan {
  int rank = 0, ranks = 1;
  index_t global_particles = 0, global_points = 0;
  std::vector<stored_index> owned;
  std::vector<stored_index> ghosts;
  std::vector<stored_index> points;
  std::vector<halo_link> sends;
  std::vector<halo_link> receives;

  index_t local_particles() const { return static_cast<index_t>(owned.size() + ghosts.size()); }
  // The global id of local particle i.
  stored_index global_particle(index_t i) const {
    const auto n = static_cast<index_t>(owned.size());
    return i < n ? owned[i] : ghosts[i - n];
  }
  // The ranges of the execution layer (core/execution.hpp): owned first, then the ghosts; the
  // rank's points are all its own (redundant ones included).
  ownership own() const {
    const auto n = static_cast<index_t>(owned.size());
    return {{0, n}, {n, local_particles()}, {0, static_cast<index_t>(points.size())}};
  }
};

// The end of every plan (make_halo_plan, parallel/snapshot_pieces.hpp): the particles marked
// in is_ghost become the ghosts (local ids after the owned ones, in increasing global id), the
// receives group them by owner, and the sends list, rank by rank, the owned particles of the
// (rank, global id) pairs in to_send. `local`: global id -> local id, the owned ones filled in.
inline void link_ghosts(halo_plan& h, const std::vector<stored_index>& part, const std::vector<char>& is_ghost,
                        std::vector<std::pair<stored_index, stored_index>>& to_send, std::vector<stored_index>& local) {
  for (index_t I = 0; I < static_cast<index_t>(is_ghost.size()); ++I)
    if (is_ghost[I]) {
      local[I] = static_cast<stored_index>(h.owned.size() + h.ghosts.size());
      h.ghosts.push_back(static_cast<stored_index>(I));
    }
  // Receives: the ghosts grouped by owner, each group in increasing global id.
  std::vector<std::vector<stored_index>> from(h.ranks);
  for (const stored_index I : h.ghosts) from[part[I]].push_back(local[I]);
  for (int b = 0; b < h.ranks; ++b)
    if (!from[b].empty()) h.receives.push_back({b, std::move(from[b])});
  // Sends: (rank, particle) pairs in rank order, then global id.
  std::ranges::sort(to_send);
  to_send.erase(std::ranges::unique(to_send).begin(), to_send.end());
  for (const auto& [b, I] : to_send) {
    if (h.sends.empty() || h.sends.back().rank != b) h.sends.push_back({b, {}});
    h.sends.back().particles.push_back(local[I]);
  }
}

// The plan of `rank` for `partition` (as many parts as ranks) and the table at the points
// (rows: points, columns: the partition's particles). Every rank builds its own from the same
// global table and partition; nothing is communicated. For the whole step two more sets of
// particles are held (parallel/local_model.hpp):
//   at_particles  the table at the particles (rows: particles): each owned particle's row, so
//                 that its physical values are computed by its owner
//   shared        particles every rank holds (sorted global ids): the constrained and contact
//                 slave particles with their rows' columns, whose corrections every rank
//                 computes alike (the replicated region of docs/method.md section 9.8)
// `table` is read row by row, once, for its columns: a shape table, or the rows a neighbour
// search finds (search_rows, discretization/search_rows.hpp) where no table of the whole exists.
template <ColumnRows Rows>
halo_plan make_halo_plan(const particle_partition& partition, const Rows& table, int rank,
                         const shape_table<2>* at_particles = nullptr, std::span<const stored_index> shared = {}) {
  const index_t n = partition.particles(), np = table.points();
  if (rank < 0 || rank >= partition.parts)
    fail("halo plan: rank {} of a partition into {} parts; run on as many processes as parts", rank,
         partition.parts);
  const std::vector<stored_index>& part = partition.part;
  halo_plan h;
  h.rank = rank;
  h.ranks = static_cast<int>(partition.parts);
  h.global_particles = n;
  h.global_points = np;
  std::vector<stored_index> local(n, -1);
  for (index_t I = 0; I < n; ++I)
    if (part[I] == rank) {
      local[I] = static_cast<stored_index>(h.owned.size());
      h.owned.push_back(static_cast<stored_index>(I));
    }
  // The points that touch an owned particle, and at each of them the ranks it touches: a rank
  // b that computes point q needs all of q's particles, so ours in q go to every such b.
  std::vector<std::pair<stored_index, stored_index>> to_send;  // (rank, global particle)
  std::vector<char> is_ghost(n, 0);
  std::vector<stored_index> ranks_here;
  for (index_t q = 0; q < np; ++q) {
    const std::span<const particle_index> row = table.columns(q);
    for (const particle_index I : row)
      if (I < 0 || I >= n)
        fail("halo plan: the shape table names particle {} but the partition has {} particles; build the table "
             "and the partition from the same particles",
             I, n);
    if (std::ranges::none_of(row, [&](particle_index I) { return part[I] == rank; })) continue;
    h.points.push_back(static_cast<stored_index>(q));
    ranks_here.clear();
    for (const particle_index I : row)
      if (part[I] != rank) {
        is_ghost[I] = 1;
        ranks_here.push_back(part[I]);
      }
    if (ranks_here.empty()) continue;
    std::ranges::sort(ranks_here);
    ranks_here.erase(std::ranges::unique(ranks_here).begin(), ranks_here.end());
    for (const particle_index I : row)
      if (part[I] == rank)
        for (const stored_index b : ranks_here) to_send.emplace_back(b, static_cast<stored_index>(I));
  }
  // An owned particle's row at the particles: its columns held here, ours sent to the row's owner.
  if (at_particles) {
    if (at_particles->points() != n)
      fail("halo plan: the table at the particles has {} rows but the partition has {} particles; build both from "
           "the same particles",
           at_particles->points(), n);
    for (index_t I = 0; I < n; ++I)
      for (index_t e = at_particles->offset[I]; e < at_particles->offset[I + 1]; ++e) {
        const index_t J = at_particles->neighbor[e];
        if (part[I] == rank && part[J] != rank) is_ghost[J] = 1;
        if (part[I] != rank && part[J] == rank) to_send.emplace_back(part[I], static_cast<stored_index>(J));
      }
  }
  // The shared particles: every rank holds them; their owner sends them to all the others.
  for (const stored_index I : shared) {
    if (I < 0 || I >= n) fail("halo plan: shared particle {} outside 0..{}", I, n - 1);
    if (part[I] != rank) is_ghost[I] = 1;
    else
      for (int b = 0; b < h.ranks; ++b)
        if (b != rank) to_send.emplace_back(b, I);
  }
  link_ghosts(h, part, is_ghost, to_send, local);
  return h;
}

// The rows of the plan's points, in its order, with the columns renamed to local particle ids:
// the table the rank's force loop reads. Each row keeps its entries in the global table's order,
// so a point's gather adds the same terms in the same order as on one process.
template <int Dim>
shape_table<Dim> local_shape_table(const halo_plan& plan, const shape_table<Dim>& table) {
  if (table.points() != plan.global_points)
    fail("local shape table: the plan was made for {} points but the table has {}; make the plan from this table",
         plan.global_points, table.points());
  std::vector<stored_index> local(plan.global_particles, -1);
  for (index_t i = 0; i < plan.local_particles(); ++i) local[plan.global_particle(i)] = static_cast<stored_index>(i);
  shape_table<Dim> t;
  t.offset.assign(plan.points.size() + 1, 0);
  for (std::size_t k = 0; k < plan.points.size(); ++k) {
    const index_t q = plan.points[k];
    t.offset[k + 1] = t.offset[k] + (table.offset[q + 1] - table.offset[q]);
  }
  t.neighbor.resize(t.offset.back());
  t.N.resize(t.offset.back());
  if (!table.grad.empty()) t.grad.resize(t.offset.back());
  for (std::size_t k = 0; k < plan.points.size(); ++k) {
    const index_t q = plan.points[k];
    for (index_t e = table.offset[q], to = t.offset[k]; e < table.offset[q + 1]; ++e, ++to) {
      const stored_index I = local[table.neighbor[e]];
      if (I < 0)
        fail("local shape table: point {} needs particle {}, which rank {} neither owns nor holds as a ghost; "
             "make the plan from this table",
             q, table.neighbor[e], plan.rank);
      t.neighbor[to] = I;
      t.N[to] = table.N[e];
      if (!table.grad.empty()) t.grad[to] = table.grad[e];
    }
  }
  return t;
}

}  // namespace rkpm::parallel
