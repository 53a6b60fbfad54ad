#pragma once
// The run-time dispatch of `rkpm_run CASE --kernel K --correction C --quadrature Q --contact E`:
// a table, built with Boost.Hana from the policy lists the command line offers (methods.hpp),
// from the kernel, correction and enforcement names to one compiled combination each; the case
// fixes geometry and material, Coulomb friction (coefficient 0 is frictionless) serves every
// case, and the quadrature rule is chosen at run time inside (build_model_with_rule), since it
// changes tables, not types. The table's 12 entries per case share three instantiations of the
// time-stepping loop (one per enforcement).

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
#include "methods.hpp"
#include "outcome.hpp"
#include "request.hpp"
#include "run_record.hpp"
#include "simulate.hpp"

namespace rkpm::runner {

// The discrete model with the rule named `rule` (one of `quadratures`, methods.hpp): the rule is
// chosen at run time, since it changes only the points, the weights and (VCI) the test
// gradients, not the types of the model or the solver.
template <class K, class C, class G>
discrete_model build_model_with_rule(std::string_view rule, particle_set<2> particles, background_mesh mesh,
                                     double max_condition) {
  std::optional<discrete_model> model;
  hana::for_each(quadratures, [&](auto t) {
    using Q = typename decltype(t)::type;
    if (!model && rule == Q::name)
      model.emplace(build_discrete_model<K, C, Q, G>(std::move(particles), std::move(mesh), max_condition));
  });
  if (!model) fail("no quadrature rule '{}'; the rules are {}", rule, fmt::join(policy_names(quadratures), ", "));
  return std::move(*model);
}

template <class Case, class K, class C, class E>
run_outcome run_with(const run_request& r, const typename Case::parameters& p, const std::optional<restart_point>& restart) {
  using G = typename Case::geometry_type;
  using M = typename Case::material_type;
  using Ct = contact::particle_to_segment<E, contact::friction::coulomb>;
  using Solver = explicit_solver<G, M, Ct>;
  run_options options;
  options.end_time = Case::end_time(p);
  options.max_steps = r.max_steps;
  const std::function<Solver()> make = [&] {
    problem<M, Ct> pr = Case::template build<Ct>(p, r.resolution);
    discrete_model model = build_model_with_rule<K, C, G>(r.quadrature, std::move(pr.particles), std::move(pr.mesh),
                                                          options.max_moment_condition);
    return Solver(std::move(model), std::move(pr), options);
  };
  // config<...>::name()'s form, with the rule named at run time.
  const std::string configuration = fmt::format("{}-{}-{}-{}-{}-{}", K::name, C::name, r.quadrature, G::name,
                                                M::name, Ct::name);
  return simulate<Case, Solver>(r, p, {K::name, C::name, r.quadrature, G::name, E::name, configuration}, make,
                                restart);
}

template <class Case>
using run_function = run_outcome (*)(const run_request&, const typename Case::parameters&,
                                     const std::optional<restart_point>&);

// "cubic-linear-paper" (kernel-correction-enforcement) -> the run function of that
// combination; the quadrature rule is chosen inside, at run time.
template <class Case>
std::map<std::string, run_function<Case>> dispatch_table() {
  std::map<std::string, run_function<Case>> table;
  auto combos = hana::cartesian_product(hana::make_tuple(kernels, corrections, enforcements));
  hana::for_each(combos, [&](auto combo) {
    using K = typename decltype(+combo[hana::size_c<0>])::type;
    using C = typename decltype(+combo[hana::size_c<1>])::type;
    using E = typename decltype(+combo[hana::size_c<2>])::type;
    table[fmt::format("{}-{}-{}", K::name, C::name, E::name)] = &run_with<Case, K, C, E>;
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
