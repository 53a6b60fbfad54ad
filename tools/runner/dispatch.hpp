#pragma once
// The run-time dispatch of `rkpm_run CASE --kernel K --correction C --quadrature Q --contact E`:
// the case fixes geometry and material, the enforcement picks one of three compiled solver
// types from a table built with Boost.Hana (methods.hpp), and kernel, correction and rule are
// chosen at run time by the library's builder (rkpm/solver/make_model.hpp, compiled once per
// geometry: models.hpp), since they change the model's tables, not the solver's type. Coulomb friction (coefficient 0 is frictionless) serves every
// case.

#include <boost/hana.hpp>
#include <map>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <rkpm/solver/discrete_model.hpp>
#include <rkpm/solver/make_solver.hpp>
#include <rkpm/solver/policies.hpp>

#include "case_list.hpp"
#include "cases/parameters.hpp"
#include "memory_estimate.hpp"
#include "methods.hpp"
#include "models.hpp"
#include "outcome.hpp"
#include "request.hpp"
#include "run_record.hpp"
#include "simulate.hpp"

namespace rkpm::runner {

template <class Case, class E>
run_outcome run_with(const run_request& r, const typename Case::parameters& p, const std::optional<restart_point>& restart) {
  using G = typename Case::geometry_type;
  using M = typename Case::material_type;
  using Ct = contact::particle_to_segment<E, contact::friction::coulomb>;
  using Solver = explicit_solver<G, M, Ct>;
  run_options options;
  options.end_time = Case::end_time(p);
  options.max_steps = r.max_steps;
  const rkpm::method_names method{r.kernel, r.correction, r.quadrature};
  const std::function<Solver()> make = [&] {
    problem<M, Ct> pr = Case::template build<Ct>(p, r.resolution);
    warn_if_too_large(pr.particles.size(), quadrature_point_count(r.quadrature, pr.mesh.cells(),
                                                                  static_cast<index_t>(pr.mesh.node.size())));
    return make_solver<G>(method, std::move(pr), options);
  };
  return simulate<Case, Solver>(r, p,
                                {r.kernel, r.correction, r.quadrature, G::name, E::name,
                                 method.configuration_name<G, M, Ct>()},
                                make, restart);
}

template <class Case>
using run_function = run_outcome (*)(const run_request&, const typename Case::parameters&,
                                     const std::optional<restart_point>&);

// Contact enforcement name -> the run function with that enforcement (the solver's type);
// kernel, correction and quadrature rule are chosen inside, at run time (models.hpp).
template <class Case>
std::map<std::string, run_function<Case>> dispatch_table() {
  std::map<std::string, run_function<Case>> table;
  hana::for_each(enforcements, [&](auto t) {
    using E = typename decltype(t)::type;
    table[std::string(E::name)] = &run_with<Case, E>;
  });
  return table;
}

// Runs the case named by the request, with its parameters from --set and --end-time (the
// parser has checked them), or continues the checkpoint --restart names with the policies,
// resolution and parameters it was started with; declared in case_list.hpp, instantiated in
// run_CASE.cpp.
template <class Case>
run_outcome run_case(const run_request& request) {
  run_request r = request;
  typename Case::parameters p;
  std::optional<restart_point> restart;
  if (!r.restart.empty()) {
    restart = find_restart_point(r.restart);
    if (restart->description.contains("case_file"))
      fail("--restart {}: the checkpoint is of the case file {}: rkpm_run {} --restart {}", r.restart,
           restart->description.at("case_file").get<std::string>(),
           restart->description.at("case_file").get<std::string>(), r.restart);
    adopt_checkpoint_run(r, restart->description, Case::name);
    for (const auto& [name, value] : restart->description.at("parameters").items())
      cases::set_parameter(p, name, value.dump());
    if (r.out_dir.empty()) r.out_dir = std::filesystem::absolute(restart->file).parent_path().string();
  }
  for (const auto& [name, value] : r.sets) cases::set_parameter(p, name, value);
  // --end-time becomes the case's own parameter, so that summary.json, the checks of the case
  // (tools that would meet) and the figures (the wheel's tools at the end) all agree with it.
  if (r.end_time) {
    if constexpr (requires { p.end_time_s; })
      p.end_time_s = *r.end_time;
    else
      p.stroke_m = *r.end_time * p.tool_velocity_m_s;  // wheel forging: the stroke reached then
  }
  const auto table = dispatch_table<Case>();
  const auto it = table.find(r.method_key());
  if (it == table.end()) fail("no compiled configuration for '{}'", r.method_key());
  return it->second(r, p, restart);
}

}  // namespace rkpm::runner
