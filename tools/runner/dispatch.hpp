#pragma once
// The run-time dispatch of `rkpm_run CASE --kernel K --correction C --quadrature Q --enforcement E`:
// the case fixes geometry and material, so each case is one compiled solver type. Kernel,
// correction and rule are chosen at run time by the library's builder (rkpm/solver/make_model.hpp,
// compiled once per geometry in the project's rkpm_instances), since they change the model's
// tables, not the solver's type; the contact enforcement is contact::enforcement::chosen, which
// calls the policy the request names (the same numbers as that policy compiled in). Coulomb
// friction (coefficient 0 is frictionless) serves every case.

#include <boost/hana.hpp>
#include <type_traits>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <rkpm/solver/discrete_model.hpp>
#include <rkpm/solver/make_model.hpp>
#include <rkpm/solver/make_solver.hpp>
#include <rkpm/solver/policies.hpp>

#include "case_list.hpp"
#include "cases/parameters.hpp"
#include "memory_estimate.hpp"
#include "methods.hpp"
#include "outcome.hpp"
#ifdef RKPM_RUNNER_MPI
#include "run_on_ranks.hpp"
#endif
#include "request.hpp"
#include "run_record.hpp"
#include "simulate.hpp"

namespace rkpm::runner {

// The runner's contact: the enforcement the request names, Coulomb friction.
using runner_contact = contact::particle_to_segment<contact::enforcement::chosen, contact::friction::coulomb>;
// Every enforcement the command line offers (methods.hpp, from the library's policy list) can be chosen.
static_assert(hana::all_of(enforcements, [](auto t) {
  return hana::bool_c<std::is_constructible_v<contact::enforcement::chosen, typename decltype(t)::type>>;
}));

template <class Case>
run_outcome run_with(const run_request& r, const typename Case::parameters& p, const std::optional<restart_point>& restart) {
  using G = typename Case::geometry_type;
  using M = typename Case::material_type;
  using Ct = runner_contact;
  using Solver = explicit_solver<G, M, Ct>;
  run_options options;
  options.end_time = Case::end_time(p);
  options.max_steps = r.max_steps;
  options.rereference = r.rereference;
  options.mass_scaling = r.mass_scaling;
  const rkpm::method_names method{r.kernel, r.correction, r.quadrature};
  // One warning per machine; on several processes once the set-up is chosen (ranks.hpp).
  const std::function<void(const problem<M, Ct>&, bool)> warn = [&](const problem<M, Ct>& pr, bool in_parts) {
    if (r.machine_rank != 0) return;
    warn_if_too_large(pr.particles.size(),
                      quadrature_point_count(r.quadrature, pr.mesh.cells(), static_cast<index_t>(pr.mesh.node.size())),
                      {r.processes > 1, r.processes_here, r.with_rank_0, r.processes, in_parts});
  };
  const std::function<problem<M, Ct>()> make_problem = [&] {
    problem<M, Ct> pr = Case::template build<Ct>(p, r.resolution);
    pr.contact.set_enforcement(contact::enforcement::chosen::named(r.contact, penalty_stiffness<Case>(p)));
    if (r.processes == 1) warn(pr, false);
    return pr;
  };
  const run_policies policies{r.kernel, r.correction, r.quadrature, G::name, r.contact,
                              method.configuration_name<G, M, Ct>()};
  if (r.processes > 1) {
#ifdef RKPM_RUNNER_MPI
    return run_on_ranks<Case, Solver>(r, p, policies, make_problem, method, options, restart, warn);
#else
    fail("mpiexec started {} processes, but this rkpm_run was built without MPI, so each would run the whole case "
         "alone: apt-get install libopenmpi-dev openmpi-bin libmetis-dev, then build it again",
         r.processes);
#endif
  }
  const std::function<Solver()> make = [&] { return make_solver<G>(method, make_problem(), options); };
  return simulate<Case, Solver>(r, p, policies, make, restart);
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
  return run_with<Case>(r, p, restart);
}

}  // namespace rkpm::runner
