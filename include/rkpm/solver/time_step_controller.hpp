#pragma once
// time_step_controller<G>: the step size of the explicit loop (docs/method.md section 5.6).
// The stable step follows the current configuration: between power iterations it scales
// with the narrowing of the supports (point_materials::min_stretch); when that has drifted by
// 10%, or every 500 steps, a short power iteration on the current elastic tangent (warm-started,
// with the fixed start vector mixed back in so that a newly dominant mode is not missed)
// measures it again. The stretch rule alone is safe but, with the Taylor bar's 4:1 supports
// crushed at the impact face, 3 to 4 times too pessimistic. The moduli are per point
// (point_moduli), so with several bodies the stiffest, lightest one sets the step.

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <rkpm/concepts/geometry.hpp>
#include <rkpm/core/error.hpp>
#include <rkpm/core/execution.hpp>
#include <rkpm/io/checkpoint.hpp>
#include <rkpm/material/elastic_constants.hpp>
#include <rkpm/solver/discrete_model.hpp>
#include <rkpm/solver/problem.hpp>
#include <rkpm/solver/stable_time_step.hpp>

namespace rkpm {

template <Geometry G>
class time_step_controller {
 public:
  time_step_controller() = default;

  // Measures the reference stable step (100 power iterations about F, the configuration at
  // t = 0) and returns the first step. F: the deformation gradient at every point, a callable
  // q -> mat3 (point_materials::deformation_gradients()) or a std::vector<mat3>.
  template <class PointF>
  double start(const discrete_model& m, const point_moduli& c, const std::vector<double>& mass, const PointF& F,
               const run_options& options) {
    power_iteration_start(m, mode_);
    workspace_ = stiffness_workspace(m);
    reference_dt_ = estimate_dt_ = 2.0 / std::sqrt(largest_frequency_squared<G>(m, c, F, mass, mode_, workspace_, 100));
    estimate_stretch_ = 1.0;
    estimate_step_ = 0;
    return step_size(1.0, options, 0.0, 0);
  }

  // The step after `steps` steps at `time`, with the supports narrowed to min_stretch.
  template <class PointF>
  double update(const discrete_model& m, const point_moduli& c, const std::vector<double>& mass, const PointF& F,
                double min_stretch, const run_options& options, double time,
                index_t steps) {
    const double drift = min_stretch / estimate_stretch_;
    if (steps > 0 && (drift < 0.9 || drift > 1.25 || steps - estimate_step_ >= 500)) {
      const double norm = exec::max_over_owned(m.own, [&](index_t I) { return mode_[I].cwiseAbs().maxCoeff(); }, 0.0);
      // The start vector recomputed, not stored (16 bytes per particle): the same values.
      exec::parallel_for(m.own.particles, [&](index_t I) {
        mode_[I] = mode_[I] / norm + 0.3 * power_iteration_start(static_cast<std::size_t>(m.global_particle(I)));
      });
      estimate_dt_ = 2.0 / std::sqrt(largest_frequency_squared<G>(m, c, F, mass, mode_, workspace_, 20));
      estimate_stretch_ = min_stretch;
      estimate_step_ = steps;
    }
    return step_size(min_stretch, options, time, steps);
  }

  // The step on a model rebuilt in the current configuration (explicit_solver::rereference): the
  // particles keep their numbers, so the power iteration starts from the last mode (with the start
  // vector mixed in, as update() does) and measures the new model's spectrum; the supports'
  // stretch starts again at 1.
  template <class PointF>
  double rereference(const discrete_model& m, const point_moduli& c, const std::vector<double>& mass, const PointF& F,
                     const run_options& options, double time, index_t steps) {
    workspace_ = stiffness_workspace(m);
    const double norm = exec::max_over_owned(m.own, [&](index_t I) { return mode_[I].cwiseAbs().maxCoeff(); }, 0.0);
    exec::parallel_for(m.own.particles, [&](index_t I) {
      mode_[I] = mode_[I] / norm + 0.3 * power_iteration_start(static_cast<std::size_t>(m.global_particle(I)));
    });
    estimate_dt_ = 2.0 / std::sqrt(largest_frequency_squared<G>(m, c, F, mass, mode_, workspace_, 30));
    estimate_stretch_ = 1.0;
    estimate_step_ = steps;
    return step_size(1.0, options, time, steps);
  }

  // dt_crit of the reference configuration, 2 / omega_max.
  double reference_stable_step() const { return reference_dt_; }

  // Checkpoint (io/checkpoint.hpp): the power-iteration vectors and the last estimate.
  void save(io::checkpoint_writer& w) const { sections(w, *this); }
  void load(io::checkpoint_reader& r) { sections(r, *this); }

 private:
  template <class Archive, class Self>
  static void sections(Archive& a, Self& s) {
    a.array("clock.mode", s.mode_);
    a.value("clock.reference_dt", s.reference_dt_);
    a.value("clock.estimate_dt", s.estimate_dt_);
    a.value("clock.estimate_stretch", s.estimate_stretch_);
    a.value("clock.estimate_step", s.estimate_step_);
  }

  double step_size(double min_stretch, const run_options& options, double time, index_t steps) const {
    const double stable = estimate_dt_ * std::min(1.0, min_stretch / estimate_stretch_);
    if (options.fixed_time_step <= 0.0) return options.time_step_fraction * stable;
    if (options.fixed_time_step > stable)
      fail("the forced time step {:.4g} s exceeds the stable limit {:.4g} s (t = {:.6g} s, step {}): "
           "use a smaller time step or let rkpm choose it (fixed_time_step = 0)",
           options.fixed_time_step, stable, time, steps);
    return options.fixed_time_step;
  }

  std::vector<vec2> mode_;  // power-iteration vector
  stiffness_workspace workspace_{discrete_model{}};
  double reference_dt_ = 0.0, estimate_dt_ = 0.0, estimate_stretch_ = 1.0;
  index_t estimate_step_ = 0;
};

}  // namespace rkpm
