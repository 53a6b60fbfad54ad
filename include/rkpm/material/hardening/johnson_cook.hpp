#pragma once
// The Johnson-Cook flow stress (docs/method.md (24b); Johnson & Cook, 7th Int. Symp. Ballistics,
// The Hague, 1983, 541-547):
//   sigma_y = (A + B eps_p^n) (1 + C ln max(rate*, 1)) (1 - T*^m),
//   rate* = (d eps_p / dt) / (reference rate),  T* = (T - T_room) / (T_melt - T_room) in [0, 1].
// A law of eps_p, its rate and temperature (flow_point, concepts/material.hpp): the return
// mapping (radial_return.hpp) asks it at the rate dgamma / dt its increment implies and adds
// rate_slope / dt to its Newton slope. The rate term is never below 1 (slower than the reference
// rate gives no softening) and the temperature term is 1 at or below room temperature (and when
// no temperature is known: NaN) and 0 at or above melt. Not in `laws`: material::johnson_cook
// (material/johnson_cook.hpp) holds it with the temperature and damage it needs.

#include <algorithm>
#include <cmath>
#include <limits>
#include <string_view>
#include <utility>

#include <rkpm/concepts/material.hpp>
#include <rkpm/core/error.hpp>

namespace rkpm::material::hardening {

struct johnson_cook {
  static constexpr std::string_view name = "johnson_cook";

  double A;                  // Pa, the initial yield stress at the reference rate and room temperature
  double B;                  // Pa, the hardening coefficient
  double n;                  // the hardening exponent, in (0, 1]
  double C;                  // the strain-rate coefficient, >= 0
  double reference_rate;     // 1/s, > 0
  double m;                  // the thermal-softening exponent, > 0
  double room_temperature;   // K
  double melt_temperature;   // K, above room_temperature

  void validate() const {
    const auto check = [](bool ok, std::string_view what, double v, std::string_view give) {
      if (!ok) fail("hardening::johnson_cook: {} = {} is invalid: give {}", what, v, give);
    };
    check(std::isfinite(A) && A >= 0.0, "A", A, "a finite value >= 0 in Pa (OFHC copper: 90e6)");
    check(std::isfinite(B) && B >= 0.0, "B", B, "a finite value >= 0 in Pa (OFHC copper: 292e6)");
    check(A + B > 0.0, "A + B", A + B, "a positive flow stress (OFHC copper: A = 90e6, B = 292e6)");
    check(std::isfinite(n) && n > 0.0 && n <= 1.0, "n", n, "a value in (0, 1] (OFHC copper: 0.31)");
    check(std::isfinite(C) && C >= 0.0, "C", C, "a finite value >= 0 (OFHC copper: 0.025)");
    check(std::isfinite(reference_rate) && reference_rate > 0.0, "reference_rate", reference_rate,
          "a finite value > 0 in 1/s (OFHC copper: 1)");
    check(std::isfinite(m) && m > 0.0, "m", m, "a finite value > 0 (OFHC copper: 1.09)");
    check(std::isfinite(room_temperature) && room_temperature > 0.0, "room_temperature", room_temperature,
          "a finite value > 0 in K (294)");
    check(std::isfinite(melt_temperature) && melt_temperature > room_temperature, "melt_temperature",
          melt_temperature, "a finite value above the room temperature in K (OFHC copper: 1356)");
  }

  // T* of (24b), clamped to [0, 1]; 0 when the temperature is unknown (NaN).
  double homologous_temperature(double T) const {
    if (!(T > room_temperature)) return 0.0;
    return std::min(1.0, (T - room_temperature) / (melt_temperature - room_temperature));
  }
  // T*^m: 0 at or below room temperature, 1 at or above melt.
  double homologous_power(double T) const {
    const double t = homologous_temperature(T);
    if (t <= 0.0) return 0.0;
    return t >= 1.0 ? 1.0 : std::pow(t, m);
  }
  // 1 - T*^m: 1 at room temperature, 0 at melt.
  double thermal_factor(double T) const { return 1.0 - homologous_power(T); }
  // T*^m at T_new from its value power_old at T_old, where a point heats by a small fraction of
  // T_old - T_room in a step: power_old (1 + u)^m, u = (T_new - T_old) / (T_old - T_room), by the
  // binomial series while |u| <= 1/32 (a pow otherwise, and from room temperature).
  // The bounds are checked on T itself (T* itself costs a division, and only the pow needs it).
  double homologous_power_after(double T_old, double power_old, double T_new) const {
    if (!(T_new > room_temperature)) return 0.0;
    if (T_new >= melt_temperature) return 1.0;
    if (power_old > 0.0 && T_old > room_temperature) {
      const double u = (T_new - T_old) / (T_old - room_temperature);
      if (std::abs(u) <= 1.0 / 32.0) return power_old * binomial_power(m, u);
    }
    return homologous_power(T_new);
  }
  // (1 + u)^p for |u| <= 1/32 as its binomial series: 12 terms at most, below 1e-17 of the sum
  // (|u|^12 <= 1e-18); exact after one term for p = 1.
  static double binomial_power(double p, double u) {
    static constexpr double inverse[13] = {0.0,       1.0,       1.0 / 2,  1.0 / 3,  1.0 / 4,
                                           1.0 / 5,   1.0 / 6,   1.0 / 7,  1.0 / 8,  1.0 / 9,
                                           1.0 / 10,  1.0 / 11,  1.0 / 12};  // 1 / k: no division per term
    double sum = 1.0, term = 1.0;
    for (int k = 1; k <= 12; ++k) {
      term *= (p - (k - 1)) * inverse[k] * u;
      sum += term;
      if (std::abs(term) <= 1e-17 * sum) break;
    }
    return sum;
  }
  // 1 + C ln max(rate*, 1).
  double rate_factor(double rate) const {
    const double r = rate / reference_rate;
    return r > 1.0 ? 1.0 + C * std::log(r) : 1.0;
  }
  // A + B eps_p^n, the isothermal curve at the reference rate.
  double strain_factor(double eps_p) const { return A + B * std::pow(eps_p, n); }

  double flow_stress(double eps_p, const flow_point& at) const {
    return strain_factor(eps_p) * rate_factor(at.plastic_strain_rate) * thermal_factor(at.temperature);
  }
  // d sigma_y / d eps_p at a fixed rate and temperature: n B eps_p^(n-1) (...) (...), infinite at
  // eps_p = 0 when n < 1 (the return mapping then bisects).
  double slope(double eps_p, const flow_point& at) const {
    const double theta = thermal_factor(at.temperature);
    if (theta == 0.0) return 0.0;
    const double d = eps_p > 0.0 ? n * B * std::pow(eps_p, n - 1.0)
                                 : (n < 1.0 && B > 0.0 ? std::numeric_limits<double>::infinity() : B);
    return d * rate_factor(at.plastic_strain_rate) * theta;
  }
  // d sigma_y / d rate: (A + B eps_p^n) C / rate (1 - T*^m) above the reference rate, 0 below.
  double rate_slope(double eps_p, const flow_point& at) const {
    const double rate = at.plastic_strain_rate;
    if (!(rate > reference_rate)) return 0.0;
    return strain_factor(eps_p) * C / rate * thermal_factor(at.temperature);
  }
  // What a return mapping needs of the constants besides themselves, computed once per material
  // (material::johnson_cook) instead of once per point.
  struct precomputed_t {
    double log_reference_rate;  // ln rate0
    double inverse_n_plus_1;    // 1 / (n + 1)
  };
  precomputed_t precomputed() const { return {std::log(reference_rate), 1.0 / (n + 1.0)}; }

  // The law at one temperature, 1 - T*^m evaluated once: what the return mapping of a step
  // iterates on (the temperature of a step is that of its start, material/johnson_cook.hpp),
  // so that each Newton update costs the strain and rate terms only.
  struct at_temperature_t {
    static constexpr std::string_view name = "johnson_cook";
    const johnson_cook* law;
    double theta;  // 1 - T*^m
    precomputed_t constants;  // ln rate0 and 1 / (n + 1), kept by material::johnson_cook
    double flow_stress(double eps_p, const flow_point& at) const {
      return law->strain_factor(eps_p) * law->rate_factor(at.plastic_strain_rate) * theta;
    }
    double slope(double eps_p, const flow_point& at) const {
      if (theta == 0.0) return 0.0;
      const double d = eps_p > 0.0 ? law->n * law->B * std::pow(eps_p, law->n - 1.0)
                                   : (law->n < 1.0 && law->B > 0.0 ? std::numeric_limits<double>::infinity() : law->B);
      return d * law->rate_factor(at.plastic_strain_rate) * theta;
    }
    double rate_slope(double eps_p, const flow_point& at) const {
      const double rate = at.plastic_strain_rate;
      if (!(rate > law->reference_rate)) return 0.0;
      return law->strain_factor(eps_p) * law->C / rate * theta;
    }
    // slope and rate_slope at a point whose flow stress `flow` is known, without a pow:
    // B eps_p^n R theta = flow - A R theta, and (A + B eps_p^n) theta = flow / R.
    std::pair<double, double> slopes_at_flow(double eps_p, const flow_point& at, double flow) const {
      if (theta == 0.0) return {0.0, 0.0};
      const double rate = at.plastic_strain_rate;
      const double R = law->rate_factor(rate);
      const double strain = eps_p > 0.0 ? law->n * (flow - law->A * R * theta) / eps_p : slope(eps_p, at);
      return {strain, rate > law->reference_rate ? flow / R * law->C / rate : 0.0};
    }
    // The work integral (32) over [from, to] at the step's rate, from the flow stresses the
    // return mapping found: flow_from at rate 0 and eps_p = from, flow_to at `rate` and to.
    // theta > 0.
    double integral(double from, double to, double flow_from, double flow_to, double rate) const {
      const double R = law->rate_factor(rate);
      return integral_at_factor(from, to, flow_from, flow_to / (R * theta), R);
    }
    // The same from what a return mapping on the step curve gives: the rate factor R = 1 + C ln
    // max(rate*, 1) and the strain factor S_to = A + B to^n at the end. With theta S_from =
    // flow_from at the start, R theta int_from^to (A + B e^n) de
    //   = R (theta A (to - from) + (theta to (S_to - A) - from (flow_from - A theta)) / (n + 1)):
    // no pow, no log, no division.
    double integral_at_factor(double from, double to, double flow_from, double strain_to, double R) const {
      const double A = law->A;
      return R * (theta * A * (to - from) +
                  constants.inverse_n_plus_1 * (theta * to * (strain_to - A) - from * (flow_from - A * theta)));
    }

    // The flow stress along one step's return mapping, for Newton in x = ln dgamma
    // (radial_return.hpp, docs/method.md (28a)): sigma_y(eps_n + dg) at the rate* = dg / (dt rate0)
    // and its x-derivative, with no log (ln rate* = x - ln(dt rate0)) and, while dg is a small
    // fraction of eps_n, no pow: (eps_n + dg)^n = eps_n^n (1 + u)^n, u = dg / eps_n, summed as the
    // binomial series (|u| <= 1/32: 12 terms below 1e-17 of the sum). eps_n^n comes from the flow
    // stress at the step's start that the caller has (its yield check). Each Newton update then
    // costs one exp (dg = e^x) and a few multiplications.
    struct step_curve {
      double A, B, n, C, theta;
      double eps_n;       // eps_p at the start of the step
      double power_n;     // eps_n^n
      double inverse_eps_n;  // 1 / eps_n (+inf at 0)
      double log_offset;  // ln(dt rate0), +inf when dt = 0 (no rate term)
      struct point {
        double flow;        // sigma_y
        double strain;      // A + B eps^n, the flow stress at the reference rate and room temperature
        double dflow_dx;    // d sigma_y / d ln dgamma = dg d sigma_y / d eps_p + d sigma_y / d ln rate*
        double d2flow_dx2;  // its x-derivative, for Chebyshev's update (radial_return.hpp)
        double log_rate;    // ln max(rate*, 1)
      };
      point operator()(double dg, double x) const {
        // S = A + B eps^n and R = 1 + C ln max(rate*, 1) with their x-derivatives (dg = e^x):
        // S_x = dg n B eps^(n-1), S_xx = S_x (1 + (n - 1) dg / eps), R_x = C above the reference rate.
        const double eps = eps_n + dg;
        double power, S_x, S_xx;
        if (n == 1.0) {  // the linear law: no series, no division
          power = eps;
          S_x = S_xx = B * dg;
        } else {
          const double u = dg * inverse_eps_n;
          power = (eps_n > 0.0 && u <= 1.0 / 32.0) ? power_n * binomial_power(n, u) : std::pow(eps, n);
          const double dg_over_eps = dg / eps;
          S_x = n * B * power * dg_over_eps;
          S_xx = S_x * (1.0 + (n - 1.0) * dg_over_eps);
        }
        const double S = A + B * power;
        const double log_rate = std::max(0.0, x - log_offset);
        const double R = 1.0 + C * log_rate;
        const double R_x = log_rate > 0.0 ? C : 0.0;
        return {S * R * theta, S, (S_x * R + S * R_x) * theta, (S_xx * R + 2.0 * S_x * R_x) * theta, log_rate};
      }
    };
    // flow_at_start: sigma_y(eps_n) at the reference rate and this temperature, (A + B eps_n^n) theta.
    // log_dt: ln dt if the caller has it (material_step::log_dt), NaN otherwise. ln(dt rate0) is
    // taken as ln dt + ln rate0, so that one log per step serves every point of a body.
    step_curve along_step(double eps_n, double dt, double flow_at_start,
                          double log_dt = std::numeric_limits<double>::quiet_NaN()) const {
      const double power_n = (eps_n > 0.0 && law->B > 0.0 && theta > 0.0)
                                 ? std::max(0.0, (flow_at_start / theta - law->A) / law->B)
                                 : (eps_n > 0.0 ? std::pow(eps_n, law->n) : 0.0);
      return {law->A, law->B, law->n, law->C, theta, eps_n, power_n, 1.0 / eps_n,
              dt > 0.0 ? (std::isnan(log_dt) ? std::log(dt) : log_dt) + constants.log_reference_rate
                       : std::numeric_limits<double>::infinity()};
    }
  };
  at_temperature_t at_temperature(double T) const { return {this, thermal_factor(T), precomputed()}; }
  // The same from T*^m known (material::johnson_cook keeps it per point: no pow).
  at_temperature_t at_homologous_power(double power, const precomputed_t& constants) const {
    return {this, 1.0 - power, constants};
  }
  at_temperature_t at_homologous_power(double power) const { return at_homologous_power(power, precomputed()); }

  // The plastic work per unit volume int_from^to sigma_y de at a fixed rate and temperature (the
  // step's, docs/method.md (32)): (1 + C ln rate*)(1 - T*^m) (A (to - from) + B (to^(n+1) -
  // from^(n+1)) / (n + 1)).
  double integral(double from, double to, const flow_point& at) const {
    const double strain = A * (to - from) + B / (n + 1.0) * (std::pow(to, n + 1.0) - std::pow(from, n + 1.0));
    return strain * rate_factor(at.plastic_strain_rate) * thermal_factor(at.temperature);
  }
};

}  // namespace rkpm::material::hardening
