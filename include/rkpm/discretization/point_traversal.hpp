#pragma once
// point_traversal: the order in which the force loop (solver/point_forces.hpp) visits the
// quadrature points so that it can gather, update and scatter in one pass, in parallel,
// without atomics and with sums that do not depend on the thread count.
//   tile_start  #tiles+1: tile t is the points tile_start[t] .. tile_start[t+1]-1 (made with
//               a fixed size, the last one shorter, whatever the thread count; a rank's
//               traversal, parallel/halo.hpp, keeps of each tile the points it computes)
//   tile        the tiles grouped by colour; colour c is tile[colour_start[c] .. colour_start[c+1]-1]
//   serial_from colours from this one on are visited one tile after the other (tiles of such a
//               colour may share particles); below it, tiles of one colour share no particle
//   paired_rows every tile's points 0-1, 2-3, ... have the same neighbours in the same order
//               (the points of a cell under Q2 and Q4 on a grid of particles whose supports
//               are a whole number of spacings wide), so the force loop gathers and scatters
//               two points per visit of a neighbour (solver/point_forces.hpp)
// Two tiles get different colours when a particle is a neighbour of a point of each, so the
// tiles of one colour can scatter into the particles at the same time. A particle's force is
// then summed colour by colour, tile by tile, point by point: a fixed order.

#include <algorithm>
#include <bit>
#include <cstdint>
#include <span>
#include <vector>

#include <rkpm/core/error.hpp>
#include <rkpm/core/execution.hpp>
#include <rkpm/discretization/search_rows.hpp>
#include <rkpm/discretization/shape_table.hpp>

namespace rkpm {

struct point_traversal {
  std::vector<index_t> tile_start{0};
  std::vector<index_t> tile;
  std::vector<index_t> colour_start{0};
  index_t serial_from = 0;
  bool paired_rows = false;

  index_t tiles() const { return static_cast<index_t>(tile_start.size()) - 1; }
  index_t colours() const { return static_cast<index_t>(colour_start.size()) - 1; }
  // body(t, first, last) for every tile t, its points first .. last-1, colour by colour, the
  // tiles of a colour below serial_from in parallel (exec::for_each_coloured,
  // core/execution.hpp). A tile is visited by one thread, its points in order, so per-tile sums
  // (point_materials' reductions) are race-free and in a fixed order.
  template <class Body>
  void for_each_tile(Body&& body) const {
    exec::for_each_coloured(colour_start, serial_from, [&](index_t k) {
      const index_t t = tile[k];
      body(t, tile_start[t], tile_start[t + 1]);
    });
  }
};

// Points per tile: large enough that a tile's particles are mostly its own (few colours), small
// enough that a 10^4-particle body gives each of two threads a dozen tiles per colour.
inline constexpr index_t traversal_tile_points = 128;

// Whether the points first, first+1 of every tile (and first+2, first+3, ...) have identical
// neighbour lists in `rows` (a tile's odd last point stands alone).
template <ColumnRows Rows>
bool rows_come_in_pairs(const Rows& rows, const std::vector<index_t>& tile_start) {
  std::vector<particle_index> first;
  for (std::size_t k = 0; k + 1 < tile_start.size(); ++k)
    for (index_t q = tile_start[k]; q + 1 < tile_start[k + 1]; q += 2) {
      const std::span<const particle_index> a = rows.columns(q);
      first.assign(a.begin(), a.end());
      const std::span<const particle_index> b = rows.columns(q + 1);
      if (!std::ranges::equal(first, b)) return false;
    }
  return true;
}

// Greedy colouring of the tiles of `rows` (rows: points, columns: `particles` particles): a
// table, or the rows a neighbour search finds (discretization/search_rows.hpp), read once.
template <ColumnRows Rows>
point_traversal make_point_traversal(const Rows& rows, index_t particles,
                                     index_t tile_points = traversal_tile_points) {
  constexpr int parallel_colours = 63;  // colour 63 collects the tiles that find no free colour
  if (tile_points < 1) fail("point traversal: tile_points = {} must be at least 1", tile_points);
  point_traversal t;
  const index_t np = rows.points();
  const index_t tiles = (np + tile_points - 1) / tile_points;
  t.tile_start.resize(tiles + 1);
  for (index_t k = 0; k <= tiles; ++k) t.tile_start[k] = std::min(k * tile_points, np);
  std::vector<std::uint64_t> used(particles, 0);  // colours of the tiles touching each particle
  std::vector<int> colour(tiles);
  std::vector<index_t> count(parallel_colours + 1, 0);
  std::vector<particle_index> touched;  // the tile's rows' columns
  for (index_t k = 0; k < tiles; ++k) {
    touched.clear();
    for (index_t q = t.tile_start[k]; q < t.tile_start[k + 1]; ++q) {
      const std::span<const particle_index> row = rows.columns(q);
      touched.insert(touched.end(), row.begin(), row.end());
    }
    std::uint64_t taken = 0;
    for (const particle_index I : touched) taken |= used[I];
    const int c = std::min(std::countr_one(taken), parallel_colours);
    for (const particle_index I : touched) used[I] |= std::uint64_t{1} << c;
    colour[k] = c;
    ++count[c];
  }
  // Colours in order of first use are 0, 1, 2, ... already; drop the empty ones.
  t.tile.reserve(tiles);
  for (int c = 0; c <= parallel_colours; ++c) {
    if (count[c] == 0) continue;
    if (c == parallel_colours) t.serial_from = t.colours();
    for (index_t k = 0; k < tiles; ++k)
      if (colour[k] == c) t.tile.push_back(k);
    t.colour_start.push_back(static_cast<index_t>(t.tile.size()));
  }
  if (count[parallel_colours] == 0) t.serial_from = t.colours();
  t.paired_rows = rows_come_in_pairs(rows, t.tile_start);
  return t;
}

}  // namespace rkpm
