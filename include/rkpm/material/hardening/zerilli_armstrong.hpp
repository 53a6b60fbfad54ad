#pragma once
// The Zerilli-Armstrong flow stress (docs/method.md (24c); F. J. Zerilli, R. W. Armstrong,
// J. Appl. Phys. 61 (1987) 1816-1825), from the dislocation mechanics of the two lattices:
//   fcc:  sigma_y = C0 + C2 eps_p^(1/2) exp(-C3 T + C4 T ln rate*)
//   bcc:  sigma_y = C0 + C1 exp(-C3 T + C4 T ln rate*) + C5 eps_p^n
//   rate* = max((d eps_p / dt) / (reference rate), 1),  sigma_y = 0 at T >= T_melt.
// A law of eps_p, its rate and temperature (flow_point, concepts/material.hpp), like
// hardening::johnson_cook: the return mapping (radial_return.hpp) asks it at the rate dgamma / dt
// its increment implies, in x = ln dgamma (28a), where r(x) is concave (sigma_y is convex and
// rising in x for either lattice), so its Newton iterates fall to the root. The temperature is
// required (NaN gives NaN): material::zerilli_armstrong (material/zerilli_armstrong.hpp) holds
// it with the adiabatic heating. Not in `laws`, for that reason.

#include <cmath>
#include <limits>
#include <string_view>
#include <utility>

#include <rkpm/concepts/material.hpp>
#include <rkpm/core/error.hpp>

namespace rkpm::material::hardening {

struct zerilli_armstrong {
  static constexpr std::string_view name = "zerilli_armstrong";
  enum class lattice_type { fcc, bcc };

  lattice_type lattice;
  double C0;              // Pa, the athermal stress (fcc and bcc)
  double C1;              // Pa, the thermal stress at 0 K (bcc; unused for fcc)
  double C2;              // Pa, the strain-hardening coefficient (fcc; unused for bcc)
  double C3;              // 1/K, the thermal softening, >= 0
  double C4;              // 1/K, the rate sensitivity, >= 0
  double C5;              // Pa, the strain-hardening coefficient (bcc; unused for fcc)
  double n;               // the strain-hardening exponent (bcc; unused for fcc), > 0
  double reference_rate = 1.0;                                            // 1/s, > 0
  double melt_temperature = std::numeric_limits<double>::infinity();      // K; infinity: none

  void validate() const {
    const auto check = [](bool ok, std::string_view what, double v, std::string_view give) {
      if (!ok) fail("hardening::zerilli_armstrong: {} = {} is invalid: give {}", what, v, give);
    };
    const bool fcc = lattice == lattice_type::fcc;
    check(std::isfinite(C0) && C0 >= 0.0, "C0", C0, "a finite value >= 0 in Pa (OFHC copper: 65e6)");
    check(std::isfinite(C3) && C3 >= 0.0, "C3", C3, "a finite value >= 0 in 1/K (OFHC copper: 0.0028)");
    check(std::isfinite(C4) && C4 >= 0.0, "C4", C4, "a finite value >= 0 in 1/K (OFHC copper: 0.000115)");
    if (fcc) {
      check(std::isfinite(C2) && C2 >= 0.0, "C2", C2, "a finite value >= 0 in Pa (OFHC copper: 890e6)");
      check(C0 + C2 > 0.0, "C0 + C2", C0 + C2, "a positive flow stress (OFHC copper: C0 = 65e6, C2 = 890e6)");
    } else {
      check(std::isfinite(C1) && C1 >= 0.0, "C1", C1, "a finite value >= 0 in Pa (Armco iron: 1033e6)");
      check(std::isfinite(C5) && C5 >= 0.0, "C5", C5, "a finite value >= 0 in Pa (Armco iron: 266e6)");
      check(std::isfinite(n) && n > 0.0, "n", n, "a finite value > 0 (Armco iron: 0.289)");
      check(C0 + C1 + C5 > 0.0, "C0 + C1 + C5", C0 + C1 + C5, "a positive flow stress (Armco iron: C1 = 1033e6)");
    }
    check(std::isfinite(reference_rate) && reference_rate > 0.0, "reference_rate", reference_rate,
          "a finite value > 0 in 1/s (usually 1)");
    check(melt_temperature > 0.0, "melt_temperature", melt_temperature,
          "a value > 0 in K, or infinity for none (copper: 1356)");
  }

  bool molten(double T) const { return T >= melt_temperature; }
  // ln rate*, never below 0.
  double log_rate(double rate) const {
    const double r = rate / reference_rate;
    return r > 1.0 ? std::log(r) : 0.0;
  }
  // exp(-C3 T + C4 T ln rate*), the thermally activated factor.
  double thermal_factor(double log_rate_star, double T) const { return std::exp(T * (C4 * log_rate_star - C3)); }
  // The part of sigma_y that the thermal factor multiplies, and the part that it does not.
  double activated(double eps_p, double factor) const {
    return lattice == lattice_type::fcc ? C2 * std::sqrt(eps_p) * factor : C1 * factor;
  }
  double athermal(double eps_p) const { return lattice == lattice_type::fcc ? C0 : C0 + C5 * std::pow(eps_p, n); }

  double flow_stress(double eps_p, const flow_point& at) const {
    if (molten(at.temperature)) return 0.0;
    return athermal(eps_p) + activated(eps_p, thermal_factor(log_rate(at.plastic_strain_rate), at.temperature));
  }
  // d sigma_y / d eps_p at a fixed rate and temperature, infinite at eps_p = 0 (fcc, and bcc with
  // n < 1; the return mapping starts above 0).
  double slope(double eps_p, const flow_point& at) const {
    if (molten(at.temperature)) return 0.0;
    constexpr double inf = std::numeric_limits<double>::infinity();
    if (lattice == lattice_type::fcc)
      return eps_p > 0.0 ? 0.5 * C2 * thermal_factor(log_rate(at.plastic_strain_rate), at.temperature) / std::sqrt(eps_p)
                         : (C2 > 0.0 ? inf : 0.0);
    if (eps_p > 0.0) return n * C5 * std::pow(eps_p, n - 1.0);
    return C5 == 0.0 || n > 1.0 ? 0.0 : (n == 1.0 ? C5 : inf);
  }
  // d sigma_y / d rate: the activated part times C4 T / rate above the reference rate, 0 below.
  double rate_slope(double eps_p, const flow_point& at) const {
    const double rate = at.plastic_strain_rate;
    if (molten(at.temperature) || !(rate > reference_rate)) return 0.0;
    return activated(eps_p, thermal_factor(log_rate(rate), at.temperature)) * C4 * at.temperature / rate;
  }
  // Both slopes at a point whose flow stress `flow` is known (the return mapping's Newton
  // update): the activated part is flow - athermal, so fcc needs no exp, pow or sqrt.
  std::pair<double, double> slopes_at_flow(double eps_p, const flow_point& at, double flow) const {
    if (molten(at.temperature)) return {0.0, 0.0};
    const double rate = at.plastic_strain_rate;
    const double active = lattice == lattice_type::fcc ? flow - C0 : flow - athermal(eps_p);
    const double d_rate = rate > reference_rate ? active * C4 * at.temperature / rate : 0.0;
    if (lattice == lattice_type::fcc) return {eps_p > 0.0 ? 0.5 * active / eps_p : slope(eps_p, at), d_rate};
    return {slope(eps_p, at), d_rate};
  }
  // The plastic work per unit volume int_from^to sigma_y de at a fixed rate and temperature (the
  // step's, docs/method.md (32)):
  //   fcc: C0 (to - from) + (2/3) C2 E (to^(3/2) - from^(3/2))
  //   bcc: (C0 + C1 E)(to - from) + C5 (to^(n+1) - from^(n+1)) / (n + 1),   E the thermal factor.
  double integral(double from, double to, const flow_point& at) const {
    if (molten(at.temperature)) return 0.0;
    const double E = thermal_factor(log_rate(at.plastic_strain_rate), at.temperature);
    if (lattice == lattice_type::fcc)
      return C0 * (to - from) + 2.0 / 3.0 * C2 * E * (to * std::sqrt(to) - from * std::sqrt(from));
    return (C0 + C1 * E) * (to - from) + C5 / (n + 1.0) * (std::pow(to, n + 1.0) - std::pow(from, n + 1.0));
  }
};

}  // namespace rkpm::material::hardening
