// Two deformable bodies in contact (contact/body_contact.hpp, solver/body_models.hpp), against
// 1D wave theory. Two elastic strips (plane strain, Poisson ratio 0, so that the strip is a 1D bar
// with wave speed c = sqrt(E / rho) exactly) fly at each other at +-V, each slave against the
// other (two passes).
//   - equal lengths L: contact lasts 2 L / c, after which each bar leaves with its velocity
//     reversed (the kinetic energy comes back but for the vibration the discrete impact leaves);
//   - lengths L and 2 L: the shorter leaves at 2 L / c with velocity -V, and the longer keeps the
//     rest of the momentum, (m_1 V - m_2 V + m_1 V) / m_2 = 0 for m_2 = 2 m_1;
//   - total linear momentum is conserved to round-off at every step (the contact force's reaction
//     goes to the master body through rows that sum to one), and no slave ends a step inside the
//     other body by more than 2% of the spacing;
//   - kernels never reach across bodies: every particle's neighbours are of its own body;
//   - a slave twice finer than its master, and twice coarser: no face passes through the other;
//   - Coulomb friction between bodies: a block launched along a deformable slab under a body
//     force g slows at mu g, stops after v0^2 / (2 mu g) and stays.
// The effective-mass and the paper's enforcement both run; the effective mass (of both sides)
// closes each isolated gap in one step.

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/material/elastic.hpp>
#include <rkpm/solver/make_solver.hpp>

#include "support/error_message.hpp"

namespace test_numeric_bodies_in_contact {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

namespace {

constexpr double E = 200e9, rho = 7800.0, V = 1.0;
constexpr double L = 10e-3, H = 1.5e-3, h = 0.25e-3;
// The bars start this far apart; particles with x below half of it belong to the first bar.
constexpr double gap0 = 0.01 * h, split = 0.5 * gap0;
const double c = std::sqrt(E / rho);

// Appends a grid body [lo, hi] with spacing `spacing` to particles and cells (its nodes are its
// particles).
void add_bar(const vec2& lo, const vec2& hi, particle_set<2>& p, background_mesh& m, double spacing = h) {
  const Eigen::Vector2i n(static_cast<int>(std::lround((hi - lo)[0] / spacing)) + 1,
                          static_cast<int>(std::lround((hi - lo)[1] / spacing)) + 1);
  append_body(p, m, make_grid_particles<2>(lo, hi, n, 2.0), make_grid_mesh(lo, hi, n));
}

struct impact {
  double contact_start = -1.0, contact_end = -1.0;  // first and last step time with an active pair
  double first_leaves_velocity = 0.0;               // mean velocity of bar 0 after contact
  double second_velocity = 0.0;                     // of bar 1
  double momentum_error = 0.0;                      // max |P - P0| / (m_0 V)
  double worst_inside = 0.0;                        // deepest slave inside the other bar after a step, / h
  double kinetic_back = 0.0;                        // kinetic energy after / before
  bool kernels_within_bodies = true;
};

// Bar 0 on [-L, 0] with spacing h0 flies at +V into bar 1 of length `second_length` and spacing
// h1 at -V; bar 1 is the slave against bar 0, then bar 0 against bar 1 (two passes) unless
// `one_pass`.
template <class Enforcement>
impact collide(double second_length, double h0 = h, double h1 = h, bool one_pass = false) {
  using Ct = contact::particle_to_segment<Enforcement, contact::friction::frictionless>;
  using Cfg = config<kernel::cubic_spline, correction::linear, quadrature::q2, geometry::plane_strain,
                     material::elastic, Ct>;
  particle_set<2> particles;
  background_mesh mesh;
  add_bar(vec2(-L, 0.0), vec2(0.0, H), particles, mesh, h0);
  add_bar(vec2(gap0, 0.0), vec2(gap0 + second_length, H), particles, mesh, h1);
  std::vector<contact::body_pair> pairs{{1, 0}};
  if (!one_pass) pairs.push_back({0, 1});
  problem_for<Cfg> p{.particles = std::move(particles),
                     .mesh = std::move(mesh),
                     .material = material::elastic({E, 0.0, rho}),
                     .contact = Ct({}, std::move(pairs)),
                     .initial_velocity = [](const vec2& X) { return vec2(X[0] < split ? V : -V, 0.0); }};
  run_options o;
  const double duration = 2.0 * std::min(L, second_length) / c;
  o.end_time = gap0 / (2.0 * V) + 1.6 * duration;
  auto s = make_solver<Cfg>(std::move(p), o);

  const auto& X = s.model().particles.position;
  const auto n = s.model().particle_count();
  impact r;
  const auto& rows = s.model().at_particles;
  for (index_t I = 0; I < n; ++I)
    for (index_t e = rows.offset[I]; e < rows.offset[I + 1]; ++e)
      r.kernels_within_bodies = r.kernels_within_bodies && ((X[I][0] < split) == (X[rows.neighbor[e]][0] < split));

  auto bar_momentum = [&](bool first) {
    double P = 0.0, M = 0.0;
    for (index_t I = 0; I < n; ++I)
      if ((X[I][0] < split) == first) {
        P += s.mass()[I] * s.coefficient_velocities()[I][0];
        M += s.mass()[I];
      }
    return std::pair{P, M};
  };
  const double m0 = bar_momentum(true).second;
  const double P0 = bar_momentum(true).first + bar_momentum(false).first;
  const double K0 = s.kinetic_energy();
  while (s.time() < o.end_time * (1.0 - 1e-12)) {
    s.step();
    const double P = bar_momentum(true).first + bar_momentum(false).first;
    r.momentum_error = std::max(r.momentum_error, std::abs(P - P0) / (m0 * V));
    if (s.last_contact().active > 0) {
      if (r.contact_start < 0.0) r.contact_start = s.time();
      r.contact_end = s.time();
    }
    // Slaves of each bar inside the other: x beyond the other's current end face.
    const auto x = s.particle_positions();
    double face0 = -1e300, face1 = 1e300;
    for (index_t I = 0; I < n; ++I) {
      if (X[I][0] < split) face0 = std::max(face0, x[I][0]);
      else face1 = std::min(face1, x[I][0]);
    }
    r.worst_inside = std::max(r.worst_inside, (face0 - face1) / std::min(h0, h1));
  }
  r.first_leaves_velocity = bar_momentum(true).first / m0;
  r.second_velocity = bar_momentum(false).first / bar_momentum(false).second;
  r.kinetic_back = s.kinetic_energy() / K0;
  return r;
}

double relative(double measured, double expected) { return std::abs(measured - expected) / std::abs(expected); }

}  // namespace

TEST_CASE_TEMPLATE("two equal elastic bars: contact lasts 2L/c and the velocities reverse", Enforcement,
                   contact::enforcement::effective_mass, contact::enforcement::paper) {
  const impact r = collide<Enforcement>(L);
  const double t0 = gap0 / (2.0 * V);  // the gap closes
  const double duration = r.contact_end - r.contact_start;
  MESSAGE("contact from " << r.contact_start * 1e6 << " us to " << r.contact_end * 1e6 << " us: " << duration * 1e6
                          << " us against 2L/c = " << 2.0 * L / c * 1e6 << " us; velocities after " << r.first_leaves_velocity
                          << ", " << r.second_velocity << " m/s; kinetic energy back " << r.kinetic_back
                          << "; momentum error " << r.momentum_error << "; deepest slave inside " << r.worst_inside
                          << " h");
  CHECK(r.kernels_within_bodies);
  // The gap closes within a step of t0; the discrete unloading front is a few spacings wide, so
  // the bars part a little after 2 L / c (40 spacings per bar here).
  CHECK(std::abs(r.contact_start - t0) < 0.1 * 2.0 * L / c);
  CHECK(relative(duration, 2.0 * L / c) < 0.05);
  CHECK(relative(r.first_leaves_velocity, -V) < 0.05);
  CHECK(relative(r.second_velocity, V) < 0.05);
  CHECK(r.kinetic_back > 0.85);
  CHECK(r.kinetic_back < 1.0);  // contact takes energy (the vibration it leaves), never gives
  CHECK(r.momentum_error < 1e-12);
  CHECK(r.worst_inside < 0.02);
}

TEST_CASE("bars of lengths L and 2L: the shorter leaves first, at -V, and the longer stops") {
  const impact r = collide<contact::enforcement::effective_mass>(2.0 * L);
  const double duration = r.contact_end - r.contact_start;
  MESSAGE("contact " << duration * 1e6 << " us against 2L/c = " << 2.0 * L / c * 1e6 << " us; short bar "
                     << r.first_leaves_velocity << " m/s, long bar " << r.second_velocity << " m/s");
  CHECK(relative(duration, 2.0 * L / c) < 0.1);
  CHECK(relative(r.first_leaves_velocity, -V) < 0.05);
  CHECK(std::abs(r.second_velocity) < 0.05 * V);
  CHECK(r.momentum_error < 1e-12);
}

TEST_CASE("slave finer than master and master finer than slave: no face passes through the other") {
  for (const auto& [h0, h1] : {std::pair{2.0 * h, h}, std::pair{h, 2.0 * h}}) {
    const impact r = collide<contact::enforcement::effective_mass>(L, h0, h1, true);
    const double duration = r.contact_end - r.contact_start;
    MESSAGE("master spacing " << h0 * 1e3 << " mm, slave " << h1 * 1e3 << " mm: contact " << duration * 1e6
                              << " us, velocities after " << r.first_leaves_velocity << ", " << r.second_velocity
                              << " m/s; deepest face overlap " << r.worst_inside << " of the finer spacing");
    CHECK(r.kernels_within_bodies);
    CHECK(r.worst_inside < 0.02);
    CHECK(relative(duration, 2.0 * L / c) < 0.1);
    CHECK(relative(r.first_leaves_velocity, -V) < 0.1);
    CHECK(r.momentum_error < 1e-12);
  }
}

TEST_CASE("a block sliding on a deformable slab decelerates at mu g and stops where Coulomb says") {
  // A soft block (spacing 10 mm) on a soft slab fixed at its bottom, pressed by a body force g
  // and launched at v0 along the surface: its mean velocity falls as v0 - mu g t and it stops
  // after v0^2 / (2 mu g), and then stays (it sticks). Soft material (20 MPa) and a large g keep
  // the run to a few hundred steps; the block is set down unloaded, so its normal force swings
  // about m g while it slides, and the slab's shear spring shakes it a little after it stops.
  using Ct = contact::particle_to_segment<contact::enforcement::effective_mass, contact::friction::coulomb>;
  using Cfg = config<kernel::cubic_spline, correction::linear, quadrature::q2, geometry::plane_strain,
                     material::elastic, Ct>;
  constexpr double s = 0.01, g = 200.0, mu = 0.3, v0 = 1.0;
  particle_set<2> particles;
  background_mesh mesh;
  add_bar(vec2(-0.3, -0.04), vec2(0.3, 0.0), particles, mesh, s);  // body 0: the slab
  const auto slab = particles.size();
  add_bar(vec2(-0.05, 0.0), vec2(0.05, 0.03), particles, mesh, s);  // body 1: the block
  std::vector<velocity_constraint> fixed;
  for (index_t I = 0; I < slab; ++I)
    if (particles.position[I][1] < -0.04 + 1e-9)
      for (int k : {0, 1}) fixed.push_back({I, k, [](double) { return 0.0; }});
  problem_for<Cfg> p{.particles = std::move(particles),
                     .mesh = std::move(mesh),
                     .material = material::elastic({2e7, 0.3, 1000.0}),
                     .contact = Ct({}, {contact::body_pair{1, 0}}, contact::friction::coulomb{mu}),
                     .initial_velocity = {},
                     .initial_particle_velocity = [slab](index_t I, const vec2&) {
                       return vec2(I < slab ? 0.0 : v0, 0.0);
                     },
                     .constraints = std::move(fixed),
                     .body_force = vec2(0.0, -g)};
  const double t_stop = v0 / (mu * g), x_stop = v0 * v0 / (2.0 * mu * g);
  run_options o;
  o.end_time = 1.5 * t_stop;
  auto solver = make_solver<Cfg>(std::move(p), o);
  const auto n = solver.model().particle_count();
  auto block = [&] {  // mean x-velocity and x-position of the block
    double P = 0.0, M = 0.0, X = 0.0;
    const auto x = solver.particle_positions();
    for (index_t I = slab; I < n; ++I) {
      P += solver.mass()[I] * solver.coefficient_velocities()[I][0];
      X += solver.mass()[I] * x[I][0];
      M += solver.mass()[I];
    }
    return std::pair{P / M, X / M};
  };
  const double x0 = block().second;
  double v_half = 0.0, worst_after_stop = 0.0;
  while (solver.time() < o.end_time * (1.0 - 1e-12)) {
    solver.step();
    if (v_half == 0.0 && solver.time() >= 0.5 * t_stop) v_half = block().first;
    if (solver.time() > 1.1 * t_stop) worst_after_stop = std::max(worst_after_stop, std::abs(block().first));
  }
  const double travelled = block().second - x0;
  MESSAGE("velocity at t_stop / 2: " << v_half << " m/s (Coulomb " << 0.5 * v0 << "); travelled " << travelled * 1e3
                                     << " mm (Coulomb " << x_stop * 1e3 << " mm); largest |v| after stopping "
                                     << worst_after_stop << " m/s; " << solver.steps() << " steps");
  CHECK(relative(v_half, 0.5 * v0) < 0.05);
  CHECK(relative(travelled, x_stop) < 0.05);
  CHECK(worst_after_stop < 0.05 * v0);
}

TEST_CASE("bad input: overlapping bodies, a pair naming a body that does not exist") {
  using Ct = contact::particle_to_segment<contact::enforcement::effective_mass, contact::friction::frictionless>;
  using Cfg = config<kernel::cubic_spline, correction::linear, quadrature::q2, geometry::plane_strain,
                     material::elastic, Ct>;
  auto make = [](double second_start, index_t master) {
    particle_set<2> particles;
    background_mesh mesh;
    add_bar(vec2(-L, 0.0), vec2(0.0, H), particles, mesh);
    add_bar(vec2(second_start, 0.0), vec2(second_start + L, H), particles, mesh);
    problem_for<Cfg> p{.particles = std::move(particles),
                       .mesh = std::move(mesh),
                       .material = material::elastic({E, 0.3, rho}),
                       .contact = Ct({}, {contact::body_pair{0, master}})};
    run_options o;
    o.end_time = 1e-6;
    return make_solver<Cfg>(std::move(p), o);
  };
  const std::string overlap = test::error_message([&] { make(-2.0 * h, 1); });
  CHECK(overlap.find("bodies 0 and 1 overlap") != std::string::npos);
  CHECK(overlap.find("move the bodies apart") != std::string::npos);
  const std::string missing = test::error_message([&] { make(h, 2); });
  CHECK(missing.find("body 2 does not exist") != std::string::npos);
  // Touching bodies are allowed.
  CHECK(test::error_message([&] { make(0.0, 1); }).empty());
}

}  // namespace test_numeric_bodies_in_contact
