#pragma once
// step_timeline: where an explicit run is in time. The time t(n) reached, the steps taken, the
// size of the next step and the range of the sizes taken, and the step being taken while
// explicit_solver::step() runs (errors raised inside a step name it). explicit_solver::run()
// sizes each step through it so that the run lands on its end time exactly.

#include <algorithm>
#include <limits>

#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/io/checkpoint.hpp>
#include <rkpm/solver/problem.hpp>

namespace rkpm {

struct step_timeline {
  double time = 0.0;
  double dt = 0.0;      // the next step's size
  double taking = 0.0;  // the step being taken, 0 between steps
  double dt_min = std::numeric_limits<double>::infinity(), dt_max = 0.0;
  index_t steps = 0;

  bool between_steps() const { return taking == 0.0; }
  // The number and end time of the step being taken; between steps, of the last one taken.
  index_t current_step() const { return steps + !between_steps(); }
  double current_time() const { return time + taking; }
  bool before(double end) const { return time < end * (1.0 - 1e-12); }
  // The smallest and largest step taken (before the first step: the next step's size).
  double min_step() const { return steps ? dt_min : dt; }
  double max_step() const { return steps ? dt_max : dt; }

  // Sizes the next step of a run to options.end_time: it lands on the end time exactly, in two
  // equal steps rather than a full one and a sliver (a sliver's contact impulse over a tiny step
  // would read as a force spike). Refuses a step past options.max_steps.
  void approach_end(const run_options& options) {
    const double end = options.end_time;
    if (time + dt >= end) dt = end - time;
    else if (time + 2.0 * dt > end) dt = 0.5 * (end - time);
    if (steps >= options.max_steps)
      fail("t = {:.6g} s of {:.6g} s after {} steps, the limit max_steps: the stable step has shrunk to "
           "{:.3g} s (a body crushed or inverting?); raise max_steps if the run is meant to be this long",
           time, end, steps, dt);
  }

  // A run that would need more steps than options.max_steps at the step dt is refused before it starts.
  void check_budget(const run_options& options) const {
    const double needed = options.end_time / dt;
    if (needed > static_cast<double>(options.max_steps))
      fail("the run would take about {:.3g} steps (end time {:.6g} s / stable step {:.3g} s), more than "
           "max_steps = {}: check the material constants and units (a modulus too large, a density too "
           "small?) or the particle spacing, or raise max_steps",
           needed, options.end_time, dt, options.max_steps);
  }

  // The step of size dt begins; it ends with finish_step().
  double begin_step() { return taking = dt; }
  void finish_step() {
    time += taking;
    ++steps;
    dt_min = std::min(dt_min, taking);
    dt_max = std::max(dt_max, taking);
    taking = 0.0;
  }

  // Checkpoint (io/checkpoint.hpp): sections solver.time .. solver.steps of the solver's.
  void save(io::checkpoint_writer& w) const { sections(w, *this); }
  void load(io::checkpoint_reader& r) { sections(r, *this); }

 private:
  template <class Archive, class Self>
  static void sections(Archive& a, Self& s) {
    for (auto [name, field] : {std::pair{"solver.time", &s.time}, {"solver.dt", &s.dt}, {"solver.dt_min", &s.dt_min},
                               {"solver.dt_max", &s.dt_max}})
      a.value(name, *field);
    a.value("solver.steps", s.steps);
  }
};

}  // namespace rkpm
