#pragma once
// The checks of a case file that look at more than one field: a body's shape has an area (a
// polygon is simple and counter-clockwise), an axisymmetric body lies at r >= 0, names of
// edges, bodies and tools exist and are unique, pairs of bodies in contact name two bodies, no
// tool starts inside a body, the penalty enforcement has its stiffness. (Bodies that overlap
// are found when the problem is built, on their cells: build_problem.hpp.) Run after read_case found no error, so that every field read is sound.

#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include <fmt/format.h>

#include <rkpm/contact/enforcement.hpp>
#include <rkpm/geometry/axisymmetric.hpp>

#include "body_edges.hpp"
#include "case_description.hpp"
#include "diagnostics.hpp"
#include "polygon_geometry.hpp"

namespace rkpm::runner::case_file {

namespace detail {

inline void check_shape(diagnostics& d, const body_description& b, bool axisymmetric) {
  const std::string at = child_pointer(b.at, "shape");
  if (const auto* r = std::get_if<rectangle_shape>(&b.shape)) {
    if (!(r->upper_right.x() > r->lower_left.x() && r->upper_right.y() > r->lower_left.y()))
      d.error(child_pointer(at, "rectangle"),
              fmt::format("the rectangle from ({:g}, {:g}) to ({:g}, {:g}) has no area; give upper_right_m above and "
                          "to the right of lower_left_m", r->lower_left.x(), r->lower_left.y(), r->upper_right.x(),
                          r->upper_right.y()));
  } else if (const auto* p = std::get_if<polygon_shape>(&b.shape)) {
    const std::string vat = child_pointer(child_pointer(at, "polygon"), "vertices_m");
    const double area = signed_area(p->vertices), size = extent(p->vertices);
    const auto crossing = crossing_edges(p->vertices);
    if (!(std::abs(area) > 1e-12 * size * size) && (!crossing || on_one_line(p->vertices)))
      d.error(vat, "the polygon has no area (its vertices are on one line); give the corners of the body");
    else if (crossing)
      d.error(vat, fmt::format("the polygon crosses itself: edge_{} meets edge_{}; give the outline in order, "
                               "without crossings", crossing->first, crossing->second));
    else if (area < 0.0)
      d.error(vat, "the polygon is clockwise; give its vertices counter-clockwise (reverse the list)");
  }
  const auto* mesh = std::get_if<mesh_shape>(&b.shape);
  if (axisymmetric)
    for (const vec2& v : mesh ? mesh->body.mesh.node : body_outline(b))
      if (v.x() < 0.0) {
        d.error(at, fmt::format("the body reaches r = {:g} < 0; an axisymmetric body is the half section r >= 0 "
                                "(the axis is x = 0)", v.x()));
        break;
      }
}

// Does the edge lie on x = 0 (a mesh's: every node of its group)?
inline bool on_axis(const body_description& b, const std::string& edge) {
  if (const auto* m = std::get_if<mesh_shape>(&b.shape)) {
    const auto& nodes = m->body.node_groups.at(edge);
    const double tol = 1e-9 * extent(m->body.mesh.node);
    return std::all_of(nodes.begin(), nodes.end(), [&](index_t I) { return std::abs(m->body.mesh.node[I].x()) <= tol; });
  }
  const auto seg = edge_segment(b, edge);
  return seg && seg->first.x() == 0.0 && seg->second.x() == 0.0;
}

inline void check_constraints(diagnostics& d, const body_description& b, bool axisymmetric) {
  const auto names = edge_names(b);
  for (const auto& c : b.constraints) {
    const std::string at = child_pointer(c.at, "edge");
    if (std::find(names.begin(), names.end(), c.edge) == names.end()) {
      d.error(at, fmt::format("body '{}' has no edge '{}'; {}", b.name, c.edge, suggest(c.edge, names, "its edges are")));
      continue;
    }
    if (axisymmetric && c.velocity[0] && on_axis(b, c.edge))
      d.error(child_pointer(c.at, "velocity_m_s"),
              fmt::format("edge '{}' lies on the axis, where u_r = 0 is imposed already in axisymmetric geometry; "
                          "give null for the x component", c.edge));
  }
}

inline void check_tool_outside(diagnostics& d, const tool_description& t, const body_description& b) {
  const auto outline = body_outline(b);
  const auto* mesh = std::get_if<mesh_shape>(&b.shape);
  const segment_list boundary = mesh ? mesh_boundary(mesh->body.mesh) : polygon_edges(outline);
  if (boundary.empty() || t.polyline.size() < 2) return;
  const double tol = 1e-9 * (mesh ? extent(mesh->body.mesh.node) : extent(outline));
  const auto inside = [&](const vec2& p) {
    return mesh ? strictly_inside_mesh(p, mesh->body.mesh, boundary, tol) : strictly_inside(p, outline, tol);
  };
  const std::string at = child_pointer(t.at, "polyline_m");
  for (std::size_t k = 0; k < t.polyline.size(); ++k)
    if (inside(t.polyline[k])) {
      d.error(child_pointer(at, k), fmt::format("tool '{}' starts inside body '{}': vertex {} ({:g}, {:g}) is in it; "
                                                "move the tool so that it at most touches the body",
                                                t.name, b.name, k, t.polyline[k].x(), t.polyline[k].y()));
      return;
    }
  for (std::size_t k = 0; k + 1 < t.polyline.size(); ++k)
    if (const auto p = point_inside_along(t.polyline[k], t.polyline[k + 1], boundary, tol, inside)) {
      d.error(at, fmt::format("tool '{}' starts inside body '{}': its segment {} (vertices {} to {}) crosses the "
                              "body at ({:g}, {:g}); move the tool so that it at most touches the body",
                              t.name, b.name, k, k, k + 1, p->x(), p->y()));
      return;
    }
}

// Reports `name` unless it is one of `names` (`what`: "tool" or "body").
inline void check_name(diagnostics& d, const std::string& at, const std::string& name,
                       const std::vector<std::string>& names, std::string_view what) {
  if (std::find(names.begin(), names.end(), name) == names.end())
    d.error(at, fmt::format("no {} '{}'; {}", what, name,
                            suggest(name, names, what == "body" ? "the bodies are" : "the tools are")));
}

inline void check_histories(diagnostics& d, const case_description& c, const std::vector<std::string>& bodies,
                            const std::vector<std::string>& tools) {
  for (const auto& h : c.histories) {
    const auto kind_at = [&](std::string_view field) {
      const std::string_view kinds[] = {"extent", "tool_gap", "tool_force", "tool_displacement", "probe",
                                        "max_plastic_strain", "max_penetration", "volume_change", "momentum",
                                        "max_temperature", "failed_fraction"};
      return child_pointer(child_pointer(h.at, kinds[h.kind.index()]), field);
    };
    std::visit(
        [&](const auto& k) {
          using K = std::decay_t<decltype(k)>;
          if constexpr (requires { k.body; }) check_name(d, kind_at("body"), k.body, bodies, "body");
          if constexpr (requires { k.tool; }) check_name(d, kind_at("tool"), k.tool, tools, "tool");
          if constexpr (std::is_same_v<K, max_temperature_history>) {
            for (const body_description& b : c.bodies)
              if (b.name == k.body && b.material.law != material::johnson_cook::name &&
                  b.material.law != material::zerilli_armstrong::name)
                d.error(kind_at("body"), fmt::format("body '{}' has no temperature (its material law is '{}'); give it "
                                                     "\"law\": \"johnson_cook\" or \"zerilli_armstrong\" or "
                                                     "measure another body",
                                                     k.body, b.material.law));
          }
          if constexpr (std::is_same_v<K, failed_fraction_history>) {
            for (const body_description& b : c.bodies)
              if (b.name == k.body && b.material.law != material::johnson_cook::name &&
                  b.material.law != material::rankine_fracture::name)
                d.error(kind_at("body"), fmt::format("body '{}' has no damage (its material law is '{}'); give it "
                                                     "\"law\": \"johnson_cook\" or \"rankine\" or measure another body",
                                                     k.body, b.material.law));
          }
          if constexpr (std::is_same_v<K, tool_gap_history>) {
            check_name(d, kind_at("from"), k.from, tools, "tool");
            check_name(d, kind_at("to"), k.to, tools, "tool");
          }
          if constexpr (std::is_same_v<K, extent_history>) {
            const auto body = std::find(bodies.begin(), bodies.end(), k.body);
            if (k.on_edge.empty() || body == bodies.end()) return;
            const body_description& b = c.bodies[static_cast<std::size_t>(body - bodies.begin())];
            const auto names = edge_names(b);
            if (std::find(names.begin(), names.end(), k.on_edge) == names.end())
              d.error(kind_at("on_edge"), fmt::format("body '{}' has no edge '{}'; {}", b.name, k.on_edge,
                                                      suggest(k.on_edge, names, "its edges are")));
          }
        },
        h.kind);
  }
}

// The pairs of bodies in contact name bodies of the file (a body with itself is self-contact);
// "self" takes every pair, so it comes without a list.
inline void check_body_pairs(diagnostics& d, const case_description& c, const std::vector<std::string>& bodies) {
  for (const auto& p : c.body_pairs) {
    check_name(d, child_pointer(p.at, "slave"), p.slave, bodies, "body");
    check_name(d, child_pointer(p.at, "master"), p.master, bodies, "body");
  }
  if (c.self_contact && !c.body_pairs.empty())
    d.error("/contact/pairs", "\"self\": true already puts every body against every body, itself included; remove "
                              "\"pairs\" or \"self\"");
  else if (c.self_contact && c.two_pass)
    d.error("/contact/two_pass", "\"self\": true already takes every pair both ways; remove two_pass");
  else if (c.two_pass && c.body_pairs.empty())
    d.error("/contact/two_pass", "two passes of what? no \"pairs\" of bodies in contact are given; add \"pairs\": "
                                 "[{\"slave\": \"plate\", \"master\": \"projectile\"}] or remove two_pass");
}

}  // namespace detail

inline void cross_check(diagnostics& d, const case_description& c) {
  const bool axisymmetric = c.geometry == geometry::axisymmetric::name;
  std::vector<std::string> bodies, tools;
  for (const auto& b : c.bodies) {
    detail::check_shape(d, b, axisymmetric);
    detail::check_constraints(d, b, axisymmetric);
    if (std::find(bodies.begin(), bodies.end(), b.name) != bodies.end())
      d.error(child_pointer(b.at, "name"), fmt::format("a second body named '{}'; give each body its own name", b.name));
    bodies.push_back(b.name);
  }
  detail::check_body_pairs(d, c, bodies);
  for (const auto& t : c.tools) {
    if (std::find(tools.begin(), tools.end(), t.name) != tools.end())
      d.error(child_pointer(t.at, "name"), fmt::format("a second tool named '{}'; give each tool its own name", t.name));
    tools.push_back(t.name);
  }
  if (d.empty())  // the tool test needs sound outlines and names
    for (const auto& t : c.tools)
      for (const auto& b : c.bodies) detail::check_tool_outside(d, t, b);
  if (c.method.contact == contact::enforcement::penalty::name && !c.penalty_stiffness)
    d.error("/contact", "the penalty enforcement needs a stiffness; add \"penalty_stiffness_N_m\": 1e11 to \"contact\"");
  detail::check_histories(d, c, bodies, tools);
}

}  // namespace rkpm::runner::case_file
