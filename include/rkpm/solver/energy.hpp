#pragma once
// The energy ledger, the health check of an explicit run (docs/method.md section 7):
//   kinetic + internal = initial kinetic + external + contact + constraint
// internal is the work of the internal forces (elastic energy plus plastic dissipation),
// external the work of body forces, contact the work of the contact corrections and
// constraint that of prescribed physical motions. balance_error is the largest imbalance
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
  double largest_term = 0.0;
  double largest_imbalance = 0.0;

  double imbalance() const {
    return kinetic + internal - initial_kinetic - external - contact - constraint;
  }
  double balance_error() const { return largest_term > 0.0 ? largest_imbalance / largest_term : 0.0; }

  // Records the current imbalance; call once per step after every term is updated.
  void record() {
    const double terms[] = {initial_kinetic, kinetic, internal, std::abs(external),
                            std::abs(contact), std::abs(constraint)};
    for (double t : terms) largest_term = std::max(largest_term, t);
    largest_imbalance = std::max(largest_imbalance, std::abs(imbalance()));
  }
};

inline double kinetic_energy(const std::vector<double>& mass, const std::vector<vec2>& v) {
  double k = 0.0;
  for (std::size_t I = 0; I < mass.size(); ++I) k += 0.5 * mass[I] * v[I].squaredNorm();
  return k;
}

// Work of a velocity jump v_before -> v_after applied to the half-step velocity (contact or
// constraint). The jump is the impulse of a force f = m dv / dt acting at t(n); weighting it
// with the mean of the half-step velocities around t(n), v_after and v_half_prev (the
// previous half-step velocity), as the trapezoidal internal work does for f_int, keeps the
// discrete energy balance exact to O(dt^2).
inline double impulse_work(const std::vector<double>& mass, const std::vector<vec2>& v_after,
                           const std::vector<vec2>& v_before, const std::vector<vec2>& v_half_prev) {
  double w = 0.0;
  for (std::size_t I = 0; I < mass.size(); ++I)
    w += 0.5 * mass[I] * (v_after[I] - v_before[I]).dot(v_after[I] + v_half_prev[I]);
  return w;
}

// Trapezoidal work of the internal forces and work of the (constant) external forces over
// the step d_prev -> d: adds them to the ledger.
inline void add_force_work(energy_balance& e, const std::vector<vec2>& f_int_prev, const std::vector<vec2>& f_int,
                           const std::vector<vec2>& f_ext, const std::vector<vec2>& d_prev,
                           const std::vector<vec2>& d) {
  double internal = 0.0, external = 0.0;
  for (std::size_t I = 0; I < d.size(); ++I) {
    const vec2 dd = d[I] - d_prev[I];
    internal += 0.5 * (f_int_prev[I] + f_int[I]).dot(dd);
    external += f_ext[I].dot(dd);
  }
  e.internal += internal;
  e.external += external;
}

}  // namespace rkpm
