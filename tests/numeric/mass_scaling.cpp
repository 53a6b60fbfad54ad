// Mass scaling (docs/method.md section 5.10, (84)-(85)), against what it must be in theory:
//   - time similarity: the central difference on masses k m with the step sqrt(k) dt and the
//     initial velocities v0 / sqrt(k) takes exactly the steps of the unscaled run (a rate-
//     independent material sees the same configurations), with velocities divided by sqrt(k)
//     and the same kinetic energy. With k = 4 every factor is a power of two: bit for bit;
//   - the body force is the physical weight: a falling body gains the momentum M g t, scaled or not;
//   - a target step: the factor is (target / dt0)^2 (84), and the step taken is the target;
//   - the quasi-static check (85) and the errors of the policy.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "support/solver_fixtures.hpp"

namespace test_numeric_mass_scaling {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

namespace {

using cfg = config<kernel::cubic_spline, correction::linear, quadrature::q4, geometry::plane_strain,
                   material::j2_plasticity<material::hardening::linear>, contact::none>;
const material::elastic_constants steel{200e9, 0.3, 7800.0};
const double L = 10e-3, Hb = 6e-3;

// A free block, swinging in a velocity field strong enough to yield it (V = 40 m/s).
problem_for<cfg> swinging_block(double speed) {
  return {.particles = make_grid_particles<2>(vec2(0, 0), vec2(L, Hb), Eigen::Vector2i(9, 6), 2.0),
          .mesh = make_grid_mesh(vec2(0, 0), vec2(L, Hb), Eigen::Vector2i(9, 6)),
          .material = material::j2_plasticity<material::hardening::linear>(steel, {300e6, 2e9}),
          .contact = {},
          .initial_velocity = [speed](const vec2& X) {
            return vec2(speed * std::sin(M_PI * X[0] / L), speed * (X[0] / L) * (X[1] / Hb));
          }};
}

double momentum_y(const auto& s) {
  double p = 0.0;
  for (index_t I = 0; I < s.model().particle_count(); ++I) p += s.mass()[I] * s.coefficient_velocities()[I][1];
  return p;
}

}  // namespace

TEST_CASE("mass scaling by 4: the unscaled run's steps at twice the step and half the speed, bit for bit") {
  run_options plain;
  plain.end_time = 1.0;
  auto reference = make_solver<cfg>(swinging_block(40.0), plain);
  const double dt = reference.time_step();
  run_options fixed = plain;
  fixed.fixed_time_step = dt;
  auto unscaled = make_solver<cfg>(swinging_block(40.0), fixed);
  run_options scaled_options = plain;
  scaled_options.fixed_time_step = 2.0 * dt;
  scaled_options.mass_scaling.factor = 4.0;
  auto scaled = make_solver<cfg>(swinging_block(20.0), scaled_options);
  CHECK(scaled.mass_scaling_factor() == 4.0);
  // The stable step grows by sqrt(4) = 2 (the power iteration sees M^-1 K divided by 4).
  CHECK(scaled.reference_stable_step() == doctest::Approx(2.0 * unscaled.reference_stable_step()).epsilon(1e-12));
  for (int n = 0; n < 300; ++n) {
    unscaled.step();
    scaled.step();
  }
  REQUIRE(unscaled.energy().plastic > 0.0);  // the block has yielded
  bool same_d = true, half_v = true;
  for (index_t I = 0; I < unscaled.model().particle_count(); ++I) {
    same_d = same_d && scaled.coefficients()[I] == unscaled.coefficients()[I];
    half_v = half_v && scaled.coefficient_velocities()[I] == 0.5 * unscaled.coefficient_velocities()[I];
  }
  CHECK(same_d);
  CHECK(half_v);
  CHECK(scaled.time() == 2.0 * unscaled.time());
  CHECK(scaled.energy().plastic == unscaled.energy().plastic);
  CHECK(scaled.energy().kinetic == unscaled.energy().kinetic);
  CHECK(scaled.physical_mass() == unscaled.mass());
}

TEST_CASE("mass scaling: the body force is the physical weight, so a falling block gains M g t") {
  const double g = 9.81;
  for (double factor : {1.0, 100.0}) {
    auto p = swinging_block(0.0);
    p.body_force = vec2(0.0, -g);
    run_options o;
    o.end_time = 1.0;
    o.mass_scaling.factor = factor;
    auto s = make_solver<cfg>(std::move(p), o);
    double weight = 0.0;
    for (double m : s.physical_mass()) weight += m;
    for (int n = 0; n < 50; ++n) s.step();
    const double exact = -weight * g * s.time();
    CAPTURE(factor);
    CHECK(momentum_y(s) == doctest::Approx(exact).epsilon(1e-12));
    CHECK(weight == doctest::Approx(L * Hb * steel.density).epsilon(1e-12));
  }
}

TEST_CASE("mass scaling to a target step: the factor (target / dt0)^2 (84), and the step taken is the target") {
  run_options plain;
  plain.end_time = 1.0;
  const double dt0 = make_solver<cfg>(swinging_block(40.0), plain).time_step();
  run_options o = plain;
  o.mass_scaling.target_time_step = 3.0 * dt0;
  auto s = make_solver<cfg>(swinging_block(40.0), o);
  CHECK(s.mass_scaling_factor() == doctest::Approx(9.0).epsilon(1e-12));
  CHECK(s.time_step() == doctest::Approx(3.0 * dt0).epsilon(1e-9));
  // A target below the step already taken scales nothing.
  o.mass_scaling.target_time_step = 0.5 * dt0;
  auto unscaled = make_solver<cfg>(swinging_block(40.0), o);
  CHECK(unscaled.mass_scaling_factor() == 1.0);
  CHECK(unscaled.time_step() == dt0);
}

TEST_CASE("the quasi-static check (85): the ratio after the settling time, and when the run left the regime") {
  mass_scaling_policy p;
  p.factor = 10.0;
  quasi_static_check q;
  q.observe(p, 0.05, 1.0, 5.0, 1.0);  // before 10% of the end time: not counted
  CHECK(q.worst_ratio == 0.0);
  q.observe(p, 0.2, 1.0, 0.04, 1.0);
  CHECK(!q.left());
  CHECK(q.worst_ratio == doctest::Approx(0.04));
  q.observe(p, 0.3, 1.0, 0.06, 1.0);
  CHECK(q.left());
  CHECK(q.left_at == 0.3);
  q.observe(p, 0.4, 1.0, 0.5, 1.0);
  CHECK(q.left_at == 0.3);  // the first time
  CHECK(q.worst_time == 0.4);
}

TEST_CASE("mass scaling's errors name the value and the fix") {
  const auto message = [](mass_scaling_policy p) {
    try {
      p.validate();
    } catch (const error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK(message({.factor = 0.5}).find("at least 1") != std::string::npos);
  CHECK(message({.factor = NAN}).find("at least 1") != std::string::npos);
  CHECK(message({.target_time_step = -1e-6}).find("must be positive") != std::string::npos);
  CHECK(message({.factor = 10.0, .target_time_step = 1e-6}).find("not both") != std::string::npos);
  CHECK(message({.factor = 10.0, .max_kinetic_to_internal = 0.0}).find("e.g. 0.05") != std::string::npos);
  CHECK(message({.factor = 10.0}).empty());
}

}  // namespace test_numeric_mass_scaling
