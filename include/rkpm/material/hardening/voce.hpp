#pragma once
// Voce hardening with a linear tail, sigma_y = sigma_0 + Q (1 - exp(-b eps_p)) + H eps_p
// (docs/method.md (24a)): the flow stress rises from sigma_0 by Q at the rate b and then keeps
// rising with slope H; the usual fit of annealed metals (copper, aluminium, steels) at moderate
// strain. Q = 0 is linear hardening, H = 0 saturates at sigma_0 + Q. `integral(a, b)` is the
// exact plastic work per unit volume int_a^b sigma_y de_p.

#include <array>
#include <cmath>
#include <string_view>

#include <rkpm/core/error.hpp>
#include <rkpm/material/hardening/parameter.hpp>

namespace rkpm::material::hardening {

struct voce {
  static constexpr std::string_view name = "voce";

  double yield_stress;       // sigma_0 in Pa
  double saturation_stress;  // Q in Pa, what the exponential term adds at saturation
  double saturation_rate;    // b, how fast it saturates (dimensionless: per unit eps_p)
  double modulus;            // H in Pa, the slope left at large strain

  static constexpr auto parameters() {
    using p = hardening_parameter<voce>;
    return std::array{p{"yield_stress_Pa", &voce::yield_stress, lower_bound::positive, "100e6"},
                      p{"saturation_stress_Pa", &voce::saturation_stress, lower_bound::non_negative, "150e6"},
                      p{"saturation_rate", &voce::saturation_rate, lower_bound::positive, "10"},
                      p{"hardening_modulus_Pa", &voce::modulus, lower_bound::non_negative,
                        "50e6 (softening is not supported)"}};
  }

  void validate() const {
    if (!(std::isfinite(yield_stress) && yield_stress > 0.0))
      fail("hardening::voce: yield_stress = {} Pa is invalid: give a finite value > 0 (e.g. 100e6)", yield_stress);
    if (!(std::isfinite(saturation_stress) && saturation_stress >= 0.0))
      fail("hardening::voce: saturation_stress = {} Pa is invalid: give a finite value >= 0 (softening is not "
           "supported; e.g. 150e6)",
           saturation_stress);
    if (!(std::isfinite(saturation_rate) && saturation_rate > 0.0))
      fail("hardening::voce: saturation_rate = {} is invalid: give a finite value > 0 (e.g. 10)", saturation_rate);
    if (!(std::isfinite(modulus) && modulus >= 0.0))
      fail("hardening::voce: modulus = {} Pa is invalid: give a finite value >= 0 (softening is not supported; "
           "e.g. 50e6)",
           modulus);
  }

  // 1 - exp(-b eps_p) as -expm1, exact for small b eps_p.
  double flow_stress(double eps_p) const {
    return yield_stress - saturation_stress * std::expm1(-saturation_rate * eps_p) + modulus * eps_p;
  }
  // The curve's lowest value, at eps_p = 0 (Q, H >= 0: it only rises).
  double lowest_flow_stress() const { return flow_stress(0.0); }
  double slope(double eps_p) const {
    return saturation_stress * saturation_rate * std::exp(-saturation_rate * eps_p) + modulus;
  }
  // int_from^to sigma_y de = (to - from) (sigma_0 + Q + H (from + to) / 2)
  //                          + Q / b exp(-b from) expm1(-b (to - from)).
  double integral(double from, double to) const {
    const double span = to - from;
    return span * (yield_stress + saturation_stress + 0.5 * modulus * (from + to)) +
           saturation_stress / saturation_rate * std::exp(-saturation_rate * from) *
               std::expm1(-saturation_rate * span);
  }
};

}  // namespace rkpm::material::hardening
