// Bodies with their own material constants (problem::body_materials, add_body;
// solver/body_materials.hpp), against 1D wave theory. Two elastic strips (plane strain, Poisson
// ratio 0: each a 1D bar, c = sqrt(E / rho)) of different impedance Z = rho c fly at each other
// at +-V, each slave against the other:
//   - while they touch, the interface moves at v_i = (Z0 v0 + Z1 v1) / (Z0 + Z1), on both sides;
//   - contact lasts 2 L / c of the bar whose round trip is shorter (beryllium here, which also has
//     the lower impedance, so the bars do part then); that bar then leaves stress-free at
//     2 v_i - v0, and the other keeps the rest of the momentum;
//   - total linear momentum is conserved to round-off;
//   - the stable step of the pair is that of the faster bar alone (each bar's own solver);
//   - the same material given per body gives the numbers of `material` bit for bit;
//   - a bad constant in a body of the user's own material (one whose constructor does not check)
//     stops set-up with an error naming the body; a wrong count of body materials too.

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <string_view>
#include <vector>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/material/elastic.hpp>
#include <rkpm/solver/make_solver.hpp>

#include "support/error_message.hpp"

namespace test_numeric_bodies_of_two_materials {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

namespace {

constexpr double V = 1.0, L = 10e-3, H = 1.5e-3, h = 0.25e-3;
constexpr double gap0 = 0.01 * h, split = 0.5 * gap0;  // the bars start this far apart
// Beryllium against steel: the lower impedance (Z = 2.3e7 against 3.95e7 kg/m^2/s) with the
// faster wave (12.5 km/s against 5.1): beryllium's round trip 2 L / c (1.6 us) is the shorter, so
// the bars part then (the lower-impedance bar must be the one that comes back first: the other way
// round the faster bar's face would be caught up by the released face of the other), and
// beryllium sets the stable step.
const material::elastic_constants steel{200e9, 0.0, 7800.0}, beryllium{287e9, 0.0, 1850.0};
double wave_speed(const material::elastic_constants& k) { return std::sqrt(k.youngs_modulus / k.density); }
double impedance(const material::elastic_constants& k) { return k.density * wave_speed(k); }

using Ct = contact::particle_to_segment<contact::enforcement::effective_mass, contact::friction::frictionless>;
using Cfg = config<kernel::cubic_spline, correction::linear, quadrature::q2, geometry::plane_strain,
                   material::elastic, Ct>;

std::pair<particle_set<2>, background_mesh> bar(const vec2& lo, const vec2& hi) {
  const Eigen::Vector2i n(static_cast<int>(std::lround((hi - lo)[0] / h)) + 1,
                          static_cast<int>(std::lround((hi - lo)[1] / h)) + 1);
  return {make_grid_particles<2>(lo, hi, n, 2.0), make_grid_mesh(lo, hi, n)};
}

// Bar 0 on [-L, 0] at +V, bar 1 on [gap0, gap0 + L] at -V; materials per body, or `shared` for both.
problem_for<Cfg> two_bars(const material::elastic_constants& k0, const material::elastic_constants& k1,
                          bool per_body = true) {
  problem_for<Cfg> p{.material = material::elastic(k0),
                     .contact = Ct(std::vector<contact::rigid_tool>{}),
                     .initial_velocity = [](const vec2& X) { return vec2(X[0] < split ? V : -V, 0.0); }};
  const auto [p0, m0] = bar(vec2(-L, 0.0), vec2(0.0, H));
  const auto [p1, m1] = bar(vec2(gap0, 0.0), vec2(gap0 + L, H));
  index_t b0 = 0, b1 = 1;
  if (per_body) {
    b0 = add_body(p, p0, m0, material::elastic(k0));
    b1 = add_body(p, p1, m1, material::elastic(k1));
  } else {
    append_body(p.particles, p.mesh, p0, m0);
    append_body(p.particles, p.mesh, p1, m1);
  }
  p.contact = Ct({}, {contact::body_pair{b1, b0}, contact::body_pair{b0, b1}});
  return p;
}

double relative(double measured, double expected) { return std::abs(measured - expected) / std::abs(expected); }

}  // namespace

TEST_CASE("bars of different impedance: interface velocity, contact duration and speeds after, from wave theory") {
  // Bar 0 beryllium (the lower impedance, the shorter round trip) at +V, bar 1 steel at -V.
  const double c0 = wave_speed(beryllium), c1 = wave_speed(steel);
  const double Z0 = impedance(beryllium), Z1 = impedance(steel);
  const double v_i = (Z0 * V - Z1 * V) / (Z0 + Z1);
  const double t0 = gap0 / (2.0 * V), duration = 2.0 * L / c0;
  run_options o;
  o.end_time = t0 + 1.6 * duration;  // steel's wave comes back to its face at t0 + 2 L / c1, later
  REQUIRE(o.end_time < t0 + 2.0 * L / c1);
  auto s = make_solver<Cfg>(two_bars(beryllium, steel), o);
  const auto& X = s.model().particles.position;
  const auto n = s.model().particle_count();
  CHECK(s.bodies() == 2);
  CHECK(s.material(1).density() == steel.density);
  for (index_t I = 0; I < n; ++I) REQUIRE(s.body_of_particle(I) == (X[I][0] < split ? 0 : 1));

  auto momentum = [&](int body) {  // body -1: both
    double P = 0.0, M = 0.0;
    for (index_t I = 0; I < n; ++I)
      if (s.body_of_particle(I) == body || body < 0) {
        P += s.mass()[I] * s.coefficient_velocities()[I][0];
        M += s.mass()[I];
      }
    return std::pair{P, M};
  };
  // Mean x of each bar's impact face: the face particles ring (a spacing-sized wave each side),
  // their mean position does not, so the face velocity is read from its displacement.
  auto faces = [&] {
    const auto x = s.particle_positions();
    std::array<double, 2> sum{0.0, 0.0}, count{0.0, 0.0};
    for (index_t I = 0; I < n; ++I)
      for (int b : {0, 1})
        if (std::abs(X[I][0] - (b == 0 ? 0.0 : gap0)) < 1e-3 * h) {
          sum[b] += x[I][0];
          count[b] += 1.0;
        }
    return std::array<double, 2>{sum[0] / count[0], sum[1] / count[1]};
  };
  const double m0 = momentum(0).second, m1 = momentum(1).second;
  // Masses from each body's own density: rho_b L H (per unit thickness).
  CHECK(relative(m0, beryllium.density * L * H) < 1e-9);
  CHECK(relative(m1, steel.density * L * H) < 1e-9);
  const double P0 = momentum(-1).first;
  double momentum_error = 0.0, start = -1.0, end = -1.0;
  // The face velocity over the middle of the contact, [t0 + 0.2, t0 + 0.8] x duration.
  std::array<double, 2> face_a{}, face_b{}, face_velocity{};
  double time_a = -1.0, time_b = -1.0;
  while (s.time() < o.end_time * (1.0 - 1e-12)) {
    s.step();
    momentum_error = std::max(momentum_error, std::abs(momentum(-1).first - P0) / (m0 * V));
    if (s.last_contact().active > 0) {
      if (start < 0.0) start = s.time();
      end = s.time();
    }
    if (time_a < 0.0 && s.time() >= t0 + 0.2 * duration) {
      time_a = s.time();
      face_a = faces();
    }
    if (time_b < 0.0 && s.time() >= t0 + 0.8 * duration) {
      time_b = s.time();
      face_b = faces();
    }
  }
  for (int b : {0, 1}) face_velocity[b] = (face_b[b] - face_a[b]) / (time_b - time_a);
  const double after0 = momentum(0).first / m0, after1 = momentum(1).first / m1;
  const double expected0 = 2.0 * v_i - V, expected1 = (P0 - m0 * expected0) / m1;
  MESSAGE("Z0 / Z1 = " << Z0 / Z1 << "; interface velocity " << face_velocity[0] << " (beryllium face), "
                       << face_velocity[1] << " (steel face) against v_i = " << v_i << " m/s; contact "
                       << (end - start) * 1e6 << " us against 2 L / c0 = " << duration * 1e6
                       << " us; after: beryllium " << after0 << " (theory " << expected0 << "), steel " << after1
                       << " (theory " << expected1 << ") m/s; momentum error " << momentum_error);
  CHECK(relative(face_velocity[0], v_i) < 0.03);
  CHECK(relative(face_velocity[1], v_i) < 0.03);
  CHECK(std::abs(start - t0) < 0.1 * duration);
  // The parting is gradual: the discrete unloading front spans a few spacings (h / c0 = 20 ns
  // each) and the faces part at only 0.5 m/s. The overshoot converges with h: 7.5% at this
  // spacing, 3.4% at h / 2.
  CHECK(relative(end - start, duration) < 0.10);
  CHECK(relative(after0, expected0) < 0.03);
  CHECK(relative(after1, expected1) < 0.03);
  CHECK(momentum_error < 1e-12);
}

TEST_CASE("the stable step of two bodies is the faster body's, and one material per body changes nothing") {
  run_options o;
  o.end_time = 2e-6;
  auto one_bar = [&](const material::elastic_constants& k) {
    problem_for<Cfg> p{.material = material::elastic(k), .contact = Ct(std::vector<contact::rigid_tool>{})};
    const auto [particles, mesh] = bar(vec2(-L, 0.0), vec2(0.0, H));
    add_body(p, particles, mesh, material::elastic(k));
    return make_solver<Cfg>(std::move(p), o).reference_stable_step();
  };
  const double dt_steel = one_bar(steel), dt_fast = one_bar(beryllium);
  // Steel first, so that the faster body is not body 0.
  const double dt_pair = make_solver<Cfg>(two_bars(steel, beryllium), o).reference_stable_step();
  MESSAGE("stable step: steel bar " << dt_steel << " s, beryllium bar " << dt_fast << " s (ratio " << dt_steel / dt_fast
                                    << ", c_Be / c_steel = " << wave_speed(beryllium) / wave_speed(steel)
                                    << "), the pair " << dt_pair << " s");
  // Same grid: the step scales as 1 / c.
  CHECK(relative(dt_steel / dt_fast, wave_speed(beryllium) / wave_speed(steel)) < 0.02);
  // Power iteration approaches omega_max from below, to about 1e-3 in 100 iterations.
  CHECK(relative(dt_pair, dt_fast) < 0.01);

  // Both bars steel: per body or shared, the same run to the last bit.
  auto a = make_solver<Cfg>(two_bars(steel, steel, true), o);
  auto b = make_solver<Cfg>(two_bars(steel, steel, false), o);
  a.run();
  b.run();
  CHECK(a.steps() == b.steps());
  CHECK(a.mass() == b.mass());
  CHECK(a.coefficients() == b.coefficients());
  CHECK(a.coefficient_velocities() == b.coefficient_velocities());
}

namespace {

// A user's own material whose constructor does not check its constants (the Material concept
// does not ask it to): Hencky elasticity through material::elastic, built at each call.
struct unchecked_elastic {
  static constexpr std::string_view name = "unchecked_elastic";
  using state_type = material::elastic_state;
  material::elastic_constants k;
  state_type initial_state() const { return {}; }
  mat3 kirchhoff_stress(const mat3& F, state_type& s) const { return material::elastic(k).kirchhoff_stress(F, s); }
  double density() const { return k.density; }
  double dilatational_wave_speed() const { return k.dilatational_wave_speed(); }
  const material::elastic_constants& constants() const { return k; }
};

}  // namespace

TEST_CASE("bad input: a wrong constant in body 2, a wrong number of body materials, a body in two parts") {
  using UCt = contact::particle_to_segment<contact::enforcement::effective_mass, contact::friction::frictionless>;
  using UCfg = config<kernel::cubic_spline, correction::linear, quadrature::q2, geometry::plane_strain,
                      unchecked_elastic, UCt>;
  auto three_bars = [](double third_density, bool drop_last) {
    problem_for<UCfg> p{.material = unchecked_elastic{steel}, .contact = UCt(std::vector<contact::rigid_tool>{})};
    for (int k = 0; k < 3; ++k) {
      const double x = k * (L + h);
      const auto [particles, mesh] = bar(vec2(x, 0.0), vec2(x + L, H));
      add_body(p, particles, mesh, unchecked_elastic{{200e9, 0.0, k == 2 ? third_density : 7800.0}});
    }
    if (drop_last) p.body_materials.pop_back();
    run_options o;
    o.end_time = 1e-7;
    return make_solver<UCfg>(std::move(p), o);
  };
  CHECK(test::error_message([&] { three_bars(7800.0, false); }).empty());
  const std::string bad = test::error_message([&] { three_bars(-1.0, false); });
  MESSAGE(bad);
  CHECK(test::contains(bad, "body 2 (problem::body_materials[2])"));
  CHECK(test::contains(bad, "density = -1"));
  const std::string count = test::error_message([&] { three_bars(7800.0, true); });
  MESSAGE(count);
  CHECK(test::contains(count, "2 body_materials for 3 bodies"));

  // add_body takes one connected body at a time, so that the number it returns is the body's.
  problem_for<Cfg> p{.material = material::elastic(steel), .contact = Ct(std::vector<contact::rigid_tool>{})};
  auto [particles, mesh] = bar(vec2(0.0, 0.0), vec2(L, H));
  const auto [p2, m2] = bar(vec2(2.0 * L, 0.0), vec2(3.0 * L, H));
  append_body(particles, mesh, p2, m2);
  const std::string parts = test::error_message([&] { add_body(p, particles, mesh, material::elastic(steel)); });
  MESSAGE(parts);
  CHECK(test::contains(parts, "form 2 separate bodies"));
}

}  // namespace test_numeric_bodies_of_two_materials
