#pragma once
// The particles cut into P parts, one per process (docs/method.md section 9.8), by METIS on
// the particle graph of the reference configuration, or as the caller gives them.
//   make_particle_graph(table, particles)   two particles are linked when some quadrature
//                                           point's support holds both
//   partition_particles(graph, P)           METIS, fixed options: the same parts every time
//   given_partition(part, P)                the caller's parts, checked (tests force a cut
//                                           through a body, a contact or the axis with it)
//   part_loads(table, partition)            each part's work as the partition weighs it, and
//   load_imbalance(table, partition)        the largest over the mean
// The kernel is Lagrangian, so the graph never changes: a run partitions once, at set-up, and
// again only after a re-reference has changed the table past a bound (rebalance_above,
// parallel/distributed_rereference.hpp).
// Needs METIS (Debian libmetis-dev; the opt-in target rkpm::mpi links it).

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <vector>

#include <metis.h>

#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/discretization/shape_table.hpp>

namespace rkpm::parallel {

// The particle graph in METIS's compressed rows (particle I's neighbours are
// adjncy[xadj[I] .. xadj[I+1]-1], in increasing order, I itself left out).
//   vertex_weight  #particles: the (point, neighbour) entries the particle takes part in,
//                  its share of the force loop's work
//   edge_weight    #links: the points whose support holds both particles, the points that
//                  a cut between them makes two processes compute
struct particle_graph {
  std::vector<idx_t> xadj{0};
  std::vector<idx_t> adjncy;
  std::vector<idx_t> vertex_weight;
  std::vector<idx_t> edge_weight;

  index_t vertices() const { return static_cast<index_t>(xadj.size()) - 1; }
};

// The graph of `table` (rows: points, columns: `particles` particles). Each particle's links
// are counted through the points that hold it (the table transposed), so the cost is the sum
// over the points of their support size squared, once at set-up.
template <int Dim>
particle_graph make_particle_graph(const shape_table<Dim>& table, index_t particles) {
  const index_t np = table.points();
  // The transposed table: the points of each particle.
  std::vector<index_t> first(particles + 1, 0);
  for (const particle_index I : table.neighbor) {
    if (I < 0 || I >= particles)
      fail("particle graph: the shape table names particle {} but there are {} particles; build the table "
           "and the graph from the same particle set",
           I, particles);
    ++first[I + 1];
  }
  for (index_t I = 0; I < particles; ++I) first[I + 1] += first[I];
  std::vector<index_t> point_of(first[particles]);
  {
    std::vector<index_t> next(first.begin(), first.end() - 1);
    for (index_t q = 0; q < np; ++q)
      for (index_t e = table.offset[q]; e < table.offset[q + 1]; ++e) point_of[next[table.neighbor[e]]++] = q;
  }
  particle_graph g;
  g.xadj.assign(particles + 1, 0);
  g.vertex_weight.resize(particles);
  std::vector<idx_t> shared(particles, 0);  // points shared with the particle at hand
  std::vector<index_t> linked;
  for (index_t I = 0; I < particles; ++I) {
    g.vertex_weight[I] = static_cast<idx_t>(first[I + 1] - first[I]);
    linked.clear();
    for (index_t k = first[I]; k < first[I + 1]; ++k) {
      const index_t q = point_of[k];
      for (index_t e = table.offset[q]; e < table.offset[q + 1]; ++e) {
        const index_t J = table.neighbor[e];
        if (J == I) continue;
        if (shared[J]++ == 0) linked.push_back(J);
      }
    }
    std::ranges::sort(linked);
    if (static_cast<index_t>(g.adjncy.size()) + static_cast<index_t>(linked.size()) > std::numeric_limits<idx_t>::max())
      fail("particle graph: more than {} links, past METIS's 32-bit indices; partition fewer particles per "
           "graph (a parallel partitioner such as ParMETIS is the way past this size)",
           std::numeric_limits<idx_t>::max());
    for (const index_t J : linked) {
      g.adjncy.push_back(static_cast<idx_t>(J));
      g.edge_weight.push_back(shared[J]);
      shared[J] = 0;
    }
    g.xadj[I + 1] = static_cast<idx_t>(g.adjncy.size());
  }
  return g;
}

// Which part (process) owns each particle.
//   part  #particles part of each particle, 0 .. parts-1
struct particle_partition {
  index_t parts = 1;
  std::vector<stored_index> part;

  index_t particles() const { return static_cast<index_t>(part.size()); }
  // #parts: how many particles each part owns.
  std::vector<index_t> sizes() const {
    std::vector<index_t> n(parts, 0);
    for (const stored_index p : part) ++n[p];
    return n;
  }
};

// The caller's partition: part[I] in 0 .. parts-1 for every particle, each part owning at least
// one particle (a process with nothing to compute is refused, not silently idle).
inline particle_partition given_partition(std::vector<stored_index> part, index_t parts) {
  if (parts < 1) fail("partition into {} parts: give at least one part (one per process)", parts);
  if (static_cast<index_t>(part.size()) < parts)
    fail("partition of {} particles into {} parts: run on at most {} processes", part.size(), parts, part.size());
  particle_partition p{parts, std::move(part)};
  for (index_t I = 0; I < p.particles(); ++I)
    if (p.part[I] < 0 || p.part[I] >= parts)
      fail("partition: particle {} is given part {}, outside 0 .. {}; give each particle a part below the "
           "number of processes",
           I, p.part[I], parts - 1);
  const std::vector<index_t> n = p.sizes();
  for (index_t k = 0; k < parts; ++k)
    if (n[k] == 0)
      fail("partition: part {} of {} owns no particle; give every process at least one particle or run on fewer",
           k, parts);
  return p;
}

// METIS's partition of `graph` into `parts` parts balanced by vertex weight, with the cut's
// edge weight (redundant points) minimized. Options are fixed (seed, numbering, default
// imbalance), so the same graph gives the same parts every time and on every process.
// Recursive bisection below 8 parts, where METIS's manual finds it the better of its two;
// k-way from 8 on.
inline particle_partition partition_particles(const particle_graph& graph, index_t parts) {
  const index_t n = graph.vertices();
  if (parts < 1) fail("partition into {} parts: give at least one part (one per process)", parts);
  if (parts > n) fail("partition of {} particles into {} parts: run on at most {} processes", n, parts, n);
  if (parts == 1) return {1, std::vector<stored_index>(n, 0)};
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = 1;
  options[METIS_OPTION_NUMBERING] = 0;
  idx_t nvtxs = static_cast<idx_t>(n), ncon = 1, nparts = static_cast<idx_t>(parts), objval = 0;
  // METIS takes non-const pointers but does not write the graph.
  auto& g = const_cast<particle_graph&>(graph);
  std::vector<idx_t> part(n);
  const int status = parts < 8 ? METIS_PartGraphRecursive(&nvtxs, &ncon, g.xadj.data(), g.adjncy.data(),
                                                          g.vertex_weight.data(), nullptr, g.edge_weight.data(),
                                                          &nparts, nullptr, nullptr, options, &objval, part.data())
                               : METIS_PartGraphKway(&nvtxs, &ncon, g.xadj.data(), g.adjncy.data(),
                                                     g.vertex_weight.data(), nullptr, g.edge_weight.data(), &nparts,
                                                     nullptr, nullptr, options, &objval, part.data());
  if (status != METIS_OK)
    fail("METIS could not partition {} particles into {} parts (status {}: {}); try fewer processes", n, parts,
         status,
         status == METIS_ERROR_INPUT ? "bad input" : status == METIS_ERROR_MEMORY ? "out of memory" : "error");
  std::vector<stored_index> stored(part.begin(), part.end());
  const std::vector<index_t> sizes = particle_partition{parts, stored}.sizes();
  for (index_t k = 0; k < parts; ++k)
    if (sizes[k] == 0)
      fail("METIS left part {} of {} empty ({} particles): run on fewer processes", k, parts, n);
  return {parts, std::move(stored)};
}

// Each part's load as partition_particles weighs it (the graph's vertex weights): the entries
// of `table` (rows: points) at the particles the part owns, its share of the force loop.
//   returns  #parts
template <int Dim>
std::vector<std::int64_t> part_loads(const shape_table<Dim>& table, const particle_partition& p) {
  std::vector<std::int64_t> load(p.parts, 0);
  for (const particle_index I : table.neighbor) {
    if (I < 0 || I >= p.particles())
      fail("part loads: the shape table names particle {} but the partition has {} particles; measure the "
           "partition of this table's particles",
           I, p.particles());
    ++load[p.part[I]];
  }
  return load;
}

// The largest part's load over the mean (1: balanced; 1 for a table without entries).
template <int Dim>
double load_imbalance(const shape_table<Dim>& table, const particle_partition& p) {
  const std::vector<std::int64_t> load = part_loads(table, p);
  const double mean = static_cast<double>(std::accumulate(load.begin(), load.end(), std::int64_t{0})) /
                      static_cast<double>(p.parts);
  return mean > 0.0 ? static_cast<double>(*std::ranges::max_element(load)) / mean : 1.0;
}

// The METIS partition of the particles of `table`.
template <int Dim>
particle_partition partition_particles(const shape_table<Dim>& table, index_t particles, index_t parts) {
  return partition_particles(make_particle_graph(table, particles), parts);
}

}  // namespace rkpm::parallel
