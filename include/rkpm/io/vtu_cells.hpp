#pragma once
// The cells of a VTK snapshot (io/vtk.hpp, docs/method.md section 9.4), as the three arrays of
// an UnstructuredGrid's <Cells>: connectivity (the points of every cell, one cell after the
// other), offsets (where each cell ends in connectivity) and types (VTK's cell type numbers).
//   vertex_cells(n)        one VTK_VERTEX per point: ParaView shows a cloud of dots
//   quad_cells(mesh, n)    one VTK_QUAD per background cell on the points that are the mesh's
//                          nodes (point i = node i), so ParaView draws the body as a surface and
//                          interpolates every point array across it; a point that no cell uses
//                          stays a VTK_VERTEX, after the quads
//   cell_layout            either of them as a rule instead of arrays, each entry made when
//                          asked for: a snapshot writes its cells piecewise (io/vtk.hpp) without
//                          holding them (41 MB at 10^6 particles); or cells given as arrays
//                          (a cracked body's, io/crack_snapshot.hpp)
// VTK orders a quad's nodes counter-clockwise around it; background_mesh::validate() refuses a
// cell that is not counter-clockwise in the reference configuration, so its node order is VTK's.
// In an axisymmetric run the points are (r, z) -> (x, y): the section drawn in its plane.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <rkpm/core/error.hpp>
#include <rkpm/discretization/background_mesh.hpp>

namespace rkpm::io {

inline constexpr std::uint8_t vtk_vertex = 1;  // VTK_VERTEX in VTK's vtkCellType.h
inline constexpr std::uint8_t vtk_polygon = 7; // VTK_POLYGON
inline constexpr std::uint8_t vtk_quad = 9;    // VTK_QUAD

struct vtu_cells {
  std::vector<std::int64_t> connectivity;
  std::vector<std::int64_t> offsets;  // one per cell: the end of its points in connectivity
  std::vector<std::uint8_t> types;    // one per cell

  std::size_t size() const { return types.size(); }
  bool empty() const { return types.empty(); }
};

// The cells entry by entry:
//   cell_layout::vertices(n)       cell i is the single point i
//   cell_layout::quads(mesh, n)    the mesh's cells as quads on n points whose first
//                                  mesh.node.size() are the mesh's nodes in order; every point no
//                                  cell uses (a node left out of the cells, or a point beyond the
//                                  nodes) a vertex cell after the quads
//   cell_layout::given(cells)      the cells given as arrays
class cell_layout {
 public:
  static cell_layout vertices(std::size_t points) {
    cell_layout c;
    c.vertices_ = points;
    return c;
  }
  static cell_layout quads(const background_mesh& mesh, std::size_t points) {
    if (mesh.node.size() > points)
      fail("quad_cells: the mesh has {} nodes for {} points; the points must include the nodes", mesh.node.size(),
           points);
    cell_layout c;
    c.mesh_ = &mesh;
    c.quads_ = mesh.cell.size();
    std::vector<bool> used(points, false);
    for (const auto& cell : mesh.cell)
      for (const auto n : cell) used[static_cast<std::size_t>(n)] = true;
    for (std::size_t i = 0; i < points; ++i)
      if (!used[i]) c.loose_.push_back(static_cast<std::int64_t>(i));
    c.vertices_ = c.loose_.size();
    return c;
  }

  static cell_layout given(vtu_cells cells) {
    cell_layout c;
    c.given_ = std::make_shared<const vtu_cells>(std::move(cells));
    return c;
  }

  std::size_t size() const { return given_ ? given_->size() : quads_ + vertices_; }
  std::size_t connectivity_size() const { return given_ ? given_->connectivity.size() : 4 * quads_ + vertices_; }
  // Entry k of the connectivity, cell c's end in it and its type.
  std::int64_t connectivity(std::size_t k) const {
    if (given_) return given_->connectivity[k];
    if (k < 4 * quads_) return mesh_->cell[k / 4][k % 4];
    k -= 4 * quads_;
    return mesh_ ? loose_[k] : static_cast<std::int64_t>(k);
  }
  std::int64_t offset(std::size_t c) const {
    if (given_) return given_->offsets[c];
    return static_cast<std::int64_t>(c < quads_ ? 4 * (c + 1) : 4 * quads_ + (c - quads_) + 1);
  }
  std::uint8_t type(std::size_t c) const {
    if (given_) return given_->types[c];
    return c < quads_ ? vtk_quad : vtk_vertex;
  }

 private:
  const background_mesh* mesh_ = nullptr;  // quads: the mesh (kept by the caller)
  std::size_t quads_ = 0, vertices_ = 0;
  std::vector<std::int64_t> loose_;  // quads: the points no quad uses, a vertex cell each after them
  std::shared_ptr<const vtu_cells> given_;  // given: the arrays
};

// The same as arrays.
inline vtu_cells cells_of(const cell_layout& layout) {
  vtu_cells c;
  c.connectivity.resize(layout.connectivity_size());
  c.offsets.resize(layout.size());
  c.types.resize(layout.size());
  for (std::size_t k = 0; k < c.connectivity.size(); ++k) c.connectivity[k] = layout.connectivity(k);
  for (std::size_t i = 0; i < c.types.size(); ++i) {
    c.offsets[i] = layout.offset(i);
    c.types[i] = layout.type(i);
  }
  return c;
}
inline vtu_cells vertex_cells(std::size_t points) { return cells_of(cell_layout::vertices(points)); }
inline vtu_cells quad_cells(const background_mesh& mesh, std::size_t points) {
  return cells_of(cell_layout::quads(mesh, points));
}

// Cell i's type, the end of its points in the connectivity and the connectivity's entry k, of
// either form of the cells (what io/field_figure.hpp reads).
inline std::uint8_t cell_type(const vtu_cells& c, std::size_t i) { return c.types[i]; }
inline std::int64_t cell_end(const vtu_cells& c, std::size_t i) { return c.offsets[i]; }
inline std::int64_t cell_point(const vtu_cells& c, std::size_t k) { return c.connectivity[k]; }
inline std::uint8_t cell_type(const cell_layout& c, std::size_t i) { return c.type(i); }
inline std::int64_t cell_end(const cell_layout& c, std::size_t i) { return c.offset(i); }
inline std::int64_t cell_point(const cell_layout& c, std::size_t k) { return c.connectivity(k); }

}  // namespace rkpm::io
