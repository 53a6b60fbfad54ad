#pragma once
// The run-time dispatch of `rkpm_run CASE --kernel K --correction C --quadrature Q --contact E`:
// a table, built with Boost.Hana from the policy lists the command line offers (methods.hpp),
// from the policies' names to one compiled configuration type per combination. The case fixes
// geometry and material; Coulomb friction (coefficient 0 is frictionless) serves every case.
// Only the discrete-model builder depends on kernel, correction and quadrature, so the table's
// 36 entries per case share three instantiations of the time-stepping loop (one per
// enforcement).

#include <boost/hana.hpp>
#include <map>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>

#include <rkpm/solver/discrete_model.hpp>
#include <rkpm/solver/make_solver.hpp>
#include <rkpm/solver/policies.hpp>

#include "case_list.hpp"
#include "cases/parameters.hpp"
#include "methods.hpp"
#include "outcome.hpp"
#include "request.hpp"
#include "run_record.hpp"
#include "simulate.hpp"

namespace rkpm::runner {

template <class Case, class Config>
run_outcome run_with(const run_request& r, const typename Case::parameters& p, const std::optional<restart_point>& restart) {
  using Ct = typename Config::contact_type;
  run_options options;
  options.end_time = Case::end_time(p);
  options.max_steps = r.max_steps;
  const std::function<solver_for<Config>()> make = [&] {
    return make_solver<Config>(Case::template build<Ct>(p, r.resolution), options);
  };
  return simulate<Case, solver_for<Config>>(r, p, method_names::of<Config>(), make, restart);
}

template <class Case>
using run_function = run_outcome (*)(const run_request&, const typename Case::parameters&,
                                     const std::optional<restart_point>&);

// "cubic-linear-q2-paper" -> the run function of that configuration.
template <class Case>
std::map<std::string, run_function<Case>> dispatch_table() {
  std::map<std::string, run_function<Case>> table;
  auto combos = hana::cartesian_product(hana::make_tuple(kernels, corrections, quadratures, enforcements));
  hana::for_each(combos, [&](auto combo) {
    using K = typename decltype(+combo[hana::size_c<0>])::type;
    using C = typename decltype(+combo[hana::size_c<1>])::type;
    using Q = typename decltype(+combo[hana::size_c<2>])::type;
    using E = typename decltype(+combo[hana::size_c<3>])::type;
    using Ct = contact::particle_to_segment<E, contact::friction::coulomb>;
    using Config = config<K, C, Q, typename Case::geometry_type, typename Case::material_type, Ct>;
    table[fmt::format("{}-{}-{}-{}", K::name, C::name, Q::name, E::name)] = &run_with<Case, Config>;
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
