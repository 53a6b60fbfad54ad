#pragma once
// attach_heat: the case file's "heat" (read_heat.hpp) as a thermal::heat_coupling attached to
// the run's solver (include/rkpm/thermal/heat_coupling.hpp, docs/method.md 5.11): each body's
// conduction, the tools' temperatures, the edges' conditions. Called once the solver is in its
// place and before a checkpoint is read into it (simulate.hpp, file_case.hpp).

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include <rkpm/thermal/heat_coupling.hpp>

#include "body_edges.hpp"
#include "build_problem.hpp"
#include "case_description.hpp"
#include "expressions.hpp"

namespace rkpm::runner::case_file {

namespace detail {

// The material's own heating constants, when it has them (Johnson-Cook, Zerilli-Armstrong).
struct material_heating {
  std::optional<double> specific_heat, initial_temperature, taylor_quinney;
};
inline material_heating heating_of(const material_description& m) {
  if (m.johnson_cook) {
    const auto& h = m.johnson_cook->heating();
    return {h.specific_heat, h.initial_temperature, h.taylor_quinney};
  }
  if (m.zerilli_armstrong) {
    const auto& h = m.zerilli_armstrong->heating();
    return {h.specific_heat, h.initial_temperature, h.taylor_quinney};
  }
  return {};
}

// An expression of one variable (checked when the file was read) as a function; evaluated on one
// thread (heat_conduction evaluates k(T) and c_p(T) before its parallel loops).
inline std::function<double(double)> function_of(const case_description& c, const std::string& at,
                                                 const std::string& text, const std::string& variable) {
  std::string why;
  auto e = expression::parse(text, {variable}, c.constants, why);
  if (!e) fail_at(c, at, why);
  auto shared = std::make_shared<expression>(std::move(*e));
  return [shared](double v) { return (*shared)(std::span<const double>(&v, 1)); };
}

}  // namespace detail

template <class Solver>
void attach_heat(Solver& s, const case_description& c) {
  const heat_description& h = c.heat;
  if (!h.enabled) return;
  const discrete_model& m = s.model();
  const std::string bodies_at = child_pointer(h.at, "bodies");
  for (const auto& [name, entry] : h.bodies)
    if (std::none_of(c.bodies.begin(), c.bodies.end(), [&](const body_description& b) { return b.name == name; }))
      fail_at(c, entry.at, fmt::format("no body is named '{}'", name));
  std::vector<thermal::thermal_properties> props;
  std::vector<double> beta, initial(m.particle_count(), 0.0);
  for (std::size_t k = 0; k < c.bodies.size(); ++k) {
    const body_description& b = c.bodies[k];
    const auto it = h.bodies.find(b.name);
    if (it == h.bodies.end())
      fail_at(c, bodies_at, fmt::format("body '{}' has no conduction: give \"{}\": {{\"conductivity_W_mK\": ...}}",
                                        b.name, b.name));
    const heat_body_description& hb = it->second;
    const detail::material_heating own = detail::heating_of(b.material);
    const auto c_p = hb.specific_heat ? hb.specific_heat : own.specific_heat;
    const auto T0 = hb.initial_temperature ? hb.initial_temperature : own.initial_temperature;
    if (!c_p && hb.specific_heat_of_T.empty())
      fail_at(c, hb.at, "give \"specific_heat_J_kgK\": the body's material has none (e.g. 600 for hot steel)");
    if (!T0 || !std::isfinite(*T0))
      fail_at(c, hb.at, "give \"initial_temperature_K\": the body's material has none (e.g. 1373)");
    thermal::thermal_properties p{.conductivity = hb.conductivity.value_or(0.0), .specific_heat = *c_p};
    if (!hb.conductivity_of_T.empty())
      p.conductivity_of_T = detail::function_of(c, hb.at, hb.conductivity_of_T, "T");
    if (!hb.specific_heat_of_T.empty())
      p.specific_heat_of_T = detail::function_of(c, hb.at, hb.specific_heat_of_T, "T");
    props.push_back(std::move(p));
    beta.push_back(hb.taylor_quinney.value_or(own.taylor_quinney.value_or(0.9)));
    for (index_t I : m.bodies.particles_of(static_cast<index_t>(k))) initial[I] = *T0;
  }
  thermal::tool_heat tools{.conductance = h.conductance, .friction_to_body = h.friction_to_body};
  const auto& solver_tools = s.contact().tools();
  for (const auto& [name, T] : h.tool_temperature)
    if (std::none_of(solver_tools.begin(), solver_tools.end(), [&](const auto& t) { return t.name() == name; }))
      fail_at(c, child_pointer(h.at, "tools"), fmt::format("no tool is named '{}'", name));
  if (!h.tool_temperature.empty())
    for (const auto& tool : solver_tools) {
      const auto it = h.tool_temperature.find(tool.name());
      if (it == h.tool_temperature.end())
        fail_at(c, child_pointer(h.at, "tools"),
                fmt::format("tool '{}' has no temperature: give every tool one (or none)", tool.name()));
      const auto of_t = h.tool_temperature_of_t.find(tool.name());
      if (of_t != h.tool_temperature_of_t.end())
        tools.temperature.emplace_back(detail::function_of(c, child_pointer(child_pointer(h.at, "tools"), tool.name()),
                                                           of_t->second, "t"));
      else
        tools.temperature.emplace_back(it->second);
    }
  std::vector<thermal::thermal_boundary> edges;
  for (const heat_edge_description& e : h.edges) {
    const auto body = std::find_if(c.bodies.begin(), c.bodies.end(), [&](const auto& b) { return b.name == e.body; });
    if (body == c.bodies.end()) fail_at(c, e.at, fmt::format("no body is named '{}'", e.body));
    const auto k = static_cast<index_t>(body - c.bodies.begin());
    const std::vector<index_t> particles = m.bodies.particles_of(k);
    std::vector<vec2> X;
    for (index_t I : particles) X.push_back(m.particles.position[I]);
    std::vector<index_t> on_edge;
    for (index_t i : particles_on_edge(*body, X, e.edge)) on_edge.push_back(particles[i]);
    if (on_edge.empty()) fail_at(c, e.at, fmt::format("body '{}' has no edge '{}'", e.body, e.edge));
    const auto kind = e.kind == "convection"    ? thermal::boundary_kind::convection
                      : e.kind == "temperature" ? thermal::boundary_kind::fixed_temperature
                                                : thermal::boundary_kind::heat_flux;
    for (const boundary_chain& chain : m.bodies.surface("heat on the case file's edges"))
      if (chain.body == k)
        for (const thermal::chain_run& run : thermal::chain_runs(chain, on_edge))
          if (run.particle.size() > 1)
            edges.push_back(thermal::thermal_boundary::on_chain(kind, run.particle, m.particles.position, run.closed,
                                                                e.value, e.film_coefficient));
  }
  try {
    auto heat = std::make_shared<thermal::heat_coupling<Solver>>(s, std::move(props), std::move(beta), initial[0],
                                                                 std::move(edges), std::move(tools));
    heat->set_temperatures(s, std::move(initial));
    s.attach(std::move(heat));
  } catch (const error& e) {
    fail_at(c, h.at, e.what());
  }
}

}  // namespace rkpm::runner::case_file
