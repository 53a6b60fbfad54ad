#pragma once
// background_mesh: the quadrilateral integration cells that cover the body
// (docs/method.md section 3.1). Cells hold four node indices counter-clockwise.
//   node   #nodes list of corner positions (reference configuration)
//   cell   #cells list of 4 node indices, counter-clockwise
// make_grid_mesh builds the cells of a regular particle grid with the same node numbering as
// make_grid_particles (first direction fastest), so node i is particle i.

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/discretization/crack_set.hpp>

namespace rkpm {

struct background_mesh {
  std::vector<vec2> node;
  std::vector<std::array<stored_index, 4>> cell;  // node numbers, counter-clockwise
  // The cells of a re-referenced model (docs/method.md section 5.8): the particles' current
  // positions, where a cell squeezed flat against a tool may have turned inside out. Such cells
  // carry no quadrature rule (the points are the material points carried over) and say only
  // which particles and boundary edges belong together, so validate() checks their numbering.
  bool tangled = false;
  // Cracks through the cells (docs/method.md section 3.7): the model built on these cells keeps
  // its kernels from reaching across them. Empty: an intact body.
  crack_set cracks;

  index_t cells() const { return static_cast<index_t>(cell.size()); }

  // Signed area of a cell (positive when counter-clockwise).
  double cell_area(index_t c) const {
    double a = 0.0;
    for (int k = 0; k < 4; ++k) {
      const vec2& p = node[cell[c][k]];
      const vec2& q = node[cell[c][(k + 1) % 4]];
      a += p[0] * q[1] - q[0] * p[1];
    }
    return 0.5 * a;
  }

  double area() const {
    double a = 0.0;
    for (index_t c = 0; c < cells(); ++c) a += cell_area(c);
    return a;
  }

  void validate() const {
    if (cell.empty()) fail("background mesh has no cells: give the cells that cover the body");
    if (node.size() > static_cast<std::size_t>(std::numeric_limits<stored_index>::max()))
      fail("background mesh with {} nodes: at most {} (32-bit node numbers)", node.size(),
           std::numeric_limits<stored_index>::max());
    for (index_t c = 0; c < cells(); ++c) {
      for (index_t n : cell[c])
        if (n < 0 || n >= static_cast<index_t>(node.size()))
          fail("background cell {} refers to node {} of {}", c, n, node.size());
      if (!tangled && !(cell_area(c) > 0.0))
        fail("background cell {} has area {:.3g}: its nodes must be counter-clockwise and distinct",
             c, cell_area(c));
    }
  }

  // The boundary edges (those that belong to one cell only), in cell order, each traversed as
  // its cell traverses it (counter-clockwise cells: the body to the left, the outward normal to
  // the right).
  // The edges are counted in a sorted array of 64-bit keys (8 bytes per cell side), not a
  // std::map (about 110 bytes per node): this runs while the solver is set up, with the shape
  // tables already in memory, so a map would raise the peak memory of the whole run.
  std::vector<std::array<index_t, 2>> boundary_edges() const {
    const auto key = [](index_t a, index_t b) {
      const auto [lo, hi] = std::minmax(a, b);
      return static_cast<std::uint64_t>(lo) << 32 | static_cast<std::uint64_t>(hi);
    };
    std::vector<std::uint64_t> sides;
    sides.reserve(4 * cell.size());
    for (const auto& c : cell)
      for (int k = 0; k < 4; ++k) sides.push_back(key(c[k], c[(k + 1) % 4]));
    std::sort(sides.begin(), sides.end());
    std::vector<std::array<index_t, 2>> edges;
    for (const auto& c : cell)
      for (int k = 0; k < 4; ++k) {
        const auto [first, last] = std::equal_range(sides.begin(), sides.end(), key(c[k], c[(k + 1) % 4]));
        if (last - first == 1) edges.push_back({c[k], c[(k + 1) % 4]});
      }
    return edges;
  }

  // Nodes on the boundary of the meshed region: the nodes of boundary_edges(), ascending.
  std::vector<index_t> boundary_nodes() const {
    std::vector<char> on(node.size(), 0);
    for (const auto& [a, b] : boundary_edges()) on[a] = on[b] = 1;
    std::vector<index_t> out;
    for (index_t i = 0; i < static_cast<index_t>(node.size()); ++i)
      if (on[i]) out.push_back(i);
    return out;
  }
};

// One cell as a part of the mesh sees it (a rank's part of a run on several processes, which
// holds no mesh): its corners by the part's particle ids (-1 where the part does not hold one)
// and its neighbours across its sides k (corner k to k + 1) by the whole mesh's cell ids (-1 at
// the boundary).
struct cell_around {
  std::array<stored_index, 4> corner{};
  std::array<index_t, 4> neighbour{};
};

// Cells of the regular grid of counts[0] x counts[1] nodes on [lo, hi].
inline background_mesh make_grid_mesh(const vec2& lo, const vec2& hi, const Eigen::Vector2i& counts) {
  if (counts[0] < 2 || counts[1] < 2) fail("grid mesh: need at least 2 nodes per direction");
  background_mesh m;
  const vec2 h((hi[0] - lo[0]) / (counts[0] - 1), (hi[1] - lo[1]) / (counts[1] - 1));
  m.node.reserve(static_cast<std::size_t>(counts[0]) * counts[1]);
  m.cell.reserve(static_cast<std::size_t>(counts[0] - 1) * (counts[1] - 1));
  for (int j = 0; j < counts[1]; ++j)
    for (int i = 0; i < counts[0]; ++i) m.node.emplace_back(lo[0] + i * h[0], lo[1] + j * h[1]);
  for (int j = 0; j + 1 < counts[1]; ++j)
    for (int i = 0; i + 1 < counts[0]; ++i) {
      const index_t n0 = j * counts[0] + i;
      m.cell.push_back({static_cast<stored_index>(n0), static_cast<stored_index>(n0 + 1),
                        static_cast<stored_index>(n0 + 1 + counts[0]), static_cast<stored_index>(n0 + counts[0])});
    }
  return m;
}

}  // namespace rkpm
