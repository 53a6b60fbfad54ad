#pragma once
// energy_balance: the health check of an explicit run (design.md section 4 "Energy").
//   kinetic + internal = initial kinetic + external + contact + constraint
// internal is the work of the internal forces (elastic energy plus plastic dissipation),
// external the work of body forces, contact the work of the contact corrections and
// constraint that of prescribed physical motions. balance_error is the largest imbalance
// seen over the run relative to the largest energy term seen.

#include <algorithm>
#include <cmath>

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

}  // namespace rkpm
