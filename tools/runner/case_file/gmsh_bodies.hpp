#pragma once
// Bodies that Gmsh meshes (rkpm/io/gmsh_mesh.hpp, loaded when needed: gmsh_reader.hpp): a mesh file
// (.msh) is read once, when the case file is loaded (its physical curves name the edges, and
// the tool checks need its cells); a geometry script (.geo) is meshed then too, with sizes / K
// for resolution K (load_case_file's argument); a polygon is meshed when the problem is built,
// at the spacing of the resolution asked for. The particles are the mesh nodes.

#include <string>
#include <utility>

#include <fmt/format.h>

#include <rkpm/discretization/background_mesh.hpp>
#include <rkpm/discretization/particle_set.hpp>
#include <rkpm/io/gmsh_body.hpp>

#include "case_description.hpp"
#include "diagnostics.hpp"
#include "gmsh_reader.hpp"

namespace rkpm::runner::case_file {

inline std::string mesh_file_pointer(const body_description& b) {
  return child_pointer(child_pointer(child_pointer(b.at, "shape"), "mesh"), "file");
}

// Reads every mesh body's file, or meshes its .geo script with sizes / resolution, so that the
// node groups (the named edges of constraints and histories) are those of the particles the
// problem will have; a file Gmsh refuses is reported at its pointer.
inline void read_meshes(diagnostics& d, case_description& c, int resolution) {
  for (auto& b : c.bodies)
    if (auto* m = std::get_if<mesh_shape>(&b.shape)) try {
        if (m->file.extension() == ".geo") {
          m->body = load_gmsh_reader().mesh_geo(m->file, 1.0 / resolution, c.support_factor);
          m->meshed_at = resolution;
        } else {
          m->body = load_gmsh_reader().read_msh(m->file, c.support_factor);
        }
      } catch (const error& e) {
        d.error(mesh_file_pointer(b), e.what());
      }
}

// The particles and cells of a polygon or mesh body at resolution K (a polygon's spacing / K,
// a .geo script's sizes / K, as loaded; a .msh file is used as it is, at resolution 1 only).
// Errors are thrown as `fail(at, message)`.
template <class Fail>
std::pair<particle_set<2>, background_mesh> gmsh_discretize(const case_description& c, const body_description& b,
                                                            int resolution, Fail&& fail_at) {
  if (const auto* m = std::get_if<mesh_shape>(&b.shape)) {
    if (m->file.extension() == ".geo" && resolution != m->meshed_at)
      fail_at(mesh_file_pointer(b), fmt::format("the .geo script was meshed for resolution {} when the case file was "
                                                "loaded; load it with resolution {} (load_case_file's argument)",
                                                m->meshed_at, resolution));
    if (m->file.extension() != ".geo" && resolution != 1)
      fail_at(mesh_file_pointer(b), fmt::format("a mesh file is used as it is, so resolution {} cannot refine it; "
                                                "run at resolution 1 with a finer mesh file", resolution));
    return {m->body.particles, m->body.mesh};
  }
  const auto& p = std::get<polygon_shape>(b.shape);
  try {
    io::gmsh_body body = load_gmsh_reader().mesh_polygon(p.vertices, p.spacing / resolution, c.support_factor);
    return {std::move(body.particles), std::move(body.mesh)};
  } catch (const error& e) {
    fail_at(child_pointer(child_pointer(b.at, "shape"), "polygon"), e.what());
  }
  return {};  // not reached: fail_at throws
}

}  // namespace rkpm::runner::case_file
