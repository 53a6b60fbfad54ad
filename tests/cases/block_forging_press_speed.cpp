// Block forging at press speed with mass scaling (docs/method.md section 5.10), reduced: 11 x 11
// particles, 20% reduction, Q4. A rate-independent forging whose inertia is small beside its
// internal work is quasi-static: its tool force and width do not depend on how fast it is done.
//   - the forging at 20 mm/s, masses scaled to a step 200 times the unscaled one (factor about
//     4e4: the inertia of a 4 m/s forging), against the unscaled one at 10 m/s (the paper's speed,
//     where the kinetic energy is about 1% of the internal): force and width within 2%, and the
//     quasi-static check (85) holds, its ratio below 5%;
//   - the same forging at 10 m/s with masses times 100 is a 100 m/s forging in disguise: the
//     check fires, and its force is not the quasi-static one.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/solver/make_solver.hpp>

#include "cases/block_forging.hpp"

namespace test_cases_block_forging_press_speed {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

namespace {

using bf = cases::block_forging;
using contact_t = contact::particle_to_segment<contact::enforcement::paper, contact::friction::coulomb>;
using cfg = config<kernel::cubic_spline, correction::linear, quadrature::q4, bf::geometry_type, bf::material_type,
                   contact_t>;

struct forging {
  double force = 0.0;  // N/m: the top tool's mean force over the last tenth
  double width = 0.0;  // m: the block's width at the end
  double dt = 0.0;     // s: the first step
  index_t steps = 0;
  double factor = 1.0;
  quasi_static_check check;
};

forging forge(double speed, mass_scaling_policy scaling) {
  bf::parameters p;
  p.particles_per_side = 11;
  p.tool_velocity_m_s = speed;
  p.end_time_s = 0.2 * p.height_m / (2.0 * speed);  // 20% reduction
  run_options o;
  o.end_time = p.end_time_s;
  o.mass_scaling = scaling;
  auto s = make_solver<cfg>(bf::build<contact_t>(p, 1), o);
  forging r;
  r.dt = s.time_step();
  double late_start = -1.0, late_impulse = 0.0;
  s.run(
      [&](const auto& s) {
        if (s.time() > 0.9 * o.end_time && late_start < 0.0) {
          late_start = s.time();
          late_impulse = s.tool_impulses()[1].y();
        }
      },
      1);
  r.force = (s.tool_impulses()[1].y() - late_impulse) / (s.time() - late_start);
  double lo = 1e30, hi = -1e30;
  for (const vec2& x : s.particle_positions()) lo = std::min(lo, x.x()), hi = std::max(hi, x.x());
  r.width = hi - lo;
  r.steps = s.steps();
  r.factor = s.mass_scaling_factor();
  r.check = s.quasi_static();
  return r;
}

}  // namespace

TEST_CASE("block forging at 20 mm/s, mass-scaled, gives the 10 m/s forging's force and width; at 10 m/s x 100 it is dynamic") {
  const forging paper = forge(10.0, {});
  const double dt0 = paper.dt;  // the unscaled first step: the same material and particles
  const forging press = forge(0.02, {.target_time_step = 200.0 * dt0});
  const forging disguised = forge(10.0, {.factor = 100.0});
  MESSAGE("10 m/s: ", paper.steps, " steps, force ", paper.force, " N/m, width ", paper.width,
          " m; 20 mm/s scaled by ", press.factor, ": ", press.steps, " steps (unscaled: about ",
          0.2 * 0.5 / (2.0 * 0.02) / (0.7 * dt0), "), force ", press.force, ", width ", press.width,
          ", largest kinetic/internal ", press.check.worst_ratio, "; 10 m/s x 100: force ", disguised.force,
          ", kinetic/internal up to ", disguised.check.worst_ratio);
  CHECK(press.factor == doctest::Approx(4e4).epsilon(1e-9));
  CHECK(press.dt == doctest::Approx(200.0 * dt0).epsilon(1e-9));
  CHECK(std::abs(press.force / paper.force - 1.0) < 0.02);
  CHECK(std::abs(press.width / paper.width - 1.0) < 0.02);
  CHECK(!press.check.left());
  CHECK(press.check.worst_ratio < 0.05);
  CHECK(disguised.check.left());
  CHECK(disguised.check.worst_ratio > 0.05);
  CHECK(std::abs(disguised.force / paper.force - 1.0) > 0.02);
}

}  // namespace test_cases_block_forging_press_speed
