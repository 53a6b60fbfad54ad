#pragma once
// Cracks that grow through the background cells (docs/method.md section 5.12): when a
// quadrature point of a material that can break has failed (its state's failed(), e.g.
// material::rankine_fracture at full damage), its cell is cut by a straight crack through the
// cell's centroid, normal to the point's crack normal (113), and the model is rebuilt in the
// current configuration with the crack among the visibility criterion's segments (112), through
// the re-reference (section 5.8). A cut is stored by where it crosses two sides of its cell, so
// that it moves with the cell's corners (the particles) through later re-references:
//   cell_crack       a cell's cut: the two sides it crosses and where along each
//   cut_cell         the cut of a cell through its centroid with a given normal
//   cells_at_nodes, cell_neighbours  the cells around each node, and across each cell's sides
//   beside_a_cut     whether a cut runs in a neighbouring cell alongside a new one (a band of
//                    failed cells is cut once across, not into slivers)
//   crack_chord      the cut's segment on the cells at their current corners, lengthened past
//                    the cell's sides so that the cuts of neighbouring cells overlap
//   cracks_on        every cut's segment, as the crack_set the model builder reads, with its faces
//   failed_uncut_cells  the cells of failed points not cut yet, with their normals
//   opens_cracks     whether the failed points of some body's material cut cells
//   crack_fragments  the pieces the cracks have made: particles joined by a point's row
// On a rank's part of a run on several processes: solver/part_cracks.hpp.

#include <algorithm>
#include <array>
#include <numeric>
#include <optional>
#include <utility>
#include <vector>

#include <rkpm/concepts/material.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/discretization/background_mesh.hpp>
#include <rkpm/discretization/crack_set.hpp>
#include <rkpm/solver/body_materials.hpp>
#include <rkpm/solver/discrete_model.hpp>

namespace rkpm {

struct cell_crack {
  index_t cell = 0;
  std::array<index_t, 2> side{};  // side k runs from corner k to corner k + 1
  std::array<double, 2> at{};     // the crossing (1 - at) x_k + at x_{k+1}
};

// Where cell c's cut is, or would go, in cuts kept in cell order, and whether c is cut.
inline std::size_t cut_position(const std::vector<cell_crack>& cuts, index_t c) {
  return static_cast<std::size_t>(
      std::lower_bound(cuts.begin(), cuts.end(), c, [](const cell_crack& k, index_t cell) { return k.cell < cell; }) -
      cuts.begin());
}
inline bool is_cut(const std::vector<cell_crack>& cuts, index_t c) {
  const std::size_t at = cut_position(cuts, c);
  return at < cuts.size() && cuts[at].cell == c;
}

// The cut of cell c, its corners at `corner`, through its centroid with unit normal n; none if
// the line misses two sides (a degenerate cell).
inline std::optional<cell_crack> cut_cell(const std::array<vec2, 4>& corner, index_t c, const vec2& n) {
  vec2 centre = vec2::Zero();
  for (const vec2& x : corner) centre += 0.25 * x;
  std::array<double, 4> distance{};
  for (int k = 0; k < 4; ++k) distance[k] = (corner[k] - centre).dot(n);
  cell_crack cut{c, {}, {}};
  int found = 0;
  for (int k = 0; k < 4 && found < 2; ++k) {
    const double d0 = distance[k], d1 = distance[(k + 1) % 4];
    if ((d0 >= 0.0) == (d1 >= 0.0)) continue;
    cut.side[found] = k;
    cut.at[found] = d0 / (d0 - d1);
    ++found;
  }
  if (found < 2) return std::nullopt;
  return cut;
}
inline std::optional<cell_crack> cut_cell(const background_mesh& cells, index_t c, const vec2& n) {
  const auto& k = cells.cell[c];
  return cut_cell({cells.node[k[0]], cells.node[k[1]], cells.node[k[2]], cells.node[k[3]]}, c, n);
}

// The cells around each node (those that have it as a corner), in cell order.
inline std::vector<std::vector<index_t>> cells_at_nodes(const background_mesh& cells) {
  std::vector<std::vector<index_t>> at_node(cells.node.size());
  for (index_t c = 0; c < cells.cells(); ++c)
    for (const stored_index n : cells.cell[c]) at_node[n].push_back(c);
  return at_node;
}

// Each cell's neighbour across each of its sides (side k from corner k to k + 1), -1 at the boundary.
inline std::vector<std::array<index_t, 4>> cell_neighbours(const background_mesh& cells) {
  const std::vector<std::vector<index_t>> at_node = cells_at_nodes(cells);
  std::vector<std::array<index_t, 4>> out(static_cast<std::size_t>(cells.cells()));
  for (index_t c = 0; c < cells.cells(); ++c)
    for (int k = 0; k < 4; ++k) {
      const stored_index a = cells.cell[c][k], b = cells.cell[c][(k + 1) % 4];
      out[c][k] = -1;
      for (const index_t other : at_node[a])
        if (other != c && std::ranges::find(cells.cell[other], b) != cells.cell[other].end()) out[c][k] = other;
    }
  return out;
}

// Whether a cell across a side that `cut` does not cross is cut already (section 5.12): the crack
// runs alongside, and the failed points of a band several cells wide would otherwise cut every
// cell of it, parallel cuts a cell apart that leave slivers of one particle column, whose high
// frequencies shrink the stable step a hundredfold. The band is cut once across; its other
// failed points carry no tension anyway.
// `around`: the cell's neighbours across its sides (-1 at the boundary).
inline bool beside_a_cut(const std::array<index_t, 4>& around, const std::vector<cell_crack>& cuts,
                         const cell_crack& cut) {
  for (int k = 0; k < 4; ++k) {
    if (k == cut.side[0] || k == cut.side[1]) continue;
    if (const index_t other = around[k]; other >= 0 && is_cut(cuts, other)) return true;
  }
  return false;
}
inline bool beside_a_cut(const std::vector<std::array<index_t, 4>>& neighbours, const std::vector<cell_crack>& cuts,
                         const cell_crack& cut) {
  return beside_a_cut(neighbours[cut.cell], cuts, cut);
}

// Where `cut` crosses its cell's two sides, on the cells at their current corners.
inline crack_set::segment_type crack_crossings(const background_mesh& cells, const cell_crack& cut) {
  const auto& corner = cells.cell[cut.cell];
  crack_set::segment_type end;
  for (int e = 0; e < 2; ++e) {
    const index_t k = cut.side[e];
    end[e] = (1.0 - cut.at[e]) * cells.node[corner[k]] + cut.at[e] * cells.node[corner[(k + 1) % 4]];
  }
  return end;
}

// The segment of `cut` on the cells at their current corners, lengthened by `overlap` of its
// length at each end (the cuts of a crack path then overlap, and no sight line slips through
// where two of them meet on a cell side).
inline crack_set::segment_type crack_chord(const background_mesh& cells, const cell_crack& cut, double overlap = 0.1) {
  const auto [a, b] = crack_crossings(cells, cut);
  const vec2 along = overlap * (b - a);
  return {a - along, b + along};
}

// Every cut's segment, as the crack_set the model builder reads, with its face: the chord
// between the crossings, where the crack is a surface of the material on each side.
inline crack_set cracks_on(const background_mesh& cells, const std::vector<cell_crack>& cuts) {
  std::vector<crack_set::segment_type> segments;
  std::vector<crack_set::face_type> faces;
  segments.reserve(cuts.size());
  faces.reserve(cuts.size());
  for (const cell_crack& cut : cuts) {
    segments.push_back(crack_chord(cells, cut));
    faces.push_back({cut.cell, crack_crossings(cells, cut)});
  }
  return crack_set(std::move(segments), std::move(faces));
}

// The cells not cut yet of the failed points with an in-plane crack normal (a hoop crack cuts no
// cell), each with its point's normal, in point order: explicit_solver::grow_cracks's candidates.
template <class State>
std::vector<std::pair<index_t, vec2>> failed_uncut_cells(const discrete_model& m, const std::vector<State>& states,
                                                         const std::vector<cell_crack>& cuts) {
  std::vector<std::pair<index_t, vec2>> failed;  // allocates only when a cell is to be cut
  for (index_t q = 0; q < m.point_count(); ++q) {
    const State& s = states[q];
    if (!s.failed() || !(vec2(s.crack_normal).squaredNorm() > 0.0)) continue;
    if (const index_t c = m.points.cell[q]; !is_cut(cuts, c)) failed.emplace_back(c, vec2(s.crack_normal));
  }
  return failed;
}

// Whether failed points may cut cells: a state that breaks (BreakingState) and a material that
// opens cracks in some body, where the material says (OpensCracks); otherwise the solver does
// not look for failed points at all.
template <Material M>
bool opens_cracks(const materials_by_body<M>& materials) {
  if constexpr (!BreakingState<typename M::state_type>) {
    return false;
  } else if constexpr (!OpensCracks<M>) {
    return true;
  } else {
    for (index_t b = 0; b < materials.count(); ++b)
      if (materials.of_body(b).opens_cracks()) return true;
    return false;
  }
}

// The pieces of a model: particles are joined when a quadrature point's row holds both (they
// interact through the forces), so a piece is a connected set of particles; a particle that no
// point's row holds is a piece by itself (a free particle).
struct fragment_count {
  index_t pieces = 0;
  double largest_mass = 0.0;  // kg (per unit thickness in plane strain; per radian... as the masses)
};

// Each particle's piece among the model's particles, named by the piece's smallest particle
// index: particles joined when a point's row holds both (a union-find over the rows).
inline std::vector<index_t> row_pieces(const discrete_model& m) {
  std::vector<index_t> parent(m.particle_count());
  std::iota(parent.begin(), parent.end(), index_t{0});
  const auto root = [&](index_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (index_t q = 0; q < m.point_count(); ++q)
    for (index_t e = m.at_points.offset[q] + 1; e < m.at_points.offset[q + 1]; ++e) {
      const index_t a = root(m.at_points.neighbor[m.at_points.offset[q]]), b = root(m.at_points.neighbor[e]);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  for (index_t I = 0; I < m.particle_count(); ++I) parent[I] = root(I);
  return parent;
}

inline fragment_count crack_fragments(const discrete_model& m, const std::vector<double>& mass) {
  const std::vector<index_t> root = row_pieces(m);
  std::vector<double> piece(m.particle_count(), 0.0);
  fragment_count out;
  for (index_t I = 0; I < m.particle_count(); ++I) {
    const index_t r = root[I];
    if (r == I) ++out.pieces;
    piece[r] += mass[I];
  }
  out.largest_mass = *std::max_element(piece.begin(), piece.end());
  return out;
}

}  // namespace rkpm
