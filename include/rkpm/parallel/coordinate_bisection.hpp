#pragma once
// Recursive coordinate bisection (docs/method.md section 9.8): the particles cut into P parts by
// straight cuts through their reference positions, without the particle graph. Each set of
// particles is split across its bounding box's longer side, where the weight on each side is in
// proportion to the parts it gets (floor(P/2) and the rest), and each side split again until
// every part is one process's. It reads 24 bytes per particle (a position and a weight), where
// METIS (parallel/partition.hpp) needs the whole graph, a few hundred bytes per particle: the
// partition a set-up can make before any shape table exists. The cuts are straight, so METIS
// cuts fewer links on the same particles (partition_cost below; the figures are in
// docs/performance.md).
//   bisect_coordinates(x, P)           unit weights
//   bisect_coordinates(x, w, P)        weights w (e.g. each particle's share of the points)
//   partition_cost(table, partition)   links cut, points computed twice, ghosts, balance
// Deterministic: ties in a coordinate are broken by the particle's index, so every process that
// bisects the same positions gets the same parts.

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <span>
#include <utility>
#include <vector>

#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/discretization/shape_table.hpp>
#include <rkpm/parallel/partition.hpp>

namespace rkpm::parallel {

namespace detail {

// Splits the particles ids[begin, end) into parts first .. first+parts-1 (recursively).
inline void bisect(std::span<const vec2> x, std::span<const double> weight, std::vector<index_t>& ids, index_t begin,
                   index_t end, index_t first, index_t parts, std::vector<stored_index>& part) {
  if (parts == 1) {
    for (index_t k = begin; k < end; ++k) part[ids[k]] = static_cast<stored_index>(first);
    return;
  }
  vec2 lo = x[ids[begin]], hi = lo;
  for (index_t k = begin; k < end; ++k) {
    lo = lo.cwiseMin(x[ids[k]]);
    hi = hi.cwiseMax(x[ids[k]]);
  }
  const int axis = hi[1] - lo[1] > hi[0] - lo[0] ? 1 : 0;
  std::sort(ids.begin() + begin, ids.begin() + end, [&](index_t a, index_t b) {
    return x[a][axis] < x[b][axis] || (x[a][axis] == x[b][axis] && a < b);
  });
  // The first `left` parts get the share left/parts of the weight: cut after the particle whose
  // running weight comes nearest it, leaving each side at least one particle per part.
  const index_t left = parts / 2;
  double total = 0.0;
  for (index_t k = begin; k < end; ++k) total += weight[ids[k]];
  const double target = total * static_cast<double>(left) / static_cast<double>(parts);
  const index_t lowest = begin + left, highest = end - (parts - left);
  index_t cut = lowest;
  double running = 0.0;
  for (index_t k = begin; k < lowest; ++k) running += weight[ids[k]];
  while (cut < highest && running + 0.5 * weight[ids[cut]] < target) running += weight[ids[cut++]];
  bisect(x, weight, ids, begin, cut, first, left, part);
  bisect(x, weight, ids, cut, end, first + left, parts - left, part);
}

}  // namespace detail

inline particle_partition bisect_coordinates(std::span<const vec2> x, std::span<const double> weight, index_t parts) {
  const auto n = static_cast<index_t>(x.size());
  if (parts < 1) fail("coordinate bisection into {} parts: give at least one part (one per process)", parts);
  if (parts > n) fail("coordinate bisection of {} particles into {} parts: run on at most {} processes", n, parts, n);
  if (static_cast<index_t>(weight.size()) != n)
    fail("coordinate bisection: {} weights for {} particles; give one weight per particle", weight.size(), n);
  for (index_t I = 0; I < n; ++I)
    if (!(weight[I] >= 0.0) || !x[I].allFinite())
      fail("coordinate bisection: particle {} has weight {} at ({}, {}); give finite positions and non-negative "
           "weights",
           I, weight[I], x[I][0], x[I][1]);
  std::vector<index_t> ids(n);
  std::iota(ids.begin(), ids.end(), index_t{0});
  std::vector<stored_index> part(n, 0);
  detail::bisect(x, weight, ids, 0, n, 0, parts, part);
  return given_partition(std::move(part), parts);
}

inline particle_partition bisect_coordinates(std::span<const vec2> x, index_t parts) {
  const std::vector<double> unit(x.size(), 1.0);
  return bisect_coordinates(x, unit, parts);
}

// What a partition costs the run, from the table at the points (its rows' columns):
//   links_cut        particle pairs in different parts whose supports share points, each
//                    weighted by the points they share (METIS's edge cut, which it minimizes)
//   shared_points    the extra computations of points whose support spans several parts:
//                    sum over the points of (parts it touches - 1), the redundant work
//   max_ghosts       the most ghosts any part holds (the other parts' particles in its points)
//   imbalance        the largest part's work over the mean (load_imbalance, parallel/partition.hpp)
struct partition_costs {
  std::int64_t links_cut = 0;
  index_t shared_points = 0;
  index_t max_ghosts = 0;
  double imbalance = 1.0;
};

template <int Dim>
partition_costs partition_cost(const shape_table<Dim>& table, const particle_partition& p) {
  partition_costs c;
  const particle_graph graph = make_particle_graph(table, p.particles());
  for (index_t I = 0; I < graph.vertices(); ++I)
    for (idx_t k = graph.xadj[I]; k < graph.xadj[I + 1]; ++k)
      if (graph.adjncy[k] > I && p.part[graph.adjncy[k]] != p.part[I]) c.links_cut += graph.edge_weight[k];
  std::vector<std::pair<stored_index, particle_index>> ghost;  // (part, another part's particle in its points)
  std::vector<stored_index> touched;
  for (index_t q = 0; q < table.points(); ++q) {
    touched.clear();
    for (index_t e = table.offset[q]; e < table.offset[q + 1]; ++e) touched.push_back(p.part[table.neighbor[e]]);
    std::ranges::sort(touched);
    touched.erase(std::ranges::unique(touched).begin(), touched.end());
    if (touched.empty()) continue;
    c.shared_points += static_cast<index_t>(touched.size()) - 1;
    if (touched.size() > 1)
      for (const stored_index r : touched)
        for (index_t e = table.offset[q]; e < table.offset[q + 1]; ++e)
          if (p.part[table.neighbor[e]] != r) ghost.emplace_back(r, table.neighbor[e]);
  }
  std::ranges::sort(ghost);
  ghost.erase(std::ranges::unique(ghost).begin(), ghost.end());
  std::vector<index_t> ghosts(p.parts, 0);
  for (const auto& [r, I] : ghost) ++ghosts[r];
  c.max_ghosts = *std::ranges::max_element(ghosts);
  c.imbalance = load_imbalance(table, p);
  return c;
}

}  // namespace rkpm::parallel
