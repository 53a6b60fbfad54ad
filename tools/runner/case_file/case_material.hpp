#pragma once
// The one material type of every case file: material::j2_plasticity with its hardening law
// chosen at run time (hardening_law), so that the runner compiles one material per geometry
// and contact enforcement, whatever law the files name. Each call goes to the library's own
// law, so a case file runs bit for bit as the typed case with j2_plasticity<linear> or
// j2_plasticity<power_law> (tests/unit/case_file/hardening_law.cpp).
//
// "elastic" is J2 that never yields (flow stress +infinity). Its elastic part is the Hencky law
// of material::elastic (tau = K tr(eps) + 2 mu dev(eps) = lambda tr(eps) + 2 mu eps in principal
// log strains), reached through b_e = f b_e_n f^T step by step instead of b = F F^T: the same
// stress up to round-off.

#include <cmath>
#include <limits>
#include <string_view>

#include <rkpm/core/error.hpp>
#include <rkpm/material/hardening.hpp>
#include <rkpm/material/j2_plasticity.hpp>
#include <rkpm/material/radial_return.hpp>

namespace rkpm::runner::case_file {

struct hardening_law {
  static constexpr std::string_view name = "case_file";
  enum class kind { none, linear, power };

  kind law = kind::none;
  material::hardening::linear linear{};
  material::hardening::power_law power{};

  static hardening_law no_yield() { return {}; }
  static hardening_law of(const material::hardening::linear& h) { return {kind::linear, h, {}}; }
  static hardening_law of(const material::hardening::power_law& h) { return {kind::power, {}, h}; }

  void validate() const {
    if (law == kind::linear) linear.validate();
    if (law == kind::power) power.validate();
  }
  double flow_stress(double eps_p) const {
    switch (law) {
      case kind::linear: return linear.flow_stress(eps_p);
      case kind::power: return power.flow_stress(eps_p);
      default: return std::numeric_limits<double>::infinity();
    }
  }
  double slope(double eps_p) const {
    switch (law) {
      case kind::linear: return linear.slope(eps_p);
      case kind::power: return power.slope(eps_p);
      default: return 0.0;
    }
  }
  double integral(double from, double to) const {
    switch (law) {
      case kind::linear: return linear.integral(from, to);
      case kind::power: return power.integral(from, to);
      default: return 0.0;
    }
  }
  // The forms that reuse known flow stresses (material/hardening.hpp), so that a case file's
  // law gives the typed law's arithmetic bit for bit.
  double slope(double eps_p, double flow) const {
    return law == kind::power ? power.slope(eps_p, flow) : slope(eps_p);
  }
  double integral(double from, double to, double flow_from, double flow_to) const {
    return law == kind::power ? power.integral(from, to, flow_from, flow_to) : integral(from, to);
  }
};

// Found by argument-dependent lookup from j2_plasticity (a non-template beats the library's
// template): linear hardening keeps its closed form, as radial_return<hardening::linear> does,
// instead of the Newton iteration a law unknown to the library would get.
inline material::radial_return_result radial_return(const hardening_law& h, double q_trial, double three_mu,
                                                    double eps_p_n, double tolerance, int max_iterations,
                                                    double flow_at_start) {
  switch (h.law) {
    case hardening_law::kind::linear:
      return material::radial_return(h.linear, q_trial, three_mu, eps_p_n, tolerance, max_iterations, flow_at_start);
    case hardening_law::kind::power:
      return material::radial_return(h.power, q_trial, three_mu, eps_p_n, tolerance, max_iterations, flow_at_start);
    default:
      fail("case-file material: a return mapping was asked of a material that never yields (q_trial = {} Pa)",
           q_trial);
  }
}

using material_type = material::j2_plasticity<hardening_law>;

}  // namespace rkpm::runner::case_file
