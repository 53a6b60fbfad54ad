#pragma once
// Several bodies in one problem (docs/method.md section 3.1): the bodies are the connected parts
// of the background cells (cell_bodies in boundary_chains.hpp), and every particle belongs to
// the body whose cells hold it (the body of its node when the particles are the mesh nodes).
// Each body then gets its own shape functions, so kernels never reach across bodies.
//   append_body       adds one body's particles and cells to a problem's (node numbers shifted)
//   partition_bodies  particle -> body and cell -> body; refuses a particle outside every body's
//                     cells and bodies that overlap (a node or cell centre of one strictly inside
//                     a cell of another); bodies that touch along their boundaries are allowed.

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/discretization/background_mesh.hpp>
#include <rkpm/discretization/boundary_chains.hpp>
#include <rkpm/discretization/particle_set.hpp>

namespace rkpm {

struct body_partition {
  index_t bodies = 0;
  std::vector<index_t> particle_body;  // #particles
  std::vector<index_t> cell_body;      // #cells

  // The particles of body b, ascending.
  std::vector<index_t> particles_of(index_t b) const {
    std::vector<index_t> out;
    for (index_t I = 0; I < static_cast<index_t>(particle_body.size()); ++I)
      if (particle_body[I] == b) out.push_back(I);
    return out;
  }
};

// Appends a body's particles and cells to those of a problem with several bodies; the body's
// cell nodes are renumbered after the nodes already there. Bodies are numbered by their first
// cells, so the first body appended is body 0.
inline void append_body(particle_set<2>& particles, background_mesh& mesh, const particle_set<2>& body,
                        const background_mesh& cells) {
  const auto offset = static_cast<index_t>(mesh.node.size());
  particles.position.insert(particles.position.end(), body.position.begin(), body.position.end());
  particles.volume.insert(particles.volume.end(), body.volume.begin(), body.volume.end());
  particles.support.insert(particles.support.end(), body.support.begin(), body.support.end());
  mesh.node.insert(mesh.node.end(), cells.node.begin(), cells.node.end());
  for (auto cell : cells.cell) {
    for (auto& i : cell) i += offset;
    mesh.cell.push_back(cell);
  }
}

namespace detail {

// Whether X lies in cell c: inside or on it within `tolerance` (> 0), or strictly inside,
// farther than `tolerance` from every edge (< 0). Cells are convex quadrilaterals or nearly so;
// the test uses the four edge half-planes.
inline bool in_cell(const background_mesh& mesh, index_t c, const vec2& X, double tolerance) {
  for (int k = 0; k < 4; ++k) {
    const vec2& a = mesh.node[mesh.cell[c][k]];
    const vec2& b = mesh.node[mesh.cell[c][(k + 1) % 4]];
    const vec2 t = b - a;
    const double left = (t[0] * (X[1] - a[1]) - t[1] * (X[0] - a[0])) / t.norm();  // > 0: inside
    if (left < -tolerance) return false;
  }
  return true;
}

}  // namespace detail

inline body_partition partition_bodies(std::span<const vec2> positions, const background_mesh& mesh) {
  const auto count = static_cast<index_t>(positions.size());
  body_partition p;
  p.cell_body = cell_bodies(mesh, &p.bodies);
  p.particle_body.assign(count, 0);
  if (p.bodies == 1) return p;

  // Bounding box of each body's cells, and a length scale for the tolerances.
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<vec2> lo(p.bodies, vec2(inf, inf)), hi(p.bodies, vec2(-inf, -inf));
  for (index_t c = 0; c < mesh.cells(); ++c)
    for (index_t n : mesh.cell[c]) {
      lo[p.cell_body[c]] = lo[p.cell_body[c]].cwiseMin(mesh.node[n]);
      hi[p.cell_body[c]] = hi[p.cell_body[c]].cwiseMax(mesh.node[n]);
    }
  double size = 0.0;
  for (index_t b = 0; b < p.bodies; ++b) size = std::max(size, (hi[b] - lo[b]).maxCoeff());
  const double tol = 1e-9 * size;
  auto in_box = [&](index_t b, const vec2& X, double margin) {
    return (X.array() >= lo[b].array() - margin).all() && (X.array() <= hi[b].array() + margin).all();
  };
  auto in_body = [&](index_t b, const vec2& X, double tolerance) {
    for (index_t c = 0; c < mesh.cells(); ++c)
      if (p.cell_body[c] == b && detail::in_cell(mesh, c, X, tolerance)) return true;
    return false;
  };

  // Particles that are the mesh nodes (grids, meshed bodies) take their node's body, which also
  // tells apart two particles at one position where bodies touch.
  const bool nodes_are_particles =
      static_cast<index_t>(mesh.node.size()) == count &&
      std::equal(mesh.node.begin(), mesh.node.end(), positions.begin(),
                 [&](const vec2& a, const vec2& b) { return (a - b).norm() <= tol; });
  if (nodes_are_particles)
    for (index_t c = 0; c < mesh.cells(); ++c)
      for (index_t n : mesh.cell[c]) p.particle_body[n] = p.cell_body[c];
  for (index_t I = 0; I < count && !nodes_are_particles; ++I) {
    const vec2& X = positions[I];
    index_t found = -1, candidates = 0;
    for (index_t b = 0; b < p.bodies; ++b)
      if (in_box(b, X, tol)) {
        ++candidates;
        found = b;
      }
    if (candidates > 1) {  // overlapping boxes: ask the cells
      found = -1;
      for (index_t b = 0; b < p.bodies && found < 0; ++b)
        if (in_box(b, X, tol) && in_body(b, X, tol)) found = b;
    }
    if (found < 0)
      fail("particle {} at ({:.6g}, {:.6g}) lies in none of the {} bodies' cells: give cells that cover every "
           "particle, or remove the particle",
           I, X[0], X[1], p.bodies);
    p.particle_body[I] = found;
  }

  // Overlap: a node or a cell centre of one body strictly inside a cell of another (centres
  // catch bodies whose nodes sit on each other's nodes).
  for (index_t c = 0; c < mesh.cells(); ++c) {
    vec2 centre = vec2::Zero();
    for (index_t n : mesh.cell[c]) centre += 0.25 * mesh.node[n];
    for (const vec2& X : {mesh.node[mesh.cell[c][0]], mesh.node[mesh.cell[c][1]], mesh.node[mesh.cell[c][2]],
                          mesh.node[mesh.cell[c][3]], centre})
      for (index_t b = 0; b < p.bodies; ++b)
        if (b != p.cell_body[c] && in_box(b, X, -tol) && in_body(b, X, -tol))
          fail("bodies {} and {} overlap at t = 0: cell {} of body {} reaches inside body {} at ({:.6g}, {:.6g}); "
               "move the bodies apart (they may touch along their boundaries)",
               std::min(b, p.cell_body[c]), std::max(b, p.cell_body[c]), c, p.cell_body[c], b, X[0], X[1]);
  }
  for (index_t b = 0; b < p.bodies; ++b)
    if (std::find(p.particle_body.begin(), p.particle_body.end(), b) == p.particle_body.end())
      fail("body {} (cells from ({:.6g}, {:.6g}) to ({:.6g}, {:.6g})) holds no particle: give its particles or "
           "remove its cells",
           b, lo[b][0], lo[b][1], hi[b][0], hi[b][1]);
  return p;
}

}  // namespace rkpm
