#pragma once
// Several bodies in one problem (docs/method.md section 3.1): the bodies are the connected parts
// of the background cells (cell_bodies in boundary_chains.hpp), and every particle belongs to
// the body whose cells hold it (the body of its node when the particles are the mesh nodes).
// Each body then gets its own shape functions, so kernels never reach across bodies.
//   append_body          adds one body's particles and cells to a problem's (node numbers shifted)
//   nodes_are_particles  whether the particles are the mesh nodes, in the nodes' order (grids,
//                        meshed bodies), to 1e-9 of the cells' size
//   first_overlap        two bodies that overlap (a node or cell centre of one strictly inside a
//                        cell of another), or none; bodies that touch along their boundaries are
//                        allowed
//   partition_bodies     particle -> body and cell -> body; refuses a particle outside every body's
//                        cells and bodies that overlap. A model computes it once, when it is built
//                        (discretization/model_bodies.hpp).

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
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
  bool nodes_are_particles = false;    // particle i is mesh node i
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

// The bounding box of each body's cells.
struct body_boxes {
  std::vector<vec2> lo, hi;
  double size = 0.0;  // the largest box side: the length scale of the tolerances

  body_boxes(const background_mesh& mesh, const std::vector<index_t>& cell_body, index_t bodies) {
    const double inf = std::numeric_limits<double>::infinity();
    lo.assign(bodies, vec2(inf, inf));
    hi.assign(bodies, vec2(-inf, -inf));
    for (index_t c = 0; c < mesh.cells(); ++c)
      for (index_t n : mesh.cell[c]) {
        lo[cell_body[c]] = lo[cell_body[c]].cwiseMin(mesh.node[n]);
        hi[cell_body[c]] = hi[cell_body[c]].cwiseMax(mesh.node[n]);
      }
    for (index_t b = 0; b < bodies; ++b) size = std::max(size, (hi[b] - lo[b]).maxCoeff());
  }
  bool contains(index_t b, const vec2& X, double margin) const {
    return (X.array() >= lo[b].array() - margin).all() && (X.array() <= hi[b].array() + margin).all();
  }
};

inline bool in_body(const background_mesh& mesh, const std::vector<index_t>& cell_body, index_t b, const vec2& X,
                    double tolerance) {
  for (index_t c = 0; c < mesh.cells(); ++c)
    if (cell_body[c] == b && in_cell(mesh, c, X, tolerance)) return true;
  return false;
}

}  // namespace detail

inline bool nodes_are_particles(std::span<const vec2> positions, const background_mesh& mesh) {
  if (mesh.node.size() != positions.size()) return false;
  double size = 0.0;
  for (const vec2& x : mesh.node) size = std::max(size, x.cwiseAbs().maxCoeff());
  const double tol = 1e-9 * size;
  return std::equal(mesh.node.begin(), mesh.node.end(), positions.begin(),
                    [&](const vec2& a, const vec2& b) { return (a - b).norm() <= tol; });
}

// Where a cell of one body reaches strictly inside another body.
struct body_overlap {
  index_t body = 0;  // the body reached into
  index_t cell = 0;  // the cell of the other body that reaches in
  vec2 at = vec2::Zero();  // its node or centre inside `body`
};

// The first overlap of the bodies of `cell_body` (cell order), or none.
inline std::optional<body_overlap> first_overlap(const background_mesh& mesh, const std::vector<index_t>& cell_body,
                                                 index_t bodies) {
  if (bodies < 2) return std::nullopt;
  const detail::body_boxes box(mesh, cell_body, bodies);
  const double tol = 1e-9 * box.size;
  // Centres catch bodies whose nodes sit on each other's nodes.
  for (index_t c = 0; c < mesh.cells(); ++c) {
    vec2 centre = vec2::Zero();
    for (index_t n : mesh.cell[c]) centre += 0.25 * mesh.node[n];
    for (const vec2& X : {mesh.node[mesh.cell[c][0]], mesh.node[mesh.cell[c][1]], mesh.node[mesh.cell[c][2]],
                          mesh.node[mesh.cell[c][3]], centre})
      for (index_t b = 0; b < bodies; ++b)
        if (b != cell_body[c] && box.contains(b, X, -tol) && detail::in_body(mesh, cell_body, b, X, -tol))
          return body_overlap{b, c, X};
  }
  return std::nullopt;
}

inline body_partition partition_bodies(std::span<const vec2> positions, const background_mesh& mesh) {
  const auto count = static_cast<index_t>(positions.size());
  body_partition p;
  p.cell_body = cell_bodies(mesh, &p.bodies);
  p.particle_body.assign(count, 0);
  p.nodes_are_particles = nodes_are_particles(positions, mesh);
  if (p.bodies == 1) return p;

  const detail::body_boxes box(mesh, p.cell_body, p.bodies);
  const double tol = 1e-9 * box.size;
  // Particles that are the mesh nodes take their node's body, which also tells apart two
  // particles at one position where bodies touch.
  if (p.nodes_are_particles)
    for (index_t c = 0; c < mesh.cells(); ++c)
      for (index_t n : mesh.cell[c]) p.particle_body[n] = p.cell_body[c];
  for (index_t I = 0; I < count && !p.nodes_are_particles; ++I) {
    const vec2& X = positions[I];
    index_t found = -1, candidates = 0;
    for (index_t b = 0; b < p.bodies; ++b)
      if (box.contains(b, X, tol)) {
        ++candidates;
        found = b;
      }
    if (candidates > 1) {  // overlapping boxes: ask the cells
      found = -1;
      for (index_t b = 0; b < p.bodies && found < 0; ++b)
        if (box.contains(b, X, tol) && detail::in_body(mesh, p.cell_body, b, X, tol)) found = b;
    }
    if (found < 0)
      fail("particle {} at ({:.6g}, {:.6g}) lies in none of the {} bodies' cells: give cells that cover every "
           "particle, or remove the particle",
           I, X[0], X[1], p.bodies);
    p.particle_body[I] = found;
  }

  if (const auto o = first_overlap(mesh, p.cell_body, p.bodies)) {
    const index_t other = p.cell_body[o->cell];
    fail("bodies {} and {} overlap at t = 0: cell {} of body {} reaches inside body {} at ({:.6g}, {:.6g}); "
         "move the bodies apart (they may touch along their boundaries)",
         std::min(o->body, other), std::max(o->body, other), o->cell, other, o->body, o->at[0], o->at[1]);
  }
  for (index_t b = 0; b < p.bodies; ++b)
    if (std::find(p.particle_body.begin(), p.particle_body.end(), b) == p.particle_body.end())
      fail("body {} (cells from ({:.6g}, {:.6g}) to ({:.6g}, {:.6g})) holds no particle: give its particles or "
           "remove its cells",
           b, box.lo[b][0], box.lo[b][1], box.hi[b][0], box.hi[b][1]);
  return p;
}

}  // namespace rkpm
