#pragma once
// Mass scaling for processes slower than the waves (docs/method.md section 5.10):
//   mass_scaling_policy   by how much: a factor on every mass, or the factor that makes the
//                         step the target step (84); off by default (the masses as they are)
//   quasi_static_check    the honesty of a scaled run: the kinetic to internal energy ratio
//                         (85), and whether the run has left the quasi-static regime
// The scaling is uniform: every particle's mass times one factor, so the frequencies all fall
// by its square root and the mode shapes stay. The body forces keep the physical masses (a
// scaled billet weighs what it weighs); contact and the stable step see the scaled ones.

#include <algorithm>
#include <cmath>
#include <limits>

#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>

namespace rkpm {

struct mass_scaling_policy {
  // Every mass times this (>= 1); 1: not by factor.
  double factor = 1.0;
  // Or the step wanted (s): the factor is (target / dt0)^2 with dt0 the step without scaling
  // (84), and 1 if dt0 is already larger; 0: not by target.
  double target_time_step = 0.0;
  // The run has left the quasi-static regime when its kinetic energy exceeds this fraction of
  // its internal energy (85) after the first `settle_fraction` of the end time (the start of a
  // forging, when nothing has deformed yet, has no meaningful ratio).
  double max_kinetic_to_internal = 0.05;
  double settle_fraction = 0.1;

  bool enabled() const { return factor != 1.0 || target_time_step > 0.0; }
  void validate() const {
    if (!(factor >= 1.0) || !std::isfinite(factor))
      fail("mass scaling: factor {} must be at least 1 (it multiplies every mass; 1 is no scaling)", factor);
    if (!(target_time_step >= 0.0) || !std::isfinite(target_time_step))
      fail("mass scaling: target time step {} s must be positive (or 0 for none)", target_time_step);
    if (factor != 1.0 && target_time_step > 0.0)
      fail("mass scaling: give a factor or a target time step, not both");
    if (!(max_kinetic_to_internal > 0.0))
      fail("mass scaling: the kinetic to internal energy bound {} must be positive (e.g. 0.05)",
           max_kinetic_to_internal);
    if (!(settle_fraction >= 0.0 && settle_fraction < 1.0))
      fail("mass scaling: settle_fraction {} must lie in [0, 1)", settle_fraction);
  }
  // The factor for a run whose unscaled step is dt0 (84).
  double factor_for(double dt0) const {
    if (target_time_step > 0.0) return std::max(1.0, (target_time_step / dt0) * (target_time_step / dt0));
    return factor;
  }
};

// The kinetic to internal energy ratio of a scaled run, watched at every step (85).
struct quasi_static_check {
  double worst_ratio = 0.0;  // the largest ratio after the settling time
  double worst_time = 0.0;   // s
  double left_at = -1.0;     // s: when the ratio first exceeded the bound; < 0: never

  void observe(const mass_scaling_policy& p, double time, double end_time, double kinetic, double internal) {
    if (time < p.settle_fraction * end_time) return;
    const double ratio = internal > 0.0   ? kinetic / internal
                         : kinetic > 0.0 ? std::numeric_limits<double>::infinity()
                                         : 0.0;
    if (ratio > worst_ratio) worst_ratio = ratio, worst_time = time;
    if (ratio > p.max_kinetic_to_internal && left_at < 0.0) left_at = time;
  }
  bool left() const { return left_at >= 0.0; }
};

}  // namespace rkpm
