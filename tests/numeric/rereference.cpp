// Re-referencing the kernels (docs/method.md section 5.8), against theory:
//  - a homogeneous deformation: after a re-reference the new model's particles and quadrature
//    points are where F puts them (the points carried, their weights times det F), a linear field on the re-referenced (distorted) body gives its
//    gradient exactly, and F composes (79): driven by prescribed velocities at every particle, a
//    run re-referenced every few steps ends with the total F and the J2 stress of the Lagrangian
//    run, to round-off;
//  - mass, linear momentum and kinetic energy kept exactly at every re-reference (the masses and
//    the velocity coefficients stay), the velocity field changed by the approximation's O(h^2);
//  - a free elastic block set spinning, re-referenced every 10 steps for a quarter turn: angular
//    momentum within the run's balance tolerance, the energy ledger (with its remap term) balanced;
//  - no spurious mode: a strip vibrating in its first mode for 100 periods, re-referenced every 10
//    steps, keeps the Lagrangian run's frequency within 1% and its energy balance;
//  - in a section, a particle or a point carried across the axis is refused by name, and the
//    axis particles' round-off is not.

#include <doctest/doctest.h>

#include <numbers>

#include "support/error_message.hpp"
#include "support/solver_fixtures.hpp"

namespace test_numeric_rereference {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

namespace {

using j2 = material::j2_plasticity<material::hardening::linear>;
template <class Q, class G = geometry::plane_strain>
using method = config<kernel::cubic_spline, correction::linear, Q, G, j2, contact::none>;

double largest(const std::vector<vec2>& v) {
  double m = 0.0;
  for (const vec2& x : v) m = std::max(m, x.cwiseAbs().maxCoeff());
  return m;
}

// A 7 x 6 block, every particle's velocity prescribed as A X (X its initial position): the
// deformation is homogeneous, F(t) = I + t A.
template <class Cfg>
solver_for<Cfg> driven_block(const mat2& A, double dt, double end, rereference_policy when) {
  const vec2 lo(0.0, 0.0), hi(1.2, 1.0);
  auto p = test::grid_problem<Cfg>(lo, hi, Eigen::Vector2i(7, 6));
  if constexpr (Cfg::geometry_type::is_axisymmetric) {
    // Keep the axis: the radial velocity A(0, 0) r vanishes there (u_r = 0 is added by the solver).
    for (index_t I = 0; I < p.particles.size(); ++I) {
      const vec2 X = p.particles.position[I];
      if (X[0] > 1e-12) p.constraints.push_back({I, 0, [v = (A * X)[0]](double) { return v; }});
      p.constraints.push_back({I, 1, [v = (A * X)[1]](double) { return v; }});
    }
  } else {
    for (index_t I = 0; I < p.particles.size(); ++I)
      for (int k = 0; k < 2; ++k) p.constraints.push_back({I, k, [v = (A * p.particles.position[I])[k]](double) { return v; }});
  }
  run_options o;
  o.fixed_time_step = dt;
  o.end_time = end;
  o.rereference = when;
  auto s = make_solver<Cfg>(std::move(p), o);
  s.run();
  return s;
}

template <class Q, class G>
void check_composition() {
  using Cfg = method<Q, G>;
  // A strain rate that stretches, shears and yields the J2 block (yield strain 0.002).
  mat2 A;
  if constexpr (G::is_axisymmetric) A << 0.5, 0.0, 0.3, -0.8;
  else A << 0.6, 0.4, -0.1, -0.5;
  // A fixed step far below the stable one; F(end) = I + 0.5 A, a large deformation.
  const double dt = 2e-8, end = 400 * dt;
  const mat2 L = A * (0.5 / end);
  auto lagrangian = driven_block<Cfg>(L, dt, end, {});
  auto rebuilt = driven_block<Cfg>(L, dt, end, {.max_stretch = 0.0, .every_steps = 37});
  auto by_stretch = driven_block<Cfg>(L, dt, end, {.max_stretch = 1.1, .every_steps = 0});
  CHECK(by_stretch.rereferences() >= 3);
  REQUIRE(lagrangian.rereferences() == 0);
  REQUIRE(rebuilt.rereferences() == 10);
  mat3 expected = mat3::Identity();
  expected.topLeftCorner<2, 2>() += end * L;
  if constexpr (G::is_axisymmetric) expected(2, 2) = 1.0 + end * L(0, 0);
  double F_error = 0.0, stress_error = 0.0, stress_scale = 0.0;
  for (index_t q = 0; q < rebuilt.model().point_count(); ++q) {
    F_error = std::max(F_error, (rebuilt.point_states()[q].previous_deformation.full() - expected).cwiseAbs().maxCoeff());
    const mat3 s0 = lagrangian.point_cauchy_stress(q), s1 = rebuilt.point_cauchy_stress(q);
    const mat3 s2 = by_stretch.point_cauchy_stress(q);
    stress_error = std::max({stress_error, (s1 - s0).cwiseAbs().maxCoeff(), (s2 - s0).cwiseAbs().maxCoeff()});
    stress_scale = std::max(stress_scale, s0.cwiseAbs().maxCoeff());
  }
  CHECK(F_error < 1e-11);
  CHECK(stress_error < 1e-9 * stress_scale);
  // Yielded: the path is one a plastic law remembers.
  CHECK(rebuilt.point_states()[0].equivalent_plastic_strain > 1e-3);
  // The rebuilt model's particles are where F puts them.
  double position_error = 0.0;
  for (index_t I = 0; I < rebuilt.model().particle_count(); ++I) {
    const vec2 X = rebuilt.initial_positions()[I];
    position_error = std::max(position_error, (rebuilt.particle_positions()[I] - expected.topLeftCorner<2, 2>() * X).norm());
  }
  CHECK(position_error < 1e-12);
  // The points are the material points carried: where F at the last re-reference puts the
  // initial ones, their weights the initial ones times its det (with the hoop stretch and
  // 2 pi r in axisymmetry).
  const double t_r = rebuilt.rereference_times().back();
  mat3 F_r = mat3::Identity();
  F_r.topLeftCorner<2, 2>() += t_r * L;
  if constexpr (G::is_axisymmetric) F_r(2, 2) = 1.0 + t_r * L(0, 0);
  double point_error = 0.0, weight_error = 0.0;
  const double J = F_r.determinant();
  for (index_t q = 0; q < rebuilt.model().point_count(); ++q) {
    const vec2 X = lagrangian.model().points.position[q];
    point_error = std::max(point_error, (rebuilt.model().points.position[q] - F_r.topLeftCorner<2, 2>() * X).norm());
    weight_error = std::max(weight_error, std::abs(rebuilt.model().points.weight[q] / (J * lagrangian.model().points.weight[q]) - 1.0));
  }
  if (!rebuilt.model().nodal) {
    CHECK(point_error < 1e-12);
    CHECK(weight_error < 1e-12);
  }
}


// The free-free longitudinal mode of a plane-strain strip, v_x = V cos(pi x / L): its frequency
// (from the upward zero crossings of the end's velocity) over `periods` periods, and the run's
// balance error.
struct vibration {
  double frequency = 0.0, balance_error = 0.0;
  index_t rereferences = 0;
};

vibration vibrate(int periods, rereference_policy when) {
  using Cfg = method<quadrature::q2>::with_material<material::elastic>;
  const double L = 0.1, H = 0.02, V = 0.05;
  const material::elastic_constants c = test::steel_like();
  auto p = test::grid_problem<Cfg>(vec2(0.0, 0.0), vec2(L, H), Eigen::Vector2i(11, 3), c);
  p.initial_velocity = [=](const vec2& X) -> vec2 { return vec2(V * std::cos(std::numbers::pi * X[0] / L), 0.0); };
  const double plate_speed = std::sqrt(c.youngs_modulus / (c.density * (1.0 - c.poisson_ratio * c.poisson_ratio)));
  run_options o;
  o.end_time = periods * 2.0 * L / plate_speed;
  o.rereference = when;
  auto s = make_solver<Cfg>(std::move(p), o);
  std::vector<double> crossings;
  double previous = 0.0, previous_time = 0.0;
  s.run([&](const auto& s) {
    const double v = s.particle_velocities()[0][0];  // the end at x = 0
    if (previous < 0.0 && v >= 0.0) crossings.push_back(previous_time + (s.time() - previous_time) * -previous / (v - previous));
    previous = v;
    previous_time = s.time();
  }, 1);
  vibration r;
  r.frequency = (crossings.size() - 1) / (crossings.back() - crossings.front());
  r.balance_error = s.energy().balance_error();
  r.rereferences = s.rereferences();
  return r;
}
}  // namespace

TEST_CASE("re-referencing: a homogeneous deformation composes F exactly and keeps the Lagrangian stress") {
  test::run_serially();
  SUBCASE("q2 plane strain") { check_composition<quadrature::q2, geometry::plane_strain>(); }
  SUBCASE("q4 axisymmetric") { check_composition<quadrature::q4, geometry::axisymmetric>(); }
  SUBCASE("scni plane strain") { check_composition<quadrature::scni_plain, geometry::plane_strain>(); }
}

TEST_CASE("re-referencing: a linear field is reproduced on the re-referenced, distorted body") {
  test::run_serially();
  using Cfg = method<quadrature::q2>;
  // A distorted block deformed homogeneously in one step, then re-referenced.
  const vec2 lo(0.0, 0.0), hi(1.2, 1.0);
  auto p = test::grid_problem<Cfg>(lo, hi, Eigen::Vector2i(7, 6));
  test::distort_interior(p.particles, p.mesh, vec2(0.2, 0.2), 0.2);
  mat2 A;
  A << 0.3, 0.5, -0.2, 0.1;
  auto s = test::solver_at<Cfg>(std::move(p), [&](const vec2& X) -> vec2 { return A * X; }, 1e-9);
  s.rereference();
  const discrete_model& m = s.model();
  mat2 B;
  B << -0.1, 0.2, 0.4, 0.05;
  std::vector<vec2> d(m.particle_count());
  for (index_t I = 0; I < m.particle_count(); ++I) d[I] = B * m.particles.position[I] + vec2(0.3, -0.7);
  double worst = 0.0;
  for (const mat3& F : test::deformation_gradients<geometry::plane_strain>(m, d))
    worst = std::max(worst, (F.topLeftCorner<2, 2>() - (mat2::Identity() + B)).cwiseAbs().maxCoeff());
  CHECK(worst < 1e-11);
  // The new reference is the deformed body: each particle at X + A X.
  double moved = 0.0;
  for (index_t I = 0; I < m.particle_count(); ++I) {
    const vec2 X = s.initial_positions()[I];
    moved = std::max(moved, (m.particles.position[I] - (X + A * X)).norm());
  }
  CHECK(moved < 1e-9);
}

TEST_CASE("re-referencing: mass, momentum and kinetic energy kept exactly, the velocity field within O(h^2)") {
  test::run_serially();
  using Cfg = method<quadrature::q2>;
  const vec2 lo(0.0, 0.0), hi(0.06, 0.02);
  auto p = test::grid_problem<Cfg>(lo, hi, Eigen::Vector2i(13, 5));
  // A non-uniform velocity: the block flies, spins and stretches.
  p.initial_velocity = [](const vec2& X) -> vec2 {
    return vec2(30.0 + 2000.0 * X[0] * X[0] - 500.0 * X[1], -10.0 + 800.0 * X[0] + 3000.0 * X[1] * X[1]);
  };
  run_options o;
  o.end_time = 2e-6;
  auto s = make_solver<Cfg>(std::move(p), o);
  s.run();
  const std::vector<double> mass = s.mass();
  const auto momentum = [&] {
    vec2 P = vec2::Zero();
    for (index_t I = 0; I < s.model().particle_count(); ++I) P += s.mass()[I] * s.coefficient_velocities()[I];
    return P;
  };
  for (int k = 0; k < 3; ++k) {
    const vec2 before = momentum();
    const double kinetic = s.kinetic_energy();
    const std::vector<vec2> velocity = s.particle_velocities();
    s.rereference();
    CHECK(s.mass() == mass);
    CHECK(momentum() == before);
    CHECK(s.kinetic_energy() == kinetic);
    // The field on the new kernels differs by the approximation's error: the velocity's second
    // derivatives (4000 and 6000 1/(m s)) times h^2 (5 mm), a few mm/s here; at most 0.2 % of it.
    const std::vector<vec2> after = s.particle_velocities();
    double change = 0.0;
    for (std::size_t I = 0; I < after.size(); ++I) change = std::max(change, (after[I] - velocity[I]).norm());
    CHECK(change < 2e-3 * largest(velocity));
    CHECK(change > 0.0);  // not trivially the same kernels
    s.step();
  }
  CHECK(s.rereferences() == 3);
  CHECK(s.energy().remap == 0.0);
}

TEST_CASE("re-referencing: a spinning block keeps its angular momentum and its energy balance") {
  test::run_serially();
  using Cfg = method<quadrature::q2>::with_material<material::elastic>;
  const double half = 0.01, omega = 2000.0;  // rim speed 28 m/s, about 0.5 % of the wave speed
  auto p = test::grid_problem<Cfg>(vec2(-half, -half), vec2(half, half), Eigen::Vector2i(9, 9));
  p.initial_velocity = [omega](const vec2& X) -> vec2 { return omega * vec2(-X[1], X[0]); };
  run_options o;
  o.end_time = 0.25 * 2.0 * std::numbers::pi / omega;  // a quarter turn
  o.rereference.every_steps = 10;
  auto s = make_solver<Cfg>(std::move(p), o);
  const auto angular = [&] {
    const auto x = s.particle_positions();
    double L = 0.0;
    for (index_t I = 0; I < s.model().particle_count(); ++I) {
      const vec2 v = s.coefficient_velocities()[I];
      L += s.mass()[I] * (x[I][0] * v[1] - x[I][1] * v[0]);
    }
    return L;
  };
  const double L0 = angular();
  s.run();
  CHECK(s.rereferences() >= 10);
  CHECK(std::abs(angular() - L0) < 1e-3 * std::abs(L0));
  CHECK(s.energy().balance_error() < 1e-3);
  CHECK(std::abs(s.energy().remap) < 1e-3 * s.energy().initial_kinetic);
  // Turned by a quarter: the particle that started at (half, 0) is near (0, half).
  const vec2 rim = s.particle_positions()[4 * 9 + 8];
  CHECK(s.initial_positions()[4 * 9 + 8].isApprox(vec2(half, 0.0)));
  CHECK((rim - vec2(0.0, half)).norm() < 0.02 * half);
}

TEST_CASE("re-referencing: no spurious mode; a vibrating strip keeps its frequency and energy over 100 periods") {
  test::run_serially();
  const vibration lagrangian = vibrate(100, {});
  const vibration rebuilt = vibrate(100, {.max_stretch = 0.0, .every_steps = 10});
  CHECK(rebuilt.rereferences > 100);
  CHECK(rebuilt.frequency == doctest::Approx(lagrangian.frequency).epsilon(0.01));
  // Against the plate's long-wave theory, f = c / (2 L), within the coarse strip's dispersion.
  const material::elastic_constants c = test::steel_like();
  const double theory = std::sqrt(c.youngs_modulus / (c.density * (1.0 - c.poisson_ratio * c.poisson_ratio))) / 0.2;
  CHECK(lagrangian.frequency == doctest::Approx(theory).epsilon(0.05));
  // The ledger's own error over 100 periods of this coarse strip (its O(dt^2) trapezoid, about
  // 2 %) is the Lagrangian run's; the rebuilds add nothing to it.
  CHECK(rebuilt.balance_error < 1.02 * lagrangian.balance_error);
}

TEST_CASE("re-referencing in a section: a particle or a point carried across the axis is refused by name") {
  // Reference positions 1 mm across; particle 2 carried to r = -2e-5 m, particle 0 (on the axis)
  // to round-off below it.
  const std::vector<vec2> X{vec2(0.0, 0.0), vec2(5e-4, 0.0), vec2(2e-4, 1e-3)};
  std::vector<vec2> x{vec2(-1e-21, 0.0), vec2(6e-4, 0.0), vec2(2e-4, 1e-3)};
  CHECK_NOTHROW(refuse_across_axis(x, X, false, 0.0));
  x[2][0] = -2e-5;
  const std::string particle = test::error_message([&] { refuse_across_axis(x, X, false, 1e-6); });
  CHECK(test::contains(particle, "particle 2"));
  CHECK(test::contains(particle, "across the axis"));
  CHECK(test::contains(particle, "re-reference earlier"));

  // Two points, one row each, the second carried onto the axis by its particle's displacement.
  quadrature_points points;
  points.position = {vec2(1e-4, 1e-4), vec2(3e-4, 1e-4)};
  points.weight = {1.0, 1.0};
  points.cell = {0, 0};
  shape_table<2> rows;
  rows.offset = {0, 1, 2};
  rows.neighbor = {0, 1};
  rows.N = {1.0, 1.0};
  const auto J = [](index_t) { return 2.0; };
  const std::vector<vec2> d{vec2(1e-5, 0.0), vec2(-3e-4, 0.0)};
  const std::string point = test::error_message([&] { carried_points(points, rows, d, J, true, 2e-6); });
  CHECK(test::contains(point, "quadrature point 1"));
  const quadrature_points plane = carried_points(points, rows, d, J, false, 2e-6);  // plane strain: no axis
  CHECK(plane.position[1][0] == doctest::Approx(0.0).epsilon(1e-12));
  CHECK(plane.weight[0] == 2.0);
}

}  // namespace test_numeric_rereference
