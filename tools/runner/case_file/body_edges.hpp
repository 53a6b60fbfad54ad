#pragma once
// The named edges of a body, shared by constraints (build_problem.hpp), checks
// (cross_checks.hpp) and measures (measure.hpp), so that all three mean the same particles:
//   rectangle  bottom, right, top, left (its outline counter-clockwise from the lower left)
//   polygon    edge_0, edge_1, ...: edge_k runs from vertex k to vertex k + 1
//   mesh       the Gmsh physical groups of the file
// A particle is on an edge when its reference position lies within 1e-9 of the body's size
// from the edge's segment (on a grid: exactly the row or column of the edge).

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include <rkpm/core/types.hpp>

#include "case_description.hpp"
#include "polygon_geometry.hpp"

namespace rkpm::runner::case_file {

// The counter-clockwise outline of a rectangle or polygon body (empty for a mesh).
inline std::vector<vec2> body_outline(const body_description& b) {
  if (const auto* r = std::get_if<rectangle_shape>(&b.shape)) {
    const vec2 &lo = r->lower_left, &hi = r->upper_right;
    return {lo, vec2(hi.x(), lo.y()), hi, vec2(lo.x(), hi.y())};
  }
  if (const auto* p = std::get_if<polygon_shape>(&b.shape)) return p->vertices;
  return {};
}

inline std::vector<std::string> edge_names(const body_description& b) {
  if (std::holds_alternative<rectangle_shape>(b.shape)) return {"bottom", "right", "top", "left"};
  std::vector<std::string> names;
  if (const auto* p = std::get_if<polygon_shape>(&b.shape))
    for (std::size_t k = 0; k < p->vertices.size(); ++k) names.push_back(fmt::format("edge_{}", k));
  if (const auto* m = std::get_if<mesh_shape>(&b.shape))
    for (const auto& [name, nodes] : m->body.node_groups) names.push_back(name);
  return names;
}

// The segment of a named edge of a rectangle or polygon body; none for an unknown name.
inline std::optional<std::pair<vec2, vec2>> edge_segment(const body_description& b, const std::string& name) {
  const auto names = edge_names(b);
  const auto outline = body_outline(b);
  for (std::size_t k = 0; k < names.size() && k < outline.size(); ++k)
    if (names[k] == name) return std::pair{outline[k], outline[(k + 1) % outline.size()]};
  return std::nullopt;
}

// Indices of the particles on a named edge, ascending: for a mesh its group's nodes (node i is
// particle i), otherwise those whose reference position X lies on the edge's segment.
inline std::vector<index_t> particles_on_edge(const body_description& b, const std::vector<vec2>& X,
                                              const std::string& edge) {
  if (const auto* m = std::get_if<mesh_shape>(&b.shape)) {
    const auto it = m->body.node_groups.find(edge);
    return it == m->body.node_groups.end() ? std::vector<index_t>{} : it->second;
  }
  const auto segment = edge_segment(b, edge);
  if (!segment) return {};
  const double tol = 1e-9 * extent(body_outline(b));
  std::vector<index_t> out;
  for (std::size_t I = 0; I < X.size(); ++I)
    if (distance_to_segment(X[I], segment->first, segment->second) <= tol) out.push_back(static_cast<index_t>(I));
  return out;
}

}  // namespace rkpm::runner::case_file
