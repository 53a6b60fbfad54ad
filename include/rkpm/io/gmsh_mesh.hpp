#pragma once
// gmsh_mesh: bodies meshed by Gmsh (https://gmsh.info; its C++ API, tested with 4.8.4) as
// particles and background cells (docs/method.md section 3.1: the particles are the cell nodes).
//   read_gmsh_body  a .msh file (MSH 4.1 or 2.2, ASCII or binary)
//   mesh_polygon    a polygon meshed into quadrilaterals of about `spacing`
// Only this header needs libgmsh, so the library stays header-only: programs that include it
// link the CMake target rkpm::gmsh (find_package(rkpm CONFIG REQUIRED COMPONENTS gmsh)), as
// programs that draw link rkpm::gnuplot.
// Node i (compact, in Gmsh node-tag order, over the nodes of the 4-node quadrilaterals) is
// particle i; cells are turned counter-clockwise; physical curves give node and edge groups by
// name (an unnamed one by its number, "3"). Nodes that no line or quadrilateral uses (the centre
// of a circle arc, saved when a .geo has no physical group) are dropped; a node on a saved curve
// but in no quadrilateral is an error. Gmsh is one global state: each call holds it (calls from
// several threads wait); do not call these while the program itself holds Gmsh initialized.

#include <gmsh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/discretization/background_mesh.hpp>
#include <rkpm/discretization/mesh_particles.hpp>
#include <rkpm/discretization/particle_set.hpp>
#include <rkpm/io/gmsh_body.hpp>

namespace rkpm::io {

namespace detail {

// Gmsh initialized, silent and without configuration files, for the guard's lifetime.
inline std::mutex& gmsh_mutex() {
  static std::mutex m;
  return m;
}
struct gmsh_session {
  std::lock_guard<std::mutex> lock{gmsh_mutex()};
  gmsh_session() {
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
  }
  ~gmsh_session() { gmsh::finalize(); }
};

// What Gmsh threw: std::string (Gmsh 4.8) or std::exception (later versions).
inline std::string gmsh_message(std::exception_ptr e) {
  try {
    std::rethrow_exception(e);
  } catch (const std::string& s) {
    return s;
  } catch (const std::exception& x) {
    return x.what();
  } catch (...) {}
  return "unknown error";
}

// The body in Gmsh's current model; `source` names it in messages ("'plate.msh'").
inline gmsh_body body_from_model(const std::string& source, double support_factor) {
  namespace mesh = gmsh::model::mesh;
  std::vector<int> types;
  mesh::getElementTypes(types);
  std::size_t surface = 0, triangles = 0;
  std::string higher_order;
  std::vector<std::size_t> quad_tag, quad, line;  // quad: #quads x 4 node tags; line: #lines x 2
  for (int t : types) {
    std::string name;
    int dim = 0, order = 0, nodes = 0, primary = 0;
    std::vector<double> local;
    mesh::getElementProperties(t, name, dim, order, nodes, local, primary);
    std::vector<std::size_t> tags, node_tags;  // Gmsh 4.8 fills non-empty vectors in place
    mesh::getElementsByType(t, tags, node_tags);
    if (dim == 2) surface += tags.size();
    if (name.rfind("Triangle", 0) == 0) triangles += tags.size();
    if (order > 1 && (higher_order.empty() || dim == 2)) higher_order = name;
    if (t == 3) quad_tag = std::move(tags), quad = std::move(node_tags);
    if (t == 1) line = std::move(node_tags);
  }
  if (surface == 0)
    fail("{} has no 2D elements: mesh its surfaces (gmsh -2 body.geo -format msh41 -o body.msh) and, "
         "if the .geo has physical groups, put the surfaces in a Physical Surface so that Gmsh saves them",
         source);
  if (triangles > 0)
    fail("{} has {} triangles: rkpm needs quadrilateral cells; recombine them (Recombine Surface{{...}}; "
         "or Mesh.RecombineAll = 1; in the .geo) and mesh again",
         source, triangles);
  if (!higher_order.empty())
    fail("{} has second-order elements ({}): rkpm needs 4-node quadrilaterals; mesh with "
         "Mesh.ElementOrder = 1; (gmsh -order 1)",
         source, higher_order);

  // Compact numbering over the quadrilaterals' nodes, in node-tag order.
  std::vector<std::size_t> node_tag, used(quad);
  std::vector<double> xyz, uv;
  mesh::getNodes(node_tag, xyz, uv, -1, -1, false, false);
  std::unordered_map<std::size_t, const double*> at;  // node tag -> its x, y, z
  double extent = 0.0;
  for (std::size_t r = 0; r < node_tag.size(); ++r) {
    at[node_tag[r]] = &xyz[3 * r];
    extent = std::max({extent, std::abs(xyz[3 * r]), std::abs(xyz[3 * r + 1])});
  }
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::unordered_map<std::size_t, index_t> index;
  gmsh_body body;
  for (std::size_t t : used) {
    const double* x = at.at(t);
    if (std::abs(x[2]) > 1e-9 * extent)
      fail("{}: Gmsh node {} at ({:.6g}, {:.6g}, {:.6g}) has z != 0: rkpm bodies lie in the plane z = 0; "
           "draw the geometry in that plane and mesh again",
           source, t, x[0], x[1], x[2]);
    index.emplace(t, body.mesh.node.size());
    body.mesh.node.emplace_back(x[0], x[1]);
  }
  for (std::size_t t : line)
    if (!index.count(t))
      fail("{}: Gmsh node {} at ({:.6g}, {:.6g}) is on a saved curve but in no quadrilateral: every curve in the "
           "mesh must bound a meshed surface; delete the stray curve or leave it out of the physical groups",
           source, t, at.at(t)[0], at.at(t)[1]);
  for (std::size_t e = 0; e < quad_tag.size(); ++e) {
    auto& c = body.mesh.cell.emplace_back();
    for (int k = 0; k < 4; ++k) c[k] = index.at(quad[4 * e + k]);
    const double area = body.mesh.cell_area(body.mesh.cells() - 1);
    if (area == 0.0) fail("{}: quadrilateral {} has zero area; remesh the body", source, quad_tag[e]);
    if (area < 0.0) std::swap(c[1], c[3]);  // counter-clockwise: 0 3 2 1
  }

  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, 1);
  for (const auto& [dim, group] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(dim, group, name);
    if (name.empty()) name = std::to_string(group);
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(dim, group, entities);
    auto& edges = body.edge_groups[name];
    auto& nodes = body.node_groups[name];
    for (int entity : entities) {
      std::vector<std::size_t> tags, segment;
      mesh::getElementsByType(1, tags, segment, entity);
      for (std::size_t s = 0; s + 1 < segment.size(); s += 2) {
        edges.push_back({index.at(segment[s]), index.at(segment[s + 1])});
        nodes.insert(nodes.end(), edges.back().begin(), edges.back().end());
      }
    }
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  }
  body.particles = particles_from_mesh(body.mesh, support_factor);
  return body;
}

// body_from_model, with what Gmsh throws as an rkpm::error.
inline gmsh_body body_or_fail(const std::string& source, double support_factor) {
  try {
    return body_from_model(source, support_factor);
  } catch (const error&) {
    throw;
  } catch (...) {
    fail("{}: Gmsh failed on the mesh ({})", source, gmsh_message(std::current_exception()));
  }
}

}  // namespace detail

inline gmsh_body read_gmsh_body(const std::filesystem::path& msh_file, double support_factor) {
  const std::string source = "'" + msh_file.string() + "'";
  constexpr const char* fix = "give a .msh file written by Gmsh (gmsh -2 body.geo -format msh41 -o body.msh)";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(msh_file, ec))
    fail("Gmsh mesh {} does not exist (or is not a file): {}", source, fix);
  // Only MSH files reach Gmsh: it parses anything else as a .geo script, and a syntax error
  // leaves its parser broken for the rest of the process (Gmsh 4.8).
  std::string head(11, '\0');
  std::ifstream(msh_file, std::ios::binary).read(head.data(), 11);
  if (head != "$MeshFormat")
    fail("cannot read {} as a Gmsh mesh (it does not begin with $MeshFormat): {}", source, fix);
  detail::gmsh_session session;
  try {
    gmsh::open(msh_file.string());
  } catch (...) {
    fail("cannot read {} as a Gmsh mesh ({}): {}", source, detail::gmsh_message(std::current_exception()), fix);
  }
  return detail::body_or_fail(source, support_factor);
}

// A Gmsh geometry script (.geo, with its physical curves and its quadrilateral recombination)
// meshed in 2D, every mesh size multiplied by `size_factor` (1/K gives about K times the nodes
// per direction). The script is Gmsh's to run: a syntax error is reported with Gmsh's message.
inline gmsh_body mesh_geo_file(const std::filesystem::path& geo_file, double size_factor, double support_factor) {
  const std::string source = "'" + geo_file.string() + "'";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(geo_file, ec))
    fail("Gmsh geometry {} does not exist (or is not a file): give a .geo script", source);
  if (!(size_factor > 0.0) || !std::isfinite(size_factor))
    fail("mesh_geo_file: size factor {} must be positive and finite", size_factor);
  detail::gmsh_session session;
  try {
    gmsh::open(geo_file.string());
    double factor = 1.0;
    gmsh::option::getNumber("Mesh.MeshSizeFactor", factor);
    gmsh::option::setNumber("Mesh.MeshSizeFactor", factor * size_factor);
    gmsh::model::mesh::generate(2);
  } catch (...) {
    fail("Gmsh could not mesh {} ({}): run gmsh -2 {} to see its messages", source,
         detail::gmsh_message(std::current_exception()), geo_file.string());
  }
  return detail::body_or_fail(source, support_factor);
}

// The polygon `vertices` (#vertices >= 3, either orientation, edges not crossing) meshed into
// quadrilaterals of side about `spacing`, with Gmsh's OpenCASCADE kernel (its straight edges
// place transfinite nodes to the last bit): transfinite (a structured grid) when it is a convex
// quadrilateral, otherwise frontal-Delaunay triangles recombined by Gmsh's full-quad Blossom
// algorithm (Mesh.RecombinationAlgorithm = 3; Gmsh 4.8.4's quad algorithm 8 crashes). Edge k,
// from vertex k to k+1, is the group "edge_k".
inline gmsh_body mesh_polygon(const std::vector<vec2>& vertices, double spacing, double support_factor) {
  const std::size_t n = vertices.size();
  if (n < 3) fail("mesh_polygon: {} vertices; a polygon needs at least 3", n);
  if (!(spacing > 0.0) || !std::isfinite(spacing))
    fail("mesh_polygon: spacing {} must be positive and finite", spacing);
  double twice_area = 0.0;
  bool left = true, right = true;  // every turn to the left, to the right: convex
  for (std::size_t k = 0; k < n; ++k) {
    const vec2 &a = vertices[k], &b = vertices[(k + 1) % n], &c = vertices[(k + 2) % n];
    if (!a.allFinite() || (b - a).norm() == 0.0)
      fail("mesh_polygon: vertex {} is not finite or repeats the next one; give distinct vertices", k);
    twice_area += a[0] * b[1] - b[0] * a[1];
    const double turn = (b - a)[0] * (c - b)[1] - (b - a)[1] * (c - b)[0];
    left = left && turn > 0.0, right = right && turn < 0.0;
  }
  if (twice_area == 0.0) fail("mesh_polygon: the polygon has zero area; give vertices around a region");
  const bool structured = n == 4 && (left || right);

  detail::gmsh_session session;
  namespace occ = gmsh::model::occ;
  namespace mesh = gmsh::model::mesh;
  try {
    std::vector<int> point, edge;
    for (const vec2& v : vertices) point.push_back(occ::addPoint(v[0], v[1], 0.0, spacing));
    for (std::size_t k = 0; k < n; ++k) edge.push_back(occ::addLine(point[k], point[(k + 1) % n]));
    const int surface = occ::addPlaneSurface({occ::addCurveLoop(edge)});
    occ::synchronize();
    auto length = [&](std::size_t k) { return (vertices[(k + 1) % n] - vertices[k]).norm(); };
    for (std::size_t k = 0; structured && k < 2; ++k) {  // opposite edges get the same count
      const double cells = std::max(1.0, std::ceil(std::max(length(k), length(k + 2)) / spacing - 1e-9));
      mesh::setTransfiniteCurve(edge[k], static_cast<int>(cells) + 1);
      mesh::setTransfiniteCurve(edge[k + 2], static_cast<int>(cells) + 1);
    }
    if (structured) mesh::setTransfiniteSurface(surface);
    else gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 3);
    mesh::setRecombine(2, surface);
    for (std::size_t k = 0; k < n; ++k)
      gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, {edge[k]}), "edge_" + std::to_string(k));
    mesh::generate(2);
  } catch (...) {
    fail("mesh_polygon: Gmsh could not mesh the {}-vertex polygon ({}); check that its edges do not cross",
         n, detail::gmsh_message(std::current_exception()));
  }
  return detail::body_or_fail(fmt::format("the Gmsh mesh of the {}-vertex polygon", n), support_factor);
}

}  // namespace rkpm::io
