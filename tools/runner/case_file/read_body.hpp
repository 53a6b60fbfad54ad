#pragma once
// Reading one entry of "bodies": its shape (rectangle, polygon or Gmsh mesh), material
// (read_material.hpp), initial velocity and body force (numbers or expressions:
// read_expressions.hpp), edge constraints and contact slaves. Values are checked one by
// one here (types, signs, ranges); what needs the whole body (a polygon with no area, an edge
// name, a tool inside it) is checked in cross_checks.hpp.

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "case_description.hpp"
#include "json_fields.hpp"
#include "read_expressions.hpp"
#include "read_material.hpp"

namespace rkpm::runner::case_file {

namespace detail {

inline std::optional<body_shape> read_shape(diagnostics& d, const json& value, const std::string& at,
                                            const std::filesystem::path& folder) {
  static constexpr std::array<std::string_view, 3> kinds{"rectangle", "polygon", "mesh"};
  object_reader shape(d, value, at, {kinds.begin(), kinds.end()});
  if (!shape.valid()) return std::nullopt;
  if (value.size() != 1) {
    d.error(at, fmt::format("give exactly one of {} (found {})", list_choices(kinds), value.size()));
    return std::nullopt;
  }
  const std::string kind = value.begin().key();
  if (kind == "rectangle") {
    object_reader r(d, value[kind], shape.at(kind), {"lower_left_m", "upper_right_m", "particles"});
    const auto lo = r.point("lower_left_m", "[0, 0]");
    const auto hi = r.point("upper_right_m", "[3.2e-3, 32.4e-3]");
    rectangle_shape s;
    if (const json* n = r.required("particles", "[21, 51]")) {
      const bool pair = n->is_array() && n->size() == 2;
      const auto nx = pair ? to_integer(d, (*n)[0], child_pointer(r.at("particles"), 0), "21") : std::nullopt;
      const auto ny = pair ? to_integer(d, (*n)[1], child_pointer(r.at("particles"), 1), "51") : std::nullopt;
      if (!pair)
        d.error(r.at("particles"),
                fmt::format("expected [particles along x, along y], got {}; give e.g. [21, 51]", describe(*n)));
      for (int k = 0; k < 2; ++k) {
        const auto c = k == 0 ? nx : ny;
        if (c && *c < 2)
          d.error(child_pointer(r.at("particles"), k),
                  fmt::format("{} particles: a grid needs at least 2 per direction", *c));
        if (c) s.particles[k] = *c;
      }
      if (!nx || !ny || *nx < 2 || *ny < 2) return std::nullopt;
    }
    if (!lo || !hi) return std::nullopt;
    s.lower_left = *lo;
    s.upper_right = *hi;
    return s;
  }
  if (kind == "polygon") {
    object_reader p(d, value[kind], shape.at(kind), {"vertices_m", "spacing_m"});
    const json* v = p.required("vertices_m", "[[0, 0], [0.1, 0], [0, 0.1]]");
    const auto vertices = v ? to_points(d, *v, p.at("vertices_m"), 3, "[[0, 0], [0.1, 0], [0, 0.1]]") : std::nullopt;
    const auto spacing = p.number("spacing_m", "1e-3");
    if (spacing && !check_positive(d, p.at("spacing_m"), *spacing, "1e-3")) return std::nullopt;
    if (!vertices || !spacing) return std::nullopt;
    return polygon_shape{*vertices, *spacing};
  }
  object_reader m(d, value[kind], shape.at(kind), {"file"});
  const auto file = m.text("file", "plate.msh");
  if (!file) return std::nullopt;
  const std::filesystem::path path = folder / *file;
  if (!std::filesystem::is_regular_file(path)) {
    d.error(m.at("file"), fmt::format("mesh file '{}' does not exist (looked for {}); give a path relative to the "
                                      "case file's folder", *file, path.string()));
    return std::nullopt;
  }
  return mesh_shape{path};
}

inline std::optional<constraint_description> read_constraint(diagnostics& d, const json& value, const std::string& at) {
  object_reader r(d, value, at, {"edge", "velocity_m_s"});
  const auto edge = r.text("edge", "left");
  const json* v = r.required("velocity_m_s", "[0, null]");
  if (!edge || !v) return std::nullopt;
  constraint_description c{*edge, {}, at};
  const std::string vat = r.at("velocity_m_s");
  if (!v->is_array() || v->size() != 2) {
    d.error(vat, fmt::format("expected [vx, vy] with null for a free component, got {}; give e.g. [0, null]",
                             describe(*v)));
    return std::nullopt;
  }
  for (int k = 0; k < 2; ++k)
    if (!(*v)[k].is_null()) {
      const auto x = to_number(d, (*v)[k], child_pointer(vat, k), "0 (held) or null (free)");
      if (!x) return std::nullopt;
      c.velocity[k] = *x;
    }
  if (!c.velocity[0] && !c.velocity[1]) {
    d.error(vat, "both components are null, so this constrains nothing; give a velocity for one of them or "
                 "remove the constraint");
    return std::nullopt;
  }
  return c;
}

}  // namespace detail

inline body_description read_body(diagnostics& d, const json& value, const std::string& at,
                                   const std::filesystem::path& folder, const constant_table& constants = {}) {
  object_reader r(d, value, at, {"name", "shape", "material", "initial_velocity_m_s", "body_force_m_s2",
                                 "constraints", "slaves"});
  body_description b;
  b.at = at;
  if (!r.valid()) return b;
  b.name = r.text("name", "bar").value_or("");
  if (const json* s = r.required("shape", "{\"rectangle\": {...}}"))
    if (auto shape = detail::read_shape(d, *s, r.at("shape"), folder)) b.shape = std::move(*shape);
  if (const json* m = r.required("material", "{\"law\": \"j2\", ...}"))
    b.material = detail::read_material(d, *m, r.at("material"));
  b.initial_velocity = vector_field_or(r, "initial_velocity_m_s", position_variables(), constants,
                                       "[0, -190] or [\"-w * y\", \"w * x\"] (x, y: the reference position, m)");
  b.body_force = vector_field_or(r, "body_force_m_s2", position_time_variables(), constants,
                                 "[0, -9.81] or [\"0\", \"-9.81 * min(1, t / 1e-3)\"] (x, y in m, t in s)");
  if (const json* cs = r.find("constraints")) {
    if (!cs->is_array())
      d.error(r.at("constraints"), fmt::format("expected a list of constraints, got {}; give e.g. "
                                               "[{{\"edge\": \"left\", \"velocity_m_s\": [0, null]}}]", describe(*cs)));
    else
      for (std::size_t i = 0; i < cs->size(); ++i)
        if (auto c = detail::read_constraint(d, (*cs)[i], child_pointer(r.at("constraints"), i)))
          b.constraints.push_back(*c);
  }
  if (const json* s = r.find("slaves"); s && s->is_object()) {
    object_reader layers(d, *s, r.at("slaves"), {"layers"});
    const auto k = layers.integer("layers", "3");
    if (k && *k < 1)
      d.error(layers.at("layers"), fmt::format("{} layers; give at least 1 (1: the surface particles), or \"all\"", *k));
    else if (k)
      b.slave_layers = *k;
  } else {
    const std::array<std::string_view, 2> slaves{"boundary", "all"};
    b.slave_layers = r.choice("slaves", slaves, "slave choice", "boundary").value_or("boundary") == "all" ? 0 : 1;
  }
  return b;
}

}  // namespace rkpm::runner::case_file
