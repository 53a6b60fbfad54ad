#pragma once
// particles_from_mesh: the particles of a body given by its background cells, one per mesh
// node (docs/method.md section 3.1: the particles are the cell nodes), for meshes that are not
// a regular grid (io/gmsh_mesh.hpp reads them from Gmsh).
//   mesh            #nodes positions, #cells x 4 node indices counter-clockwise
//   support_factor  s > 0, as in make_grid_particles
//   returns         #nodes particles: node i is particle i, so the cells need no renumbering
// Volume of particle I: a quarter of the area of every cell that has I as a corner (the
// tributary volume; the volumes add up to the mesh area). Support in direction k:
// s * (largest |k-component| of the edges of the cells around I), all four edges of each cell,
// so that a distorted cell is covered from each of its corners. On a regular grid both equal
// make_grid_particles' (corner h0 h1 / 4, edge h0 h1 / 2, inside h0 h1; a = s h).
// A node that no cell uses is an error rather than dropped: dropping it would renumber the
// particles against the cells, and such a node would carry no volume.

#include <cmath>

#include <rkpm/discretization/background_mesh.hpp>
#include <rkpm/discretization/particle_set.hpp>

namespace rkpm {

inline particle_set<2> particles_from_mesh(const background_mesh& mesh, double support_factor) {
  if (!(support_factor > 0.0) || !std::isfinite(support_factor))
    fail("particles from mesh: support factor {} must be positive and finite", support_factor);
  mesh.validate();  // node indices in range, every cell counter-clockwise
  const index_t n = static_cast<index_t>(mesh.node.size());
  particle_set<2> p;
  p.position = mesh.node;
  p.volume.assign(n, 0.0);
  p.support.assign(n, vec2::Zero());
  for (index_t c = 0; c < mesh.cells(); ++c) {
    const auto& corner = mesh.cell[c];
    const double quarter = 0.25 * mesh.cell_area(c);
    vec2 widest = vec2::Zero();  // largest |edge component| of this cell, per direction
    for (int k = 0; k < 4; ++k)
      widest = widest.cwiseMax((mesh.node[corner[(k + 1) % 4]] - mesh.node[corner[k]]).cwiseAbs());
    for (index_t I : corner) {
      p.volume[I] += quarter;
      p.support[I] = p.support[I].cwiseMax(widest);
    }
  }
  for (index_t I = 0; I < n; ++I) {
    if (p.volume[I] == 0.0)
      fail("particles from mesh: node {} at ({:.6g}, {:.6g}) is a corner of no cell; remove it from "
           "mesh.node and renumber the cells, or add the cells it belongs to",
           I, mesh.node[I][0], mesh.node[I][1]);
    p.support[I] *= support_factor;
  }
  return p;
}

}  // namespace rkpm
