#pragma once
// The runner's warning when a mass-scaled run has left the quasi-static regime (docs/method.md
// (85)): one line, once, at the history row where the observer (run_observer.hpp) first sees it.

#include <cstdio>

#include <fmt/format.h>

#include <rkpm/solver/mass_scaling.hpp>

namespace rkpm::runner {

// `warned`: whether the line was printed already (set when it is).
template <class Solver>
void warn_if_dynamic(const Solver& s, bool& warned) {
  const quasi_static_check& q = s.quasi_static();
  if (!q.left() || warned) return;
  warned = true;
  fmt::print(stderr,
             "rkpm_run: warning: the mass-scaled run left the quasi-static regime at t = {:.6g} s: its kinetic energy "
             "exceeded {:g}% of its internal energy (mass scaling factor {:.4g}); lower the factor or the target "
             "step, or read the results as dynamic\n",
             q.left_at, 100.0 * s.options().mass_scaling.max_kinetic_to_internal, s.mass_scaling_factor());
}

}  // namespace rkpm::runner
