#pragma once
// run_with's form on several processes (dispatch.hpp, ranks.hpp): rank 0 runs simulate() with
// rank_steps, the other ranks make the same collective calls (follow_run) and write nothing.

#include <exception>
#include <functional>
#include <optional>
#include <utility>

#include "ranks.hpp"

namespace rkpm::runner {

// The ranks other than 0: the calls simulate() makes on rank 0, with no whole solver and no files.
template <class Solver>
void follow_run(rank_steps<Solver>& steps, const std::optional<restart_point>& restart) {
  if (restart) steps.read_checkpoint(restart->file, nullptr);
  bool settled = false, written = false;  // as simulate() on rank 0
  try {
    steps.run(nullptr, {});
    settled = true;
    steps.settle(nullptr);
    written = true;
    steps.write_pending_checkpoint();
  } catch (...) {
    if (steps.started() && !settled) steps.settle(nullptr);
    if (!std::exchange(written, true)) {
      try {
        steps.write_pending_checkpoint();
      } catch (const std::exception&) {  // rank 0 says it ("no checkpoint at the failure")
      }
    }
    throw;
  }
}

// run_with's form on several processes (dispatch.hpp): simulate() on rank 0, follow_run elsewhere.
template <class Case, class Solver>
run_outcome run_on_ranks(const run_request& r, const typename Case::parameters& p, const run_policies& policies,
                         const std::function<typename rank_steps<Solver>::problem_type()>& make_problem,
                         const method_names& method, const run_options& options,
                         const std::optional<restart_point>& restart,
                         const std::function<void(const typename rank_steps<Solver>::problem_type&, bool)>& warn) {
  parallel::communicator world;
  const part_setup_request request{.rereference = options.rereference.enabled(),
                                   .mass_scaling = options.mass_scaling.enabled(),
                                   .hooks = static_cast<bool>(r.hooks.observe) || r.hooks.keep_final_state,
                                   .plots = r.plots};
  rank_steps<Solver> steps(world, policies.configuration, snapshot_format(r), row_reduction_of<Case, Solver>(p),
                           make_problem, method, options, request, warn);
  if (world.rank() == 0)
    return simulate<Case, Solver>(
        r, p, policies, []() -> Solver { fail("rank 0's solver is set up by rank_steps::set_up"); }, restart,
        &steps);
  steps.set_up();
  follow_run(steps, restart);
  return {};
}

}  // namespace rkpm::runner
