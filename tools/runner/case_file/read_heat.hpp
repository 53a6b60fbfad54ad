#pragma once
// The case file's "heat": heat conduction coupled to the run (docs/method.md sections 5.9 and
// 5.11, include/rkpm/thermal/heat_coupling.hpp):
//   "heat": {
//     "bodies": {"billet": {"conductivity_W_mK": 30, "specific_heat_J_kgK": 600,
//                           "initial_temperature_K": 1373, "taylor_quinney": 0.9}},
//     "tools": {"top_die": 473, "bottom_die": 473},        // K, every tool or none
//     "conductance_W_m2K": 2e4, "friction_heat_to_body": 0.5,
//     "edges": [{"body": "billet", "edge": "left", "convection": {"h_W_m2K": 30, "ambient_K": 300}},
//               {"body": "billet", "edge": "right", "temperature_K": 1373},
//               {"body": "billet", "edge": "top", "flux_W_m2": 1e4}]
//   }
// The conductivity and specific heat may be expressions of the temperature T (K), "30 + 0.01 * (T -
// 300)", a tool's temperature an expression of the time t (s), "473 + 2000 * t", with the file's
// constants. A Johnson-Cook or Zerilli-Armstrong body's specific heat, initial temperature and Taylor-Quinney
// fraction default to its material's; a J2 or elastic body must give the first two. Names are
// checked against the bodies and tools when the run is built (build_heat.hpp).

#include <limits>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "diagnostics.hpp"
#include "expressions.hpp"
#include "heat_description.hpp"
#include "json_fields.hpp"

namespace rkpm::runner::case_file {

namespace detail {

inline bool positive_at(diagnostics& d, const object_reader& r, std::string_view key, double v, std::string_view fix) {
  if (r.find(key) && !(v > 0.0)) {
    d.error(r.at(key), fmt::format("{} is not positive; give {}", v, fix));
    return false;
  }
  return true;
}

inline heat_edge_description read_heat_edge(diagnostics& d, const json& value, const std::string& at) {
  object_reader r(d, value, at, {"body", "edge", "convection", "temperature_K", "flux_W_m2"});
  heat_edge_description e;
  e.at = at;
  if (!r.valid()) return e;
  e.body = r.text("body", "billet").value_or("");
  e.edge = r.text("edge", "left").value_or("");
  const int kinds = (r.find("convection") ? 1 : 0) + (r.find("temperature_K") ? 1 : 0) + (r.find("flux_W_m2") ? 1 : 0);
  if (kinds != 1) {
    d.error(at, "give one of \"convection\": {\"h_W_m2K\": 30, \"ambient_K\": 300}, \"temperature_K\" or \"flux_W_m2\"");
    return e;
  }
  if (const json* c = r.find("convection")) {
    object_reader cr(d, *c, r.at("convection"), {"h_W_m2K", "ambient_K"});
    e.kind = "convection";
    e.film_coefficient = cr.number("h_W_m2K", "30").value_or(0.0);
    e.value = cr.number("ambient_K", "300").value_or(0.0);
    positive_at(d, cr, "h_W_m2K", e.film_coefficient, "the film coefficient h, e.g. 30 W/(m^2 K) for still air");
    positive_at(d, cr, "ambient_K", e.value, "the air's temperature in kelvin, e.g. 300");
  } else if (r.find("temperature_K")) {
    e.kind = "temperature";
    e.value = r.number("temperature_K", "473").value_or(0.0);
    positive_at(d, r, "temperature_K", e.value, "the edge's temperature in kelvin, e.g. 473");
  } else {
    e.kind = "flux";
    e.value = r.number("flux_W_m2", "1e4").value_or(0.0);  // into the body; negative: out
  }
  return e;
}

// A number, or an expression of `variable` (a string); an expression that names no variable is
// the number it gives. Returns the number (NaN for an expression) and sets `text` for an expression.
inline double number_or_expression(diagnostics& d, const json& v, const std::string& at, const std::string& variable,
                                   const constant_table& constants, std::string& text) {
  if (v.is_number()) return v.get<double>();
  if (!v.is_string()) {
    d.error(at, fmt::format("expected a number or an expression of {} (a string), got {}", variable, describe(v)));
    return 0.0;
  }
  std::string why;
  const auto e = expression::parse(v.get<std::string>(), {variable}, constants, why);
  if (!e) {
    d.error(at, why);
    return 0.0;
  }
  if (!e->uses_variables()) return (*e)(std::span<const double>{});
  text = e->text();
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace detail

inline heat_description read_heat(diagnostics& d, const json& value, const std::string& at,
                                  const constant_table& constants = {}) {
  heat_description h;
  h.at = at;
  object_reader r(d, value, at, {"bodies", "tools", "conductance_W_m2K", "friction_heat_to_body", "edges"});
  if (!r.valid()) return h;
  h.enabled = true;
  if (const json* bodies = r.required("bodies", "{\"billet\": {\"conductivity_W_mK\": 30}}")) {
    if (!bodies->is_object() || bodies->empty())
      d.error(r.at("bodies"), "give each body's conduction by its name, e.g. {\"billet\": {\"conductivity_W_mK\": 30}}");
    else
      for (const auto& [name, entry] : bodies->items()) {
        const std::string where = child_pointer(r.at("bodies"), name);
        object_reader b(d, entry, where, {"conductivity_W_mK", "specific_heat_J_kgK", "initial_temperature_K",
                                          "taylor_quinney"});
        if (!b.valid()) continue;
        heat_body_description& hb = h.bodies[name];
        hb.at = where;
        if (const json* k = b.required("conductivity_W_mK", "30 or \"30 + 0.01 * (T - 300)\""))
          hb.conductivity = detail::number_or_expression(d, *k, b.at("conductivity_W_mK"), "T", constants,
                                                         hb.conductivity_of_T);
        if (hb.conductivity && hb.conductivity_of_T.empty() && !(*hb.conductivity >= 0.0))
          d.error(b.at("conductivity_W_mK"), fmt::format("{} is negative; give the conductivity k >= 0, e.g. 30 "
                                                         "W/(m K) for steel", *hb.conductivity));
        if (const json* c_p = b.find("specific_heat_J_kgK"))
          hb.specific_heat = detail::number_or_expression(d, *c_p, b.at("specific_heat_J_kgK"), "T", constants,
                                                          hb.specific_heat_of_T);
        if (b.find("initial_temperature_K")) hb.initial_temperature = b.number_or("initial_temperature_K", 0.0);
        if (b.find("taylor_quinney")) hb.taylor_quinney = b.number_or("taylor_quinney", 0.9);
        if (hb.specific_heat && hb.specific_heat_of_T.empty())
          detail::positive_at(d, b, "specific_heat_J_kgK", *hb.specific_heat, "c_p, e.g. 600 J/(kg K) for hot steel");
        if (hb.initial_temperature)
          detail::positive_at(d, b, "initial_temperature_K", *hb.initial_temperature, "a temperature in kelvin");
        if (hb.taylor_quinney && !(*hb.taylor_quinney >= 0.0 && *hb.taylor_quinney <= 1.0))
          d.error(b.at("taylor_quinney"), fmt::format("{} is not a fraction; give beta in [0, 1], usually 0.9",
                                                      *hb.taylor_quinney));
      }
  }
  if (const json* tools = r.find("tools")) {
    if (!tools->is_object())
      d.error(r.at("tools"), "give each tool's temperature by its name, e.g. {\"top_die\": 473}");
    else
      for (const auto& [name, T] : tools->items()) {
        const std::string where = child_pointer(r.at("tools"), name);
        std::string of_t;
        const double value = detail::number_or_expression(d, T, where, "t", constants, of_t);
        if (!of_t.empty()) h.tool_temperature_of_t[name] = of_t;
        else if (!(value > 0.0)) d.error(where, fmt::format("expected a temperature in kelvin (> 0), got {}", describe(T)));
        h.tool_temperature[name] = value;
      }
  }
  h.conductance = r.number_or("conductance_W_m2K", 0.0);
  if (r.find("conductance_W_m2K") && !(h.conductance >= 0.0))
    d.error(r.at("conductance_W_m2K"), fmt::format("{} is negative; give the interface conductance h_c >= 0, e.g. "
                                                   "2e4 W/(m^2 K)", h.conductance));
  if (!h.tool_temperature.empty() && !r.find("conductance_W_m2K"))
    d.error(at, "the tools have temperatures: give \"conductance_W_m2K\", the interface conductance (e.g. 2e4)");
  h.friction_to_body = r.number_or("friction_heat_to_body", 0.5);
  if (!(h.friction_to_body >= 0.0 && h.friction_to_body <= 1.0))
    d.error(r.at("friction_heat_to_body"), fmt::format("{} is not a fraction; give the share of the frictional heat "
                                                       "that enters the body, in [0, 1]", h.friction_to_body));
  if (const json* edges = r.find("edges")) {
    if (!edges->is_array())
      d.error(r.at("edges"), fmt::format("expected a list of edges, got {}", describe(*edges)));
    else
      for (std::size_t i = 0; i < edges->size(); ++i)
        h.edges.push_back(detail::read_heat_edge(d, (*edges)[i], child_pointer(r.at("edges"), i)));
  }
  return h;
}

}  // namespace rkpm::runner::case_file
