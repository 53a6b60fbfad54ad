#pragma once
// gmsh_body: a body as Gmsh meshed it (io/gmsh_mesh.hpp reads and meshes one), apart from the
// reader, so that code that only holds bodies needs neither gmsh.h nor libgmsh.

#include <array>
#include <map>
#include <string>
#include <vector>

#include <rkpm/core/types.hpp>
#include <rkpm/discretization/background_mesh.hpp>
#include <rkpm/discretization/particle_set.hpp>

namespace rkpm::io {

struct gmsh_body {
  particle_set<2> particles;  // #nodes particles, particles_from_mesh(mesh, support_factor): node i is particle i
  background_mesh mesh;       // #nodes positions, #cells quadrilaterals counter-clockwise
  std::map<std::string, std::vector<index_t>> node_groups;                 // curve name -> sorted node indices
  std::map<std::string, std::vector<std::array<index_t, 2>>> edge_groups;  // curve name -> #segments node pairs
};

}  // namespace rkpm::io
