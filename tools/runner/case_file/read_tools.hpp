#pragma once
// Reading one entry of "tools": a rigid polyline at t = 0, the side of it the body lies on,
// its prescribed translation (fixed, constant velocity, a velocity table, or a velocity given
// as expressions of t: read_expressions.hpp) and the deepest penetration its faces act on
// (contact/rigid_tool.hpp). Whether a tool starts inside the body is checked in cross_checks.hpp.

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "case_description.hpp"
#include "json_fields.hpp"
#include "read_expressions.hpp"
#include "vector_expression.hpp"

namespace rkpm::runner::case_file {

namespace detail {

inline tool_motion_description read_motion(diagnostics& d, const json& value, const std::string& at,
                                           const constant_table& constants) {
  static constexpr std::array<std::string_view, 4> types{"fixed", "constant_velocity", "velocity_table",
                                                         "velocity_expression"};
  const std::string type = value.is_object() && value.contains("type") && value["type"].is_string()
                               ? value["type"].get<std::string>() : "";
  std::vector<std::string_view> known{"type"};
  if (type != "fixed" && type != "velocity_table") known.push_back("velocity_m_s");
  if (type != "fixed" && type != "constant_velocity" && type != "velocity_expression") known.push_back("table");
  object_reader r(d, value, at, known);
  tool_motion_description m;
  if (!r.valid()) return m;
  m.type = r.choice("type", types, "motion type").value_or("fixed");
  if (m.type == "constant_velocity") {
    // Numbers, or expressions of the constants alone ("-v0"); one of t is a velocity_expression.
    if (const json* v = r.required("velocity_m_s", "[0, -10]"))
      if (auto f = to_vector_field(d, *v, r.at("velocity_m_s"), {}, constants,
                                   "[0, -10] (for a velocity that varies: \"type\": \"velocity_expression\")"))
        m.velocity = f->value;
  } else if (m.type == "velocity_expression") {
    const std::string example = "[\"0\", \"-10 * min(1, t / 1e-4)\"] (t: the time, s)";
    if (const json* v = r.required("velocity_m_s", example))
      if (auto f = to_vector_field(d, *v, r.at("velocity_m_s"), time_variables(), constants, example)) {
        const vector_expression velocity(*f, time_variables(), constants);
        if (const auto bad = velocity.not_finite(velocity(std::array{0.0}), "t = 0 s",
                                                 "make it finite from t = 0 (the tool's velocity at the start)"))
          d.error(bad->first, bad->second);
        m.velocity_expression = std::move(*f);
      }
  } else if (m.type == "velocity_table") {
    const std::string example = "[[0, 0, -10], [1e-3, 0, 0]] (rows: t_s, vx_m_s, vy_m_s)";
    const json* t = r.required("table", example);
    if (!t) return m;
    if (!t->is_array() || t->empty()) {
      d.error(r.at("table"), fmt::format("expected a list of rows [t_s, vx_m_s, vy_m_s], got {}; give e.g. {}",
                                         describe(*t), example));
      return m;
    }
    for (std::size_t i = 0; i < t->size(); ++i) {
      const json& row = (*t)[i];
      const std::string rat = child_pointer(r.at("table"), i);
      if (!row.is_array() || row.size() != 3 || !row[0].is_number() || !row[1].is_number() || !row[2].is_number()) {
        d.error(rat, fmt::format("expected a row [t_s, vx_m_s, vy_m_s], got {}; give e.g. [1e-3, 0, -10]",
                                 row.is_array() ? row.dump() : describe(row)));
        continue;
      }
      const std::array<double, 3> v{row[0].get<double>(), row[1].get<double>(), row[2].get<double>()};
      if (i == 0 && v[0] != 0.0)
        d.error(child_pointer(rat, 0), fmt::format("the table starts at t = {:g} s; start it at 0 (the velocity at "
                                                   "t = 0)", v[0]));
      if (i > 0 && !m.table.empty() && !(v[0] > m.table.back()[0]))
        d.error(child_pointer(rat, 0), fmt::format("t = {:g} s does not come after the previous row's {:g} s; give "
                                                   "the rows in increasing time", v[0], m.table.back()[0]));
      m.table.push_back(v);
    }
  }
  return m;
}

}  // namespace detail

inline tool_description read_tool(diagnostics& d, const json& value, const std::string& at,
                                   const constant_table& constants = {}) {
  object_reader r(d, value, at, {"name", "polyline_m", "body_side", "motion", "contact_depth_m"});
  tool_description t;
  t.at = at;
  if (!r.valid()) return t;
  t.name = r.text("name", "wall").value_or("");
  const std::string example = "[[-3.2e-3, 0], [25.6e-3, 0]]";
  if (const json* p = r.required("polyline_m", example))
    t.polyline = to_points(d, *p, r.at("polyline_m"), 2, example).value_or(std::vector<vec2>{});
  for (std::size_t k = 0; k + 1 < t.polyline.size(); ++k)
    if (t.polyline[k] == t.polyline[k + 1])
      d.error(child_pointer(r.at("polyline_m"), k + 1),
              fmt::format("vertex {} repeats vertex {} ({:g}, {:g}), a segment of zero length; remove it", k + 1, k,
                          t.polyline[k].x(), t.polyline[k].y()));
  static constexpr std::array<std::string_view, 2> sides{"left", "right"};
  t.body_on_left = r.choice("body_side", sides, "body side").value_or("left") == "left";
  if (const json* m = r.find("motion")) t.motion = detail::read_motion(d, *m, r.at("motion"), constants);
  t.contact_depth = r.number_or("contact_depth_m", 0.0);
  check_non_negative(d, r.at("contact_depth_m"), t.contact_depth, "2e-3 (0 picks half the shortest segment)");
  return t;
}

}  // namespace rkpm::runner::case_file
