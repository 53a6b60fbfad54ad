#pragma once
// Reading the top level of a case file into a case_description: name, constants, geometry, method,
// support factor, end time, bodies, tools, contact, output and histories. Each part reports
// its own mistakes through diagnostics; checks across parts are in cross_checks.hpp.

#include <array>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include <rkpm/geometry/axisymmetric.hpp>
#include <rkpm/geometry/plane_strain.hpp>

#include "../methods.hpp"
#include "case_description.hpp"
#include "json_fields.hpp"
#include "read_body.hpp"
#include "read_expressions.hpp"
#include "read_heat.hpp"
#include "read_histories.hpp"
#include "read_tools.hpp"

namespace rkpm::runner::case_file {

namespace detail {

inline method_choice read_method(diagnostics& d, const json* value, const std::string& at) {
  method_choice m{std::string(paper_kernel::name), std::string(paper_correction::name),
                  std::string(paper_quadrature::name), std::string(paper_enforcement::name)};
  if (!value) return m;
  object_reader r(d, *value, at, {"kernel", "correction", "quadrature", "contact"});
  m.kernel = r.choice("kernel", policy_names(kernels), "kernel", m.kernel).value_or(m.kernel);
  m.correction = r.choice("correction", policy_names(corrections), "correction", m.correction).value_or(m.correction);
  m.quadrature = r.choice("quadrature", policy_names(quadratures), "quadrature", m.quadrature).value_or(m.quadrature);
  m.contact = r.choice("contact", policy_names(enforcements), "contact enforcement", m.contact).value_or(m.contact);
  return m;
}

// Reads each entry of a list with `read(diagnostics, entry, pointer)`.
template <class Read>
auto read_list(diagnostics& d, const json& value, const std::string& at, std::string_view example, Read&& read) {
  std::vector<decltype(read(d, value, at))> out;
  if (!value.is_array()) {
    d.error(at, fmt::format("expected a list [...], got {}; give e.g. {}", describe(value), example));
    return out;
  }
  for (std::size_t i = 0; i < value.size(); ++i) out.push_back(read(d, value[i], child_pointer(at, i)));
  return out;
}

inline body_pair_description read_body_pair(diagnostics& d, const json& value, const std::string& at) {
  object_reader r(d, value, at, {"slave", "master"});
  return {r.text("slave", "plate").value_or(""), r.text("master", "projectile").value_or(""), at};
}

}  // namespace detail

inline case_description read_case(diagnostics& d, const json& document, const std::filesystem::path& file) {
  case_description c;
  c.file = file;
  c.document = document;
  object_reader r(d, document, "", {"name", "description", "constants", "geometry", "method", "support_factor",
                                    "end_time_s", "bodies", "tools", "contact", "output", "histories",
                                    "rereference", "mass_scaling", "heat"});
  if (!r.valid()) return c;
  c.name = r.text("name", "taylor_bar").value_or("");
  if (c.name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-") != std::string::npos)
    d.error(r.at("name"), fmt::format("'{}' would not make a file name; use letters, digits, '_' and '-'", c.name));
  c.description = r.text_or("description", "");
  c.constants = read_constants(d, r.find("constants"), r.at("constants"));
  const std::array<std::string_view, 2> geometries{geometry::plane_strain::name, geometry::axisymmetric::name};
  c.geometry = r.choice("geometry", geometries, "geometry").value_or("");
  c.method = detail::read_method(d, r.find("method"), r.at("method"));
  c.support_factor = r.number_or("support_factor", 2.0);
  check_positive(d, r.at("support_factor"), c.support_factor, "2 (support a = factor x particle spacing)");
  if (const auto t = r.number("end_time_s", "80e-6")) {
    c.end_time = *t;
    check_positive(d, r.at("end_time_s"), *t, "80e-6");
  }

  const std::filesystem::path folder = file.parent_path();
  if (const json* b = r.required("bodies", "[{\"name\": \"bar\", \"shape\": ..., \"material\": ...}]")) {
    c.bodies = detail::read_list(d, *b, r.at("bodies"), "[{\"name\": \"bar\", ...}]",
                                 [&](diagnostics& dd, const json& v, const std::string& at) {
                                   return read_body(dd, v, at, folder, c.constants);
                                 });
    if (b->is_array() && b->empty()) d.error(r.at("bodies"), "the list is empty; give the deformable body");
  }
  if (const json* t = r.find("tools"))
    c.tools = detail::read_list(d, *t, r.at("tools"), "[{\"name\": \"wall\", \"polyline_m\": ...}]",
                                [&](diagnostics& dd, const json& v, const std::string& at) {
                                  return read_tool(dd, v, at, c.constants);
                                });
  if (const json* k = r.find("contact")) {
    object_reader cr(d, *k, r.at("contact"), {"friction", "penalty_stiffness_N_m", "pairs", "two_pass", "self"});
    c.friction = cr.number_or("friction", 0.0);
    if (const json* pairs = cr.find("pairs"))
      c.body_pairs = detail::read_list(d, *pairs, cr.at("pairs"), "[{\"slave\": \"plate\", \"master\": \"projectile\"}]",
                                       detail::read_body_pair);
    c.two_pass = cr.boolean_or("two_pass", false);
    c.self_contact = cr.boolean_or("self", false);
    check_non_negative(d, cr.at("friction"), c.friction, "0.2 (Coulomb coefficient; 0 is frictionless)");
    if (cr.find("penalty_stiffness_N_m")) {
      c.penalty_stiffness = cr.number_or("penalty_stiffness_N_m", 1e11);
      check_positive(d, cr.at("penalty_stiffness_N_m"), *c.penalty_stiffness, "1e11");
    }
  }
  if (const json* o = r.find("output")) {
    object_reader orr(d, *o, r.at("output"), {"snapshots", "history_rows"});
    c.snapshots = orr.integer_or("snapshots", 20);
    c.history_rows = orr.integer_or("history_rows", 400);
    if (c.snapshots < 0) d.error(orr.at("snapshots"), fmt::format("{} snapshots; give 0 (none) or more", c.snapshots));
    if (c.history_rows < 1) d.error(orr.at("history_rows"), fmt::format("{} rows; give at least 1", c.history_rows));
  }
  if (const json* h = r.find("histories")) c.histories = read_histories(d, *h, r.at("histories"));
  if (const json* k = r.find("rereference")) {
    // When the kernels are rebuilt in the current configuration (docs/method.md section 5.8).
    object_reader rr(d, *k, r.at("rereference"), {"max_stretch", "every_steps", "rebalance_above"});
    c.rereference.max_stretch = rr.number_or("max_stretch", 0.0);
    c.rereference.every_steps = rr.integer_or("every_steps", 0);
    c.rereference.rebalance_above = rr.number_or("rebalance_above", c.rereference.rebalance_above);
    if (rr.find("max_stretch") && !(c.rereference.max_stretch > 1.0))
      d.error(rr.at("max_stretch"), fmt::format("{} is not above 1; give the principal stretch since the last "
                                                "reference that triggers a re-reference, e.g. 1.8",
                                                c.rereference.max_stretch));
    if (rr.find("every_steps") && c.rereference.every_steps < 1)
      d.error(rr.at("every_steps"), fmt::format("{} steps; give at least 1 (1 rebuilds every step)",
                                                c.rereference.every_steps));
    if (rr.find("rebalance_above") && !(c.rereference.rebalance_above >= 1.0))
      d.error(rr.at("rebalance_above"), fmt::format("{} is below 1; give the most loaded process's work over the mean "
                                                    "above which several processes partition again, e.g. 1.1",
                                                    c.rereference.rebalance_above));
    if (!rr.find("max_stretch") && !rr.find("every_steps"))
      d.error(r.at("rereference"), "give \"max_stretch\" (e.g. 1.8) or \"every_steps\" (e.g. 50)");
  }
  if (const json* k = r.find("heat")) c.heat = read_heat(d, *k, r.at("heat"), c.constants);
  if (const json* k = r.find("mass_scaling")) {
    // Masses scaled for a process slower than the waves (docs/method.md section 5.10).
    object_reader mr(d, *k, r.at("mass_scaling"), {"factor", "target_dt_s", "max_kinetic_to_internal"});
    mass_scaling_policy& m = c.mass_scaling;
    m.factor = mr.number_or("factor", 1.0);
    m.target_time_step = mr.number_or("target_dt_s", 0.0);
    m.max_kinetic_to_internal = mr.number_or("max_kinetic_to_internal", m.max_kinetic_to_internal);
    if (mr.find("factor") && !(m.factor >= 1.0))
      d.error(mr.at("factor"), fmt::format("{} is below 1; give the factor on every mass, e.g. 100", m.factor));
    if (mr.find("target_dt_s") && !(m.target_time_step > 0.0))
      d.error(mr.at("target_dt_s"), fmt::format("{} s is not positive; give the time step wanted, e.g. 2e-6",
                                                m.target_time_step));
    if (mr.find("max_kinetic_to_internal") && !(m.max_kinetic_to_internal > 0.0))
      d.error(mr.at("max_kinetic_to_internal"),
              fmt::format("{} is not positive; give the bound of the quasi-static regime, e.g. 0.05",
                          m.max_kinetic_to_internal));
    if (mr.find("factor") && mr.find("target_dt_s"))
      d.error(r.at("mass_scaling"), "give \"factor\" or \"target_dt_s\", not both");
    if (!mr.find("factor") && !mr.find("target_dt_s"))
      d.error(r.at("mass_scaling"), "give \"factor\" (e.g. 100) or \"target_dt_s\" (e.g. 2e-6)");
  }
  return c;
}

}  // namespace rkpm::runner::case_file
