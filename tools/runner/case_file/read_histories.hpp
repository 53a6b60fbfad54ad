#pragma once
// Reading "histories": the named measures written to history.csv over time and to
// summary.json at the end. Each entry is {"name": ..., KIND: {...}} with exactly one KIND:
//   extent              max/min/width of the particles' current x or y, optionally only those
//                       that started on an edge or that lie beyond bounds now (0 if none)
//   tool_gap            lowest vertex of one tool minus highest of another, along x or y
//   tool_force          a tool's reaction averaged over the last output interval
//   tool_displacement   a tool's translation since t = 0
//   probe               position, displacement or velocity of the particle nearest a point
//   max_plastic_strain  largest equivalent plastic strain of the quadrature points
//   max_temperature     largest temperature of the quadrature points, K ("law": "johnson_cook")
//   failed_fraction     fraction of the quadrature points that have failed (Johnson-Cook damage)
//   max_penetration     deepest penetration of a tool so far
//   volume_change       sum_q J_q w_q / sum_q w_q - 1
//   momentum            a body's linear momentum, sum_I m_I v_I (x or y)
// Every kind takes "scale" (default 1: 1e3 turns m into mm). Names of bodies, tools and edges
// are checked against the case in cross_checks.hpp.

#include <array>
#include <cmath>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "case_description.hpp"
#include "json_fields.hpp"

namespace rkpm::runner::case_file {

inline constexpr std::array<std::string_view, 11> history_kinds{
    "extent", "tool_gap", "tool_force", "tool_displacement", "probe", "max_plastic_strain", "max_penetration",
    "volume_change", "momentum", "max_temperature", "failed_fraction"};

namespace detail {

inline int read_component(const object_reader& r) {
  static constexpr std::array<std::string_view, 2> xy{"x", "y"};
  return r.choice("component", xy, "component", "y").value_or("y") == "x" ? 0 : 1;
}

inline history_kind read_history_kind(const object_reader& r, std::string_view kind) {
  diagnostics& d = r.diag();
  if (kind == "extent") {
    static constexpr std::array<std::string_view, 6> ofs{"max_x", "min_x", "max_y", "min_y", "width_x", "width_y"};
    extent_history h{r.text("body", "bar").value_or(""), r.choice("of", ofs, "extent").value_or("max_x"),
                     r.text_or("on_edge", "")};
    if (const json* w = r.find("where")) {
      object_reader bounds(d, *w, r.at("where"), {"x_below_m", "x_above_m", "y_below_m", "y_above_m"});
      h.x_below = bounds.number_or("x_below_m", NAN);
      h.x_above = bounds.number_or("x_above_m", NAN);
      h.y_below = bounds.number_or("y_below_m", NAN);
      h.y_above = bounds.number_or("y_above_m", NAN);
    }
    return h;
  }
  if (kind == "tool_gap")
    return tool_gap_history{r.text("from", "bottom_tool").value_or(""), r.text("to", "top_tool").value_or(""),
                            read_component(r)};
  if (kind == "tool_force")
    return tool_force_history{r.text("tool", "top_tool").value_or(""), read_component(r),
                              r.boolean_or("absolute", false)};
  if (kind == "tool_displacement")
    return tool_displacement_history{r.text("tool", "punch").value_or(""), read_component(r)};
  if (kind == "probe") {
    static constexpr std::array<std::string_view, 3> quantities{"position", "displacement", "velocity"};
    probe_history h{r.text("body", "bar").value_or(""), r.choice("quantity", quantities, "quantity").value_or("")};
    h.point = r.point("point_m", "[0, 0]").value_or(vec2::Zero());
    h.component = read_component(r);
    return h;
  }
  if (kind == "max_plastic_strain") return max_plastic_strain_history{r.text("body", "bar").value_or("")};
  if (kind == "max_temperature") return max_temperature_history{r.text("body", "bar").value_or("")};
  if (kind == "failed_fraction") return failed_fraction_history{r.text("body", "bar").value_or("")};
  if (kind == "max_penetration") return max_penetration_history{};
  if (kind == "momentum") return momentum_history{r.text("body", "bar").value_or(""), read_component(r)};
  return volume_change_history{r.text("body", "slug").value_or("")};
}

// The fields each kind takes (besides "scale").
inline std::vector<std::string_view> history_fields(std::string_view kind) {
  if (kind == "extent") return {"body", "of", "on_edge", "where"};
  if (kind == "tool_gap") return {"from", "to", "component"};
  if (kind == "tool_force") return {"tool", "component", "absolute"};
  if (kind == "tool_displacement") return {"tool", "component"};
  if (kind == "probe") return {"body", "point_m", "quantity", "component"};
  if (kind == "max_penetration") return {};
  if (kind == "momentum") return {"body", "component"};
  return {"body"};
}

}  // namespace detail

inline std::vector<history_description> read_histories(diagnostics& d, const json& value, const std::string& at) {
  std::vector<history_description> out;
  if (!value.is_array()) {
    d.error(at, fmt::format("expected a list of histories, got {}; give e.g. [{{\"name\": \"height_mm\", "
                            "\"extent\": {{\"body\": \"bar\", \"of\": \"max_y\", \"scale\": 1e3}}}}]", describe(value)));
    return out;
  }
  // Columns the runner writes itself next to the histories.
  std::set<std::string> taken{"time_s", "kinetic_J", "internal_J", "plastic_J", "contact_J", "external_J",
                              "balance_error"};
  for (std::size_t i = 0; i < value.size(); ++i) {
    const std::string hat = child_pointer(at, i);
    std::vector<std::string_view> known{"name"};
    known.insert(known.end(), history_kinds.begin(), history_kinds.end());
    object_reader r(d, value[i], hat, known);
    if (!r.valid()) continue;
    history_description h;
    h.at = hat;
    h.name = r.text("name", "height_mm").value_or("");
    if (r.find("name") && !h.name.empty()) {
      if (h.name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") !=
          std::string::npos)
        d.error(r.at("name"), fmt::format("'{}' is not a plain column name; use letters, digits and '_' (e.g. "
                                          "\"height_mm\")", h.name));
      else if (!taken.insert(h.name).second)
        d.error(r.at("name"), fmt::format("the name '{}' is already taken (another history or a column the runner "
                                          "writes: time_s and the energies); give another", h.name));
    } else if (r.find("name")) {
      d.error(r.at("name"), "the name is empty; give a column name such as \"height_mm\"");
    }
    std::vector<std::string_view> kinds;
    for (auto k : history_kinds)
      if (r.find(k)) kinds.push_back(k);
    if (kinds.size() != 1) {
      d.error(hat, fmt::format("give exactly one kind of measure (found {}): {}",
                               kinds.empty() ? std::string("none") : list_choices(kinds), list_choices(history_kinds)));
      continue;
    }
    auto fields = detail::history_fields(kinds[0]);
    fields.push_back("scale");
    object_reader kr(d, *r.find(kinds[0]), r.at(kinds[0]), fields);
    if (!kr.valid()) continue;
    h.kind = detail::read_history_kind(kr, kinds[0]);
    h.scale = kr.number_or("scale", 1.0);
    out.push_back(std::move(h));
  }
  return out;
}

}  // namespace rkpm::runner::case_file
