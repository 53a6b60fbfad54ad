#pragma once
// heat_ledger: where the heat of a conduction run went (docs/method.md section 5.9, (93)), in J
// (in axisymmetry totals over the ring, like the forces). Every term is a sum over the steps of
// what the step added; conduction moves heat between particles and adds none (the partition of
// unity, (87)), so
//   stored = sources + fixed + flux + convection      to round-off
// and imbalance() measures that. With temperature-independent capacities `stored` is also
// sum_I C_I T_I now minus at the start (heat_conduction::stored_heat()).
//   stored      sum over steps of sum_I C_I (T_I^{n+1} - T_I^n)
//   sources     the heat rates given to advance() times the step
//   fixed       the heat the fixed-temperature projection (92) added (negative: removed)
//   flux        prescribed fluxes, into the body
//   convection  convected into the body (negative when the body cools)

#include <algorithm>
#include <cmath>

namespace rkpm::thermal {

struct heat_ledger {
  double stored = 0.0;
  double sources = 0.0;
  double fixed = 0.0;
  double flux = 0.0;
  double convection = 0.0;

  double boundaries() const { return fixed + flux + convection; }
  // stored - (sources + boundaries), J.
  double imbalance() const { return stored - (sources + boundaries()); }
  // The imbalance over the largest term (0 when nothing moved).
  double relative_imbalance() const {
    const double scale = std::max({std::abs(stored), std::abs(sources), std::abs(fixed), std::abs(flux),
                                   std::abs(convection)});
    return scale > 0.0 ? std::abs(imbalance()) / scale : 0.0;
  }
};

}  // namespace rkpm::thermal
