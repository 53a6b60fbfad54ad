#pragma once
// Surfaces of deformable bodies from their background cells (docs/method.md section 3.1): the
// boundary edges (those of one cell only) joined into chains of nodes, the master surfaces of
// contact between bodies.
//   cell_bodies      the connected parts of a mesh (cells that share a node belong to one body)
//   boundary_chains  each part's boundary as chains of node indices, each traversed as its
//                    cells traverse it (counter-clockwise cells: the body to the left, the
//                    outward normal to the right). A closed chain is a whole loop (outer
//                    boundaries run counter-clockwise, holes clockwise); edges on the axis of an
//                    axisymmetric body are not surface, and the loop they cut is an open chain
//                    from the axis round to the axis.
//   surface_layers   the nodes within k cell layers of those chains
// Any cell mesh works, not only grids. A node where two parts of the boundary meet (cells that
// touch at a corner only) has no single successor and is refused with the node's position.

#include <algorithm>
#include <array>
#include <functional>
#include <numeric>
#include <vector>

#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/discretization/background_mesh.hpp>

namespace rkpm {

struct boundary_chain {
  std::vector<index_t> node;  // mesh node indices in order; a closed chain does not repeat its first
  bool closed = false;
  index_t body = 0;  // the part of the mesh (cell_bodies) the chain bounds

  index_t segments() const { return static_cast<index_t>(node.size()) - (closed ? 0 : 1); }
  // The end nodes of segment s (body to the left).
  std::array<index_t, 2> segment(index_t s) const {
    return {node[s], node[(s + 1) % static_cast<index_t>(node.size())]};
  }
};

// Body index of every cell: cells connected through shared nodes get one index, numbered in
// the order of their first cell. `bodies` receives the count.
inline std::vector<index_t> cell_bodies(const background_mesh& mesh, index_t* bodies = nullptr) {
  std::vector<index_t> parent(mesh.node.size());
  std::iota(parent.begin(), parent.end(), index_t{0});
  std::function<index_t(index_t)> root = [&](index_t i) { return parent[i] == i ? i : parent[i] = root(parent[i]); };
  for (const auto& c : mesh.cell)
    for (int k = 1; k < 4; ++k) parent[root(c[k])] = root(c[0]);
  std::vector<index_t> id_of_root(mesh.node.size(), -1), out(mesh.cells());
  index_t count = 0;
  for (index_t c = 0; c < mesh.cells(); ++c) {
    index_t& id = id_of_root[root(mesh.cell[c][0])];
    if (id < 0) id = count++;
    out[c] = id;
  }
  if (bodies) *bodies = count;
  return out;
}

// on_axis(node) says whether a node lies on the axis (always false in plane strain); an edge
// with both ends on the axis is left out.
inline std::vector<boundary_chain> boundary_chains(const background_mesh& mesh,
                                                   const std::function<bool(index_t)>& on_axis = {}) {
  mesh.validate();
  const std::vector<index_t> body_of_cell = cell_bodies(mesh);
  // Boundary edges with their cell's body; successor and predecessor of each node along them.
  std::vector<index_t> next(mesh.node.size(), -1), body_of_node(mesh.node.size(), -1);
  std::vector<char> has_previous(mesh.node.size(), 0);
  std::vector<index_t> starts;
  {
    std::vector<std::array<index_t, 2>> edges = mesh.boundary_edges();
    // boundary_edges() lists edges in cell order; find each edge's body through its first node.
    std::vector<index_t> body_of_any(mesh.node.size(), -1);
    for (index_t c = 0; c < mesh.cells(); ++c)
      for (index_t n : mesh.cell[c]) body_of_any[n] = body_of_cell[c];
    for (const auto& [a, b] : edges) {
      if (on_axis && on_axis(a) && on_axis(b)) continue;
      if (next[a] >= 0)
        fail("boundary of the cells: node {} at ({:.6g}, {:.6g}) starts two boundary edges (cells that touch at a "
             "corner only); join them through a cell or move them apart",
             a, mesh.node[a][0], mesh.node[a][1]);
      next[a] = b;
      has_previous[b] = 1;
      body_of_node[a] = body_of_node[b] = body_of_any[a];
      starts.push_back(a);
    }
  }
  std::vector<char> used(mesh.node.size(), 0);
  std::vector<boundary_chain> chains;
  auto trace = [&](index_t first) {
    boundary_chain chain;
    chain.body = body_of_node[first];
    index_t n = first;
    while (n >= 0 && !used[n]) {
      used[n] = 1;
      chain.node.push_back(n);
      n = next[n];
    }
    chain.closed = (n == first);
    chains.push_back(std::move(chain));
  };
  // Open chains first (they start where the axis cut a loop), then the loops, each from its
  // lowest-numbered node so that the result does not depend on the cells' order.
  for (index_t a : starts)
    if (!has_previous[a] && !used[a]) trace(a);
  std::sort(starts.begin(), starts.end());
  for (index_t a : starts)
    if (!used[a]) trace(a);
  return chains;
}

// The nodes within `layers` cell layers of the surface: layer 1 is the chains' nodes, layer k + 1
// the nodes sharing a cell with layer k. Sorted. Contact slaves that reach under the surface,
// for tools whose convex corners cut the chord between two surface particles (the particles just
// below the surface there meet the tool's faces; docs/method.md section 6.9).
inline std::vector<index_t> surface_layers(const background_mesh& mesh, int layers,
                                           const std::function<bool(index_t)>& on_axis = {}) {
  if (layers < 1) fail("surface layers: {} layers; give at least 1 (the surface itself)", layers);
  std::vector<int> layer(mesh.node.size(), 0);
  std::vector<index_t> front;
  for (const boundary_chain& c : boundary_chains(mesh, on_axis))
    for (index_t n : c.node)
      if (!layer[n]) {
        layer[n] = 1;
        front.push_back(n);
      }
  for (int k = 1; k < layers && !front.empty(); ++k) {
    std::vector<index_t> next;
    for (const auto& cell : mesh.cell) {
      const bool touches = std::any_of(cell.begin(), cell.end(), [&](index_t n) { return layer[n] == k; });
      if (!touches) continue;
      for (index_t n : cell)
        if (!layer[n]) {
          layer[n] = k + 1;
          next.push_back(n);
        }
    }
    front = std::move(next);
  }
  std::vector<index_t> out;
  for (index_t n = 0; n < static_cast<index_t>(layer.size()); ++n)
    if (layer[n]) out.push_back(n);
  return out;
}

}  // namespace rkpm
