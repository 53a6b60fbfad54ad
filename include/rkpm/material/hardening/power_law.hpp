#pragma once
// Power-law hardening, sigma_y = K (eps0 + eps_p)^n (docs/method.md (24); the wheel's aluminium,
// section 10.3: 576.79 MPa, 0.01658, 0.3593, initial yield 132.2 MPa). `integral(a, b)` is the
// exact plastic work per unit volume int_a^b sigma_y de_p.

#include <array>
#include <cmath>
#include <string_view>

#include <rkpm/core/error.hpp>
#include <rkpm/material/hardening/parameter.hpp>

namespace rkpm::material::hardening {

struct power_law {
  static constexpr std::string_view name = "power";

  double coefficient;  // K in Pa
  double offset;       // eps0 > 0, so that the initial yield K eps0^n is positive and finite slope
  double exponent;     // n >= 0

  static constexpr auto parameters() {
    using p = hardening_parameter<power_law>;
    return std::array{p{"flow_coefficient_Pa", &power_law::coefficient, lower_bound::positive, "576.79e6"},
                      p{"flow_offset", &power_law::offset, lower_bound::positive,
                        "0.01658 (with 0 the initial yield stress is 0)"},
                      p{"flow_exponent", &power_law::exponent, lower_bound::non_negative, "0.3593"}};
  }

  void validate() const {
    if (!(std::isfinite(coefficient) && coefficient > 0.0))
      fail("hardening::power_law: coefficient = {} Pa is invalid: give a finite value > 0 "
           "(aluminium wheel: 576.79e6 Pa)",
           coefficient);
    if (!(std::isfinite(offset) && offset > 0.0))
      fail("hardening::power_law: offset = {} is invalid: give a finite value > 0 (with 0 the "
           "initial yield stress is 0 and the slope infinite; wheel: 0.01658)",
           offset);
    if (!(std::isfinite(exponent) && exponent >= 0.0))
      fail("hardening::power_law: exponent = {} is invalid: give a finite value >= 0 "
           "(wheel: 0.3593)",
           exponent);
  }

  double flow_stress(double eps_p) const { return coefficient * std::pow(base(eps_p), exponent); }
  // The curve's lowest value, at eps_p = 0 (exponent >= 0: it only rises).
  double lowest_flow_stress() const { return flow_stress(0.0); }
  double slope(double eps_p) const {
    return coefficient * exponent * std::pow(base(eps_p), exponent - 1.0);
  }
  // The same at a strain whose flow stress is known, without a second pow.
  double slope(double eps_p, double flow) const { return exponent * flow / base(eps_p); }
  double integral(double from, double to) const {
    const double m = exponent + 1.0;
    return coefficient / m * (std::pow(base(to), m) - std::pow(base(from), m));
  }
  // The same from the flow stresses at both ends, without a pow: K b^(n+1) = b sigma_y(b).
  double integral(double from, double to, double flow_from, double flow_to) const {
    return (base(to) * flow_to - base(from) * flow_from) / (exponent + 1.0);
  }

 private:
  // eps0 + eps_p must stay positive: a negative base would turn pow() into NaN silently.
  double base(double eps_p) const {
    const double b = offset + eps_p;
    if (!(b > 0.0))
      fail("hardening::power_law: offset + eps_p = {} + {} is not positive: the equivalent plastic "
           "strain must be >= 0 and the offset > 0",
           offset, eps_p);
    return b;
  }
};

}  // namespace rkpm::material::hardening
