#pragma once
// The scalar equation of the J2 radial return (docs/method.md (28)-(29)): given the
// trial von Mises stress q_trial > sigma_y(eps_p_n), find the plastic increment dgamma >= 0 with
//   r(dgamma) = q_trial - 3 mu dgamma - sigma_y(eps_p_n + dgamma) = 0.
// Linear hardening has the closed form dgamma = (q_trial - sigma_y(eps_p_n)) / (3 mu + H); any
// other law gets a Newton iteration safeguarded by bisection on [0, q_trial / (3 mu)], where
// r(0) > 0 and r(q_trial / (3 mu)) = -sigma_y <= 0, so the root stays bracketed and
// eps0 + eps_p never drops below its value at the start of the step.
// A law of eps_p, its rate and temperature (concepts/material.hpp) is asked at the rate the
// increment implies, dgamma / dt, and the step's temperature; the Newton slope then includes
// d sigma_y / d rate / dt (docs/method.md (28)).

#include <cmath>
#include <concepts>
#include <limits>
#include <string_view>

#include <rkpm/concepts/material.hpp>
#include <rkpm/core/error.hpp>
#include <rkpm/material/hardening/linear.hpp>

namespace rkpm::material {

struct radial_return_result {
  double increment;    // dgamma, the increment of the equivalent plastic strain
  int iterations;      // Newton updates taken (0 for the closed form)
  double residual;     // r(dgamma) in Pa
  double flow_stress;  // sigma_y(eps_p_n + dgamma) in Pa
  double log_rate = 0.0;  // ln max(rate*, 1) at dgamma, by a law on a step curve (johnson_cook); else 0
  double log_increment = -std::numeric_limits<double>::infinity();  // ln dgamma, by a law on a step curve
  // The flow stress's strain factor at dgamma (johnson_cook's A + B eps_p^n), by a law on a step curve.
  double strain_factor = std::numeric_limits<double>::quiet_NaN();
};

namespace detail {

// The refusal of every Newton branch below, naming the flow law (J2's or Johnson-Cook's).
[[noreturn]] inline void not_converged(std::string_view law, double r, int iterations, double limit, double q_trial,
                                       double eps_p_n, double dg) {
  fail("the return mapping of flow law {}: the Newton iteration did not converge: residual {} Pa after {} "
       "iterations (tolerance {} Pa, q_trial = {} Pa, eps_p = {}, dgamma = {}); raise max_newton_iterations or "
       "loosen newton_tolerance",
       law, r, iterations, limit, q_trial, eps_p_n, dg);
}

}  // namespace detail

// tolerance is relative: converged when |r| <= tolerance * q_trial. flow_at_start is
// sigma_y(eps_p_n), which the caller has from its yield check (one pow less per update).
// log_first_guess, if finite, is the log of an increment near the root (a point's last
// increment: the plastic rate changes little from one explicit step to the next) where a law on
// a step curve starts its iteration in x = ln dgamma, if that increment lies in the bracket.
// log_dt: ln step.dt when the caller has it (UpdatesWithStepLog, concepts/material.hpp), for a
// law on a step curve; NaN: the law takes it.
template <Hardening H>
radial_return_result radial_return(const H& hardening, double q_trial, double three_mu,
                                   double eps_p_n, double tolerance, int max_iterations, double flow_at_start,
                                   const material_step& step = {},
                                   double log_first_guess = -std::numeric_limits<double>::infinity(),
                                   double log_dt = std::numeric_limits<double>::quiet_NaN()) {
  // Where on the curve an increment dg puts the point (rate dg / dt, the step's temperature).
  const auto at = [&](double dg) {
    if constexpr (hardens_with_state<H>) return flow_point{step.dt > 0.0 ? dg / step.dt : 0.0, step.temperature};
    else return flow_point{};
  };
  double sigma = flow_at_start;  // sigma_y at the last residual's dgamma
  const auto residual = [&](double dg) {
    sigma = flow_stress_at(hardening, eps_p_n + dg, at(dg));
    return q_trial - three_mu * dg - sigma;
  };
  // d sigma_y / d dgamma where the flow stress sigma is already known: a law may reuse it
  // (power_law's slope is n sigma / (eps0 + eps_p), which saves a pow per Newton update).
  const auto slope = [&](double dg, double flow) {
    const double eps_p = eps_p_n + dg;
    if constexpr (SlopeFromFlow<H>)
      return hardening.slope(eps_p, flow);
    else if constexpr (SlopesFromFlow<H>) {
      // Both slopes of a rate-dependent law from its flow stress (johnson_cook: no pow).
      const auto [strain_slope, rate_slope] = hardening.slopes_at_flow(eps_p, at(dg), flow);
      return strain_slope + (step.dt > 0.0 ? rate_slope / step.dt : 0.0);
    } else if constexpr (hardens_with_state<H>)
      return slope_at(hardening, eps_p, at(dg)) +
             (step.dt > 0.0 ? rate_slope_at(hardening, eps_p, at(dg)) / step.dt : 0.0);
    else
      return hardening.slope(eps_p);
  };
  if constexpr (std::same_as<H, hardening::linear>) {
    const double dg = (q_trial - flow_at_start) / (three_mu + hardening.modulus);
    const double r = residual(dg);
    return {dg, 0, r, sigma};
  } else if constexpr (HardensAlongStep<H>) {
    // The same Newton in x = ln dgamma as the branch below, on the law's own curve along the
    // step (hardening::johnson_cook::at_temperature_t::step_curve): the flow stress and its
    // x-derivative together, ln rate* = x - ln(dt rate0) with no log, one exp per update.
    const auto curve = hardening.along_step(eps_p_n, step.dt, flow_at_start, log_dt);
    const double limit = tolerance * q_trial;
    // The upper bound of the branch below, (q_trial - sigma_y(eps_p,n)) / (3 mu), brackets the
    // root with 0 (the flow stress only rises along the step). From it the iterates fall to the
    // root monotonically, in about five updates where the rate term is stiff; from the last
    // step's increment, in about two: from below the root the first update lands above it (r is
    // concave in x), then they fall as before.
    double lo = 0.0;
    double hi = (q_trial - flow_at_start) / three_mu;
    double x = log_first_guess;
    double dg = std::exp(x);
    if (!(dg > 0.0 && dg < hi)) {
      dg = hi;
      x = std::log(dg);
    }
    auto p = curve(dg, x);
    double r = q_trial - three_mu * dg - p.flow;
    for (int it = 1;; ++it) {
      if (std::abs(r) <= limit) return {dg, it, r, p.flow, p.log_rate, x, p.strain};
      if (it > max_iterations || !std::isfinite(r))
        detail::not_converged(H::name, r, it - 1, limit, q_trial, eps_p_n, dg);
      (r > 0.0 ? lo : hi) = dg;
      // Newton's update, r' = dr/dx = -(3 mu dgamma + d sigma_y / dx). r is concave in x, so from
      // above the root (r < 0) Newton's stays above it, and from below it lands above. Above the
      // root, Chebyshev's update (third order, like Halley's, with one division: about one update
      // fewer) goes a little further, x - (r / r') (1 + L / 2), L = r r'' / r'^2 with
      // r'' = -(3 mu dgamma + d2 sigma_y / dx2), unless |L| > 1 (far from the root) or it crosses
      // the kink of the rate term at rate* = 1 (x = ln(dt rate0)), which r'' does not see: there
      // it can pass the root, and from below the kink, where r' is small, Newton's then jumps
      // far above again (a cycle that once held a point for 50 updates).
      const double r1 = -(three_mu * dg + p.dflow_dx);
      const double inverse_r1 = 1.0 / r1;
      const double newton = r * inverse_r1;
      double next_x = x - newton;
      if (r < 0.0) {
        const double r2 = -(three_mu * dg + p.d2flow_dx2);
        const double L = newton * r2 * inverse_r1;
        const double chebyshev = x - newton * (1.0 + 0.5 * L);
        if (std::abs(L) <= 1.0 && (chebyshev > curve.log_offset) == (x > curve.log_offset)) next_x = chebyshev;
      }
      const double next = std::exp(next_x);
      if (next > lo && next < hi) {
        dg = next;
        x = next_x;
      } else {
        dg = lo > 0.0 ? std::sqrt(lo * hi) : 0.5 * (lo + hi);
        x = std::log(dg);
      }
      p = curve(dg, x);
      r = q_trial - three_mu * dg - p.flow;
    }
  } else if constexpr (RateDependentHardening<H>) {
    // A rate-dependent law (Johnson-Cook, docs/method.md (28a)): Newton in x = ln dgamma. The
    // flow stress rises with ln(rate) = x - ln dt and, for eps_p^n with n <= 1 or any
    // x-convex law, r(x) = q_trial - 3 mu e^x - sigma_y is concave and decreasing in x, so from
    // the upper bound dgamma_0 = (q_trial - sigma_y(eps_p,n)) / (3 mu) (the overstress returned
    // with no hardening, r <= 0 there) the iterates decrease to the root monotonically, in a few
    // steps even when the root is orders of magnitude smaller (a stiff rate term), where Newton
    // in dgamma from 0 falls back to bisection again and again. The bracket stays as a guard.
    const double limit = tolerance * q_trial;
    double lo = 0.0;
    double hi = q_trial / three_mu;
    double dg = (q_trial - flow_at_start) / three_mu;
    double r = residual(dg);
    for (int it = 1;; ++it) {
      if (std::abs(r) <= limit) return {dg, it, r, sigma};
      if (it > max_iterations || !std::isfinite(r))
        detail::not_converged(H::name, r, it - 1, limit, q_trial, eps_p_n, dg);
      (r > 0.0 ? lo : hi) = dg;
      // dr/dx = -dgamma (3 mu + d sigma_y / d dgamma).
      const double next = dg * std::exp(r / (dg * (three_mu + slope(dg, sigma))));
      dg = (next > lo && next < hi) ? next : (lo > 0.0 ? std::sqrt(lo * hi) : 0.5 * (lo + hi));
      r = residual(dg);
    }
  } else {
    const double limit = tolerance * q_trial;
    double lo = 0.0;
    double hi = q_trial / three_mu;
    double dg = 0.0;
    double r = q_trial - flow_at_start;  // r(0), sigma = sigma_y(eps_p_n)
    for (int it = 0;; ++it) {
      if (std::abs(r) <= limit) return {dg, it, r, sigma};
      if (it == max_iterations || !std::isfinite(r))
        detail::not_converged(H::name, r, it, limit, q_trial, eps_p_n, dg);
      (r > 0.0 ? lo : hi) = dg;
      const double next = dg + r / (three_mu + slope(dg, sigma));
      // Newton left the bracket (or made no progress while unconverged): bisect instead.
      dg = (next > lo && next < hi) ? next : 0.5 * (lo + hi);
      r = residual(dg);
    }
  }
}

template <Hardening H>
radial_return_result radial_return(const H& hardening, double q_trial, double three_mu,
                                   double eps_p_n, double tolerance, int max_iterations) {
  return radial_return(hardening, q_trial, three_mu, eps_p_n, tolerance, max_iterations,
                       flow_stress_at(hardening, eps_p_n, flow_point{}));
}

}  // namespace rkpm::material
