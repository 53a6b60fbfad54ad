// particle_to_segment against theory, driving enforce() directly:
//   (P4) with an identity table (N_I(X_J) = delta_IJ): the gap closes exactly in one step;
//   with a real RK table: effective_mass puts an isolated particle on the segment, the paper's
//   form closes the fraction m_s sum_I N_I^2 / m_I of the gap;
//   friction (P5)/(P6): frictionless keeps v_T, Coulomb caps at mu |f_n|, below the cap it sticks;
//   redistribution (P7): force and moment of the f_I equal those of the f_J (linear reproduction).
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <vector>

#include <rkpm/correction/polynomial_bases.hpp>
#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/solver/energy.hpp>
#include <rkpm/discretization/particle_set.hpp>
#include <rkpm/discretization/shape_table.hpp>
#include <rkpm/kernel/cubic_spline.hpp>

#include "support/contact_fixtures.hpp"

using namespace rkpm;
using namespace rkpm::contact;
using rkpm::test::identity_body;

namespace {


// A 9 x 9 RK grid on the unit square (linear correction, cubic spline, support 2h); the slaves are
// its boundary particles. Masses rho dV_I with a little variation so that m_I differ.
struct rk_body {
  particle_set<2> particles = make_grid_particles<2>(vec2(0, 0), vec2(1, 1), Eigen::Vector2i(9, 9), 2.0);
  std::vector<vec2> X = particles.position;
  std::vector<double> m;
  contact_slaves slaves;
  rk_body() {
    for (index_t I = 0; I < particles.size(); ++I) m.push_back(1000.0 * particles.volume[I] * (1.0 + 0.1 * std::sin(3.0 * I)));
    std::vector<vec2> at;
    for (index_t I = 0; I < particles.size(); ++I) {
      const vec2& p = X[I];
      if (p.x() == 0.0 || p.y() == 0.0 || p.x() == 1.0 || p.y() == 1.0) {
        slaves.particle.push_back(I);
        at.push_back(p);
      }
    }
    const neighbor_search<2> search(particles);
    slaves.table = build_shape_table<kernel::cubic_spline, correction::linear, 2>(search, at);
  }
  contact_body view() const { return {X, m}; }
  index_t row_of(index_t I) const {
    for (index_t j = 0; j < static_cast<index_t>(slaves.particle.size()); ++j)
      if (slaves.particle[j] == I) return j;
    return -1;
  }
  vec2 position(index_t j, const std::vector<vec2>& d) const { return X[slaves.particle[j]] + slaves.table.interpolate(j, d); }
};

rigid_tool floor_tool(double y = 0.0) { return rigid_tool("floor", {{-1, y}, {2, y}}, side::left); }

// The work of the velocity jumps before -> after of every particle, with the previous
// half-step velocity taken as `before`, summed (solver/energy.hpp's impulse_work_at).
double jump_work(const std::vector<double>& m, const std::vector<rkpm::vec2>& after,
                        const std::vector<rkpm::vec2>& before) {
  double w = 0.0;
  for (std::size_t I = 0; I < m.size(); ++I) w += rkpm::impulse_work_at(m[I], after[I], before[I], before[I]);
  return w;
}

}  // namespace

TEST_CASE_TEMPLATE("(P4) identity table: the gap closes exactly in one step", E, enforcement::paper,
                   enforcement::effective_mass) {
  identity_body body{{{0.5, 0.1}, {0.8, 0.1}, {1.5, 0.3}}, {2.0, 3.0, 5.0}};
  particle_to_segment<E> contact({floor_tool()});
  contact.setup(body.view(), body.slaves());
  const double dt = 1e-3;
  std::vector<vec2> d = {{0.0, -0.12}, {0.0, -0.05}, {0.0, 0.0}};  // particle 0 is 0.02 below the floor
  std::vector<vec2> v = {{0.0, -120.0}, {0.0, -50.0}, {0.0, 0.0}};
  const contact_result r = contact.enforce(body.view(), 1.0, dt, d, v);
  CHECK(r.active == 1);
  CHECK(r.max_penetration == doctest::Approx(0.02));
  CHECK(std::abs(body.X[0].y() + d[0].y()) < 1e-15);
  CHECK(d[0].x() == 0.0);
  CHECK(v[0].y() == doctest::Approx(-120.0 + 0.02 / dt));
  CHECK(d[1] == vec2(0.0, -0.05));  // above the floor: untouched
  CHECK(v[1] == vec2(0.0, -50.0));
  const double fn = 2.0 * 0.02 / (dt * dt);
  CHECK(contact.reactions()[0].isApprox(vec2(0, -fn)));
  REQUIRE(contact.active_pairs().size() == 1);
  CHECK(contact.active_pairs()[0].normal_force == doctest::Approx(fn));
  // The energy ledger books the contact's work as the change of the half-step kinetic energy
  // (first step: the previous half-step velocity is the one before the contact).
  const std::vector<vec2> v0 = {{0.0, -120.0}, {0.0, -50.0}, {0.0, 0.0}};
  CHECK(jump_work(body.m, v, v0) == doctest::Approx(0.5 * 2.0 * (v[0].squaredNorm() - 120.0 * 120.0)));
}

TEST_CASE("penalty: f_n = k g") {
  identity_body body{{{0.5, 0.1}}, {2.0}};
  particle_to_segment<enforcement::penalty> contact({floor_tool()}, {}, enforcement::penalty{.stiffness = 1e4});
  contact.setup(body.view(), body.slaves());
  std::vector<vec2> d = {{0.0, -0.13}}, v = {{0.0, -1.0}};
  const double dt = 1e-3;
  contact.enforce(body.view(), 1.0, dt, d, v);
  CHECK(v[0].y() == doctest::Approx(-1.0 + 1e4 * 0.03 * dt / 2.0));
  CHECK(d[0].y() == doctest::Approx(-0.13 + 1e4 * 0.03 * dt * dt / 2.0));
  CHECK_THROWS_AS((particle_to_segment<enforcement::penalty>({floor_tool()})), rkpm::error);  // no stiffness
}

TEST_CASE("RK table: effective mass lands an isolated particle on the segment; the paper's form closes a known part") {
  rk_body body;
  const index_t J = 4;  // bottom row, middle: X = (0.5, 0)
  REQUIRE(body.X[J].isApprox(vec2(0.5, 0.0)));
  const index_t j = body.row_of(J);
  REQUIRE(j >= 0);
  // A short tip under particle J only (its neighbours are 0.125 away), rising from 1e-3 below the
  // body at t = 0 to 0.02 above the bottom row at t = 1.
  auto tip = [] {
    return rigid_tool("tip", {{0.45, -1e-3}, {0.55, -1e-3}}, side::left,
                      tool_motion::constant_velocity(vec2(0.0, 0.021)));
  };
  const double dt = 1e-4, g = 0.02;
  double fraction_expected = 0.0;
  for (index_t e = body.slaves.table.offset[j]; e < body.slaves.table.offset[j + 1]; ++e)
    fraction_expected += body.slaves.table.N[e] * body.slaves.table.N[e] * body.m[J] / body.m[body.slaves.table.neighbor[e]];
  CHECK(fraction_expected < 0.9);  // redistribution really spreads the force

  SUBCASE("effective_mass") {
    particle_to_segment<enforcement::effective_mass> contact({tip()});
    contact.setup(body.view(), body.slaves);
    std::vector<vec2> d(body.X.size(), vec2::Zero()), v(body.X.size(), vec2::Zero());
    const contact_result r = contact.enforce(body.view(), 1.0, dt, d, v);
    CHECK(r.active == 1);
    CHECK(r.max_penetration == doctest::Approx(g));
    CHECK(std::abs(body.position(j, d).y() - g) < 1e-14);
    CHECK(std::abs(body.position(j, d).x() - 0.5) < 1e-14);
    // m_sh = m_eff (61) for an isolated slave: the first sweep's force closes the whole gap.
    REQUIRE(contact.active_pairs().size() == 1);
    CHECK(contact.active_pairs()[0].normal_force == doctest::Approx(body.m[J] / fraction_expected * g / (dt * dt)));
  }
  SUBCASE("paper") {
    particle_to_segment<enforcement::paper> contact({tip()});
    contact.setup(body.view(), body.slaves);
    std::vector<vec2> d(body.X.size(), vec2::Zero()), v(body.X.size(), vec2::Zero());
    contact.enforce(body.view(), 1.0, dt, d, v);
    const double closed = body.position(j, d).y() / g;
    CHECK(closed == doctest::Approx(fraction_expected).epsilon(1e-12));
  }
}

TEST_CASE("effective_mass sweeps close the gaps of coupled slave particles") {
  rk_body body;
  // The whole body pushed 0.01 into a flat floor: the bottom row penetrates uniformly.
  auto residual = [&](int sweeps) {
    particle_to_segment<enforcement::effective_mass> contact({floor_tool()}, {},
                                                             enforcement::effective_mass{.sweeps = sweeps});
    contact.setup(body.view(), body.slaves);
    std::vector<vec2> d(body.X.size(), vec2(0.0, -0.01)), v(body.X.size(), vec2::Zero());
    const contact_result r = contact.enforce(body.view(), 1.0, 1e-4, d, v);
    CHECK(r.active == 9);
    CHECK(r.max_penetration == doctest::Approx(0.01));
    double worst = 0.0;
    for (index_t j = 0; j < static_cast<index_t>(body.slaves.particle.size()); ++j)
      if (body.X[body.slaves.particle[j]].y() == 0.0) worst = std::max(worst, std::abs(body.position(j, d).y()));
    return worst;
  };
  const double one = residual(1), many = residual(40);
  CHECK(one > 1e-4);           // coupled particles: one sweep over- or under-shoots
  CHECK(many < 1e-3 * one);    // the sweeps converge to closure
}

TEST_CASE("friction: frictionless keeps v_T, Coulomb caps at mu |f_n|, below the cap the particle sticks") {
  identity_body body{{{0.5, 0.1}}, {2.0}};
  const double dt = 1e-3, g = 0.02;
  auto state = [&] { return std::pair{std::vector<vec2>{{0.3, -0.1 - g}}, std::vector<vec2>{{3.0, -5.0}}}; };
  const double fn = 2.0 * g / (dt * dt);
  const double f_stick = 2.0 * 3.0 / dt;

  SUBCASE("frictionless") {
    particle_to_segment<enforcement::paper, friction::frictionless> contact({floor_tool()});
    contact.setup(body.view(), body.slaves());
    auto [d, v] = state();
    contact.enforce(body.view(), 1.0, dt, d, v);
    CHECK(v[0].x() == 3.0);
    CHECK(d[0].x() == 0.3);
  }
  SUBCASE("coulomb, sliding: the tangential force is mu f_n against v_T") {
    const double mu = 0.05;
    REQUIRE(mu * fn < f_stick);
    particle_to_segment<enforcement::paper, friction::coulomb> contact({floor_tool()}, friction::coulomb{mu});
    contact.setup(body.view(), body.slaves());
    auto [d, v] = state();
    const contact_result r = contact.enforce(body.view(), 1.0, dt, d, v);
    CHECK(contact.active_pairs()[0].tangential_force.isApprox(vec2(-mu * fn, 0.0)));
    CHECK(v[0].x() == doctest::Approx(3.0 - mu * fn * dt / 2.0));
    CHECK(v[0].y() == doctest::Approx(-5.0 + g / dt));
    CHECK(contact.reactions()[0].isApprox(vec2(mu * fn, -fn)));
    const std::vector<vec2> v0 = state().second;
    CHECK(r.active == 1);
    CHECK(jump_work(body.m, v, v0) == doctest::Approx(0.5 * 2.0 * (v[0].squaredNorm() - 34.0)));
  }
  SUBCASE("coulomb, below the cap: stick") {
    const double mu = 2.0;
    REQUIRE(mu * fn > f_stick);
    particle_to_segment<enforcement::paper, friction::coulomb> contact({floor_tool()}, friction::coulomb{mu});
    contact.setup(body.view(), body.slaves());
    auto [d, v] = state();
    contact.enforce(body.view(), 1.0, dt, d, v);
    CHECK(std::abs(v[0].x()) < 1e-12);
    CHECK(contact.active_pairs()[0].tangential_force.isApprox(vec2(-f_stick, 0.0)));
  }
  SUBCASE("coulomb with an RK table and effective mass: an isolated particle sticks") {
    rk_body rk;
    const index_t J = 4, j = rk.row_of(J);
    auto tip = rigid_tool("tip", {{0.45, -1e-3}, {0.55, -1e-3}}, side::left,
                          tool_motion::constant_velocity(vec2(0.0, 0.011)));
    particle_to_segment<enforcement::effective_mass, friction::coulomb> contact({tip}, friction::coulomb{10.0});
    contact.setup(rk.view(), rk.slaves);
    std::vector<vec2> d(rk.X.size(), vec2::Zero()), v(rk.X.size(), vec2(0.7, 0.0));
    contact.enforce(rk.view(), 1.0, 1e-3, d, v);
    CHECK(std::abs(rk.slaves.table.interpolate(j, v).x()) < 1e-12);
    CHECK(v[J].x() != doctest::Approx(0.0));  // the coefficient itself is not the physical value
  }
  CHECK_THROWS_AS((particle_to_segment<enforcement::paper, friction::coulomb>({floor_tool()}, friction::coulomb{-0.1})),
                  rkpm::error);
}

TEST_CASE("(P7) redistribution keeps the resultant force and moment of the contact forces") {
  rk_body body;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  // A tilted plane under the body and random displacements and velocities, so that every bottom
  // slave has a different gap, normal force and friction force.
  const vec2 a(-1.0, 0.02), b(2.0, -0.04);
  particle_to_segment<enforcement::paper, friction::coulomb> contact(
      {rigid_tool("plane", {a, b}, side::left, tool_motion::constant_velocity(vec2(0.01, 0.03)))},
      friction::coulomb{0.3});
  const double dt = 1e-4, t = 1.0;
  std::vector<vec2> d(body.X.size()), v(body.X.size());
  for (std::size_t I = 0; I < d.size(); ++I) {
    d[I] = vec2(1e-3 * u(rng), 1e-3 * u(rng));
    v[I] = vec2(u(rng), u(rng));
  }
  contact.setup(body.view(), body.slaves);
  const std::vector<vec2> v0 = v;
  const contact_result r = contact.enforce(body.view(), t, dt, d, v);
  REQUIRE(r.active >= 6);
  vec2 sum_J = vec2::Zero(), sum_I = vec2::Zero();
  double moment_J = 0.0, moment_I = 0.0, scale = 0.0;
  for (const contact_pair& p : contact.active_pairs()) {
    const vec2 f = p.force();
    const vec2& X = body.X[body.slaves.particle[p.slave]];
    sum_J += f;
    moment_J += X.x() * f.y() - X.y() * f.x();
    scale += f.norm();
  }
  for (std::size_t I = 0; I < d.size(); ++I) {
    const vec2 f = body.m[I] * (v[I] - v0[I]) / dt;  // f_I from the velocity change it caused
    sum_I += f;
    moment_I += body.X[I].x() * f.y() - body.X[I].y() * f.x();
  }
  CHECK((sum_I - sum_J).norm() < 1e-10 * scale);
  CHECK(std::abs(moment_I - moment_J) < 1e-10 * scale);
  CHECK((contact.reactions()[0] + sum_J).norm() < 1e-12 * scale);
  // Friction really acted (not all forces along the normal).
  const vec2 n = contact.tools()[0].normal(0);
  CHECK(std::abs(sum_J.x() * n.y() - sum_J.y() * n.x()) > 1e-5 * scale);
}
