// A sticking interface while the body deforms (issue 9, "Friction that sticks"): an elastic block
// on a fixed rigid floor with Coulomb friction, its top row driven (velocity constraints on the
// physical velocities, section 5.7): first pressed down by 4% of its height, then sheared
// sideways by 4% of its height (0.4 of the spacing h), then held. The floor carries a tangential
// load of about 0.2 N, far below mu N, so the bottom slaves that touch the floor at t = 0 must stay
// where they started: their slip x_J - X_J along the floor is the error of the stick condition
// (P6), (57). Measured with a coefficient so large that friction never limits (every slave must
// stick) and with mu = 1 (the load ratio stays below 0.25 everywhere along the row here); and, to
// show the measure can tell, with mu below the load ratio, where the row must slide.
//   effective_mass (its 5 sweeps with the shared effective mass (61a)): the slip stays below 2% of h
//     and does not grow while the block is held. With (61)'s m_eff in its place the row slipped
//     by about 2 h and kept creeping: each sweep's correction overshot about twice and pushed
//     slaves off the floor, where the Coulomb cap dropped their friction.
//   paper and penalty (one sweep): they hold the block to about 0.1 h of slip; penalty with m_eff
//     in (P6) blew up (the slip reversed every step, undamped).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <type_traits>
#include <vector>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/material/elastic.hpp>
#include <rkpm/solver/make_solver.hpp>

namespace test_numeric_contact_stick {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

namespace {

// Soft elastic block, 0.1 m square, 11 x 11 particles (h = 0.01 m), resting on the floor y = 0.
constexpr double E = 1e6, nu = 0.3, rho = 1000.0, W = 0.1, H = 0.1, h = 0.01;
constexpr int nx = 11, ny = 11;
// Loading: press by U_press over [0, T_press], shear by U_shear over [T_press, T_press + T_shear],
// hold until T_end. The ramps are 10 times the time a shear wave needs to cross the block
// (H / sqrt(G / rho) = 5 ms): quasi-static, with little ringing.
constexpr double U_press = 0.04 * H, U_shear = 0.04 * H;
constexpr double T_press = 0.05, T_shear = 0.05, T_end = 0.15;

// Velocity of a smooth ramp that moves by U over [t0, t0 + T]: U / T (1 - cos(2 pi (t - t0) / T)).
double ramp_velocity(double U, double t0, double T, double t) {
  if (t < t0 || t > t0 + T) return 0.0;
  return U / T * (1.0 - std::cos(2.0 * std::numbers::pi * (t - t0) / T));
}

struct stick_record {
  double worst_slip = 0.0;           // largest |x_J - X_J| along the floor, bottom slaves, whole run
  double worst_interior_slip = 0.0;  // the same without the two outermost slaves on each side
  double hold_creep = 0.0;           // largest change of a bottom slave's slip during the hold
  double load_ratio = 0.0;           // largest |R_t| / |R_n| on the floor once pressed
  double worst_depth = 0.0;          // deepest penetration of a slave into the floor
  std::vector<double> final_slip;    // per bottom slave, x_J - X_J at the end
};

template <class Enforcement>
stick_record press_and_shear(double mu, Enforcement enforcement) {
  using contact_t = contact::particle_to_segment<Enforcement, contact::friction::coulomb>;
  using cfg = config<kernel::cubic_spline, correction::linear, quadrature::q4, geometry::plane_strain,
                     material::elastic, contact_t>;
  const vec2 lo(0.0, 0.0), hi(W, H);
  const contact::rigid_tool floor("floor", {vec2(-1.0, 0.0), vec2(1.0, 0.0)}, contact::side::left);
  std::vector<velocity_constraint> top;
  for (int i = 0; i < nx; ++i) {
    const index_t I = i + nx * (ny - 1);
    top.push_back({I, 0, [](double t) { return ramp_velocity(U_shear, T_press, T_shear, t); }});
    top.push_back({I, 1, [](double t) { return -ramp_velocity(U_press, 0.0, T_press, t); }});
  }
  problem_for<cfg> p{.particles = make_grid_particles<2>(lo, hi, Eigen::Vector2i(nx, ny), 2.0),
                     .mesh = make_grid_mesh(lo, hi, Eigen::Vector2i(nx, ny)),
                     .material = material::elastic(material::elastic_constants{E, nu, rho}),
                     .contact = contact_t({floor}, contact::friction::coulomb{mu}, enforcement),
                     .initial_velocity = {},
                     .constraints = std::move(top)};
  run_options o;
  o.end_time = T_end;
  auto s = make_solver<cfg>(std::move(p), o);
  stick_record r;
  std::vector<double> slip_at_hold(nx, 0.0);
  bool holding = false;
  s.run(
      [&](const auto& s) {
        const auto x = s.particle_positions();
        const auto& X = s.model().particles.position;
        for (int i = 0; i < nx; ++i) {
          const double slip = x[i].x() - X[i].x();
          r.worst_slip = std::max(r.worst_slip, std::abs(slip));
          if (i >= 2 && i < nx - 2) r.worst_interior_slip = std::max(r.worst_interior_slip, std::abs(slip));
          if (holding) r.hold_creep = std::max(r.hold_creep, std::abs(slip - slip_at_hold[i]));
          r.worst_depth = std::max(r.worst_depth, -x[i].y());
        }
        if (!holding && s.time() >= T_press + T_shear) {
          holding = true;
          for (int i = 0; i < nx; ++i) slip_at_hold[i] = x[i].x() - X[i].x();
        }
        const vec2 R = s.contact().reactions()[0];
        if (s.time() > 0.5 * T_press && std::abs(R.y()) > 0.0)
          r.load_ratio = std::max(r.load_ratio, std::abs(R.x()) / std::abs(R.y()));
      },
      1);
  const auto x = s.particle_positions();
  for (int i = 0; i < nx; ++i) r.final_slip.push_back(x[i].x() - s.model().particles.position[i].x());
  return r;
}

template <class Enforcement>
void report(const std::string& what, double mu, const stick_record& r) {
  MESSAGE(Enforcement::name, ", ", what, " (mu = ", mu, "): largest slip ", r.worst_slip / h, " h, interior ",
          r.worst_interior_slip / h, " h, creep during the hold ", r.hold_creep / h, " h, largest |R_t|/|R_n| ",
          r.load_ratio, ", deepest penetration ", r.worst_depth / h, " h");
  std::string line;
  for (double s : r.final_slip) line += fmt::format(" {:+.4f}", s / h);
  MESSAGE("  final slip of the bottom row / h:", line);
}

}  // namespace

TEST_CASE("effective_mass: a pressed and sheared block sticks to the floor while it deforms") {
  for (const double mu : {1e3, 1.0}) {
    const auto r = press_and_shear(mu, contact::enforcement::effective_mass{});
    report<contact::enforcement::effective_mass>(mu > 10.0 ? "friction never limits" : "Coulomb", mu, r);
    REQUIRE(r.load_ratio > 0.1);       // the floor really carries a tangential load ...
    REQUIRE(r.load_ratio < 0.5 * mu);  // ... below mu N
    CHECK(r.worst_slip < 0.02 * h);    // 5% of the imposed shear displacement
    CHECK(r.hold_creep < 0.005 * h);   // no creep while held
    CHECK(r.worst_depth < 0.01 * h);
  }
}

TEST_CASE_TEMPLATE("one-sweep forms: a pressed and sheared block stays near where it stuck", E_,
                   contact::enforcement::paper, contact::enforcement::penalty) {
  E_ e{};
  // Penalty: the floor carries about 5 kN/m over 11 slaves; k = 5e5 N/m lets them sink about 0.1 h
  // and keeps k / m_sh well inside the stable step.
  if constexpr (requires { e.stiffness = 1.0; }) e.stiffness = 5e5;
  const double mu = 1.0;
  const auto r = press_and_shear(mu, e);
  report<E_>("Coulomb", mu, r);
  REQUIRE(r.load_ratio > 0.1);
  REQUIRE(r.load_ratio < 0.75 * mu);
  CHECK(r.worst_slip < 0.2 * h);  // half the imposed shear displacement
}

TEST_CASE_TEMPLATE("a tangential load close to mu N: the interior still sticks", E_, contact::enforcement::paper,
                   contact::enforcement::effective_mass) {
  // mu = 0.3 against a load ratio of about 0.21: the Coulomb cap is near, so every step in which
  // a slave's normal force comes out low lets it slip (the paper's one-sweep normal force varies
  // from step to step along a row).
  const double mu = 0.3;
  const auto r = press_and_shear(mu, E_{});
  report<E_>("near the cap", mu, r);
  REQUIRE(r.load_ratio < mu);
  if constexpr (std::is_same_v<E_, contact::enforcement::effective_mass>) {
    CHECK(r.worst_interior_slip < 0.02 * h);
    CHECK(r.hold_creep < 0.005 * h);
  }
}

TEST_CASE("the slip measure tells: below the load ratio the row slides, at mu N") {
  const double mu = 0.05;
  const auto r = press_and_shear(mu, contact::enforcement::effective_mass{});
  report<contact::enforcement::effective_mass>("sliding", mu, r);
  CHECK(r.worst_interior_slip > 0.2 * h);
  CHECK(r.load_ratio == doctest::Approx(mu).epsilon(0.05));
}

}  // namespace test_numeric_contact_stick
