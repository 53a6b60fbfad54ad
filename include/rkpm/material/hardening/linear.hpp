#pragma once
// Linear isotropic hardening, sigma_y = sigma_y0 + H eps_p (docs/method.md (23); the Taylor bar's
// copper, section 10.1: 400 MPa, 100 MPa). `integral(a, b)` is the exact plastic work per unit
// volume int_a^b sigma_y de_p; j2_plasticity's return mapping has its closed form (29).

#include <array>
#include <cmath>
#include <string_view>

#include <rkpm/core/error.hpp>
#include <rkpm/material/hardening/parameter.hpp>

namespace rkpm::material::hardening {

struct linear {
  static constexpr std::string_view name = "linear";

  double yield_stress;  // sigma_y0 in Pa
  double modulus;       // plastic modulus H = d sigma_y / d eps_p in Pa

  static constexpr auto parameters() {
    using p = hardening_parameter<linear>;
    return std::array{p{"yield_stress_Pa", &linear::yield_stress, lower_bound::positive, "400e6"},
                      p{"hardening_modulus_Pa", &linear::modulus, lower_bound::non_negative,
                        "100e6 (softening is not supported)"}};
  }

  void validate() const {
    if (!(std::isfinite(yield_stress) && yield_stress > 0.0))
      fail("hardening::linear: yield_stress = {} Pa is invalid: give a finite value > 0 "
           "(copper: 400e6 Pa)",
           yield_stress);
    if (!(std::isfinite(modulus) && modulus >= 0.0))
      fail("hardening::linear: modulus = {} Pa is invalid: give a finite value >= 0 "
           "(softening is not supported; copper: 100e6 Pa)",
           modulus);
  }

  double flow_stress(double eps_p) const { return yield_stress + modulus * eps_p; }
  double slope(double /*eps_p*/) const { return modulus; }
  double integral(double from, double to) const {
    return (to - from) * (yield_stress + 0.5 * modulus * (from + to));
  }
};

}  // namespace rkpm::material::hardening
