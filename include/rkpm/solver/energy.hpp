#pragma once
// The energy ledger, the health check of an explicit run (docs/method.md section 7):
//   kinetic + internal = initial kinetic + external + contact + constraint + remap
// internal is the work of the internal forces (elastic energy plus plastic dissipation),
// external the work of body forces, contact the work of the contact corrections and
// constraint that of prescribed physical motions, remap the change of kinetic energy when the
// velocities are carried to a new reference (solver/rereference.hpp). balance_error is the largest imbalance
// seen over the run relative to the largest energy term seen.

#include <algorithm>
#include <cmath>
#include <vector>

#include <rkpm/core/types.hpp>

namespace rkpm {

struct energy_balance {
  double initial_kinetic = 0.0;
  double kinetic = 0.0;
  double internal = 0.0;
  double plastic = 0.0;
  double external = 0.0;
  double contact = 0.0;
  double constraint = 0.0;
  double remap = 0.0;  // kinetic energy changed by carrying the velocities to a new reference (section 5.8)
  double largest_term = 0.0;
  double largest_imbalance = 0.0;

  double imbalance() const {
    return kinetic + internal - initial_kinetic - external - contact - constraint - remap;
  }
  double balance_error() const { return largest_term > 0.0 ? largest_imbalance / largest_term : 0.0; }

  // Records the current imbalance; call once per step after every term is updated.
  void record() {
    const double terms[] = {initial_kinetic, kinetic, internal, std::abs(external),
                            std::abs(contact), std::abs(constraint), std::abs(remap)};
    for (double t : terms) largest_term = std::max(largest_term, t);
    largest_imbalance = std::max(largest_imbalance, std::abs(imbalance()));
  }
};

// Work of a velocity jump v_before -> v_after applied to the half-step velocity (contact or
// constraint). The jump is the impulse of a force f = m dv / dt acting at t(n); weighting it
// with the mean of the half-step velocities around t(n), v_after and v_half_prev (the
// previous half-step velocity), as the trapezoidal internal work does for f_int, keeps the
// discrete energy balance exact to O(dt^2).
inline double impulse_work_at(double mass, const vec2& v_after, const vec2& v_before, const vec2& v_half_prev) {
  return 0.5 * mass * (v_after - v_before).dot(v_after + v_half_prev);
}

// The work of the internal forces over a step is the trapezoidal rule,
//   internal += 1/2 (f_int(n) + f_int(n+1)) . (d(n+1) - d(n)),  external += f_ext . (d(n+1) - d(n)),
// which explicit_solver::step() books in two halves around the force evaluation, with
// d(n+1) - d(n) = dt v(n+1/2) (exact in exact arithmetic, and not a difference of two large
// coefficients in floating point).

}  // namespace rkpm
