// Moving tools and set-up: velocities and reactions follow the tool's motion, a particle slides
// under gravity down one face and across a vertex onto the next, the wheel punch drives particles
// with its own normal velocity, set-up rejects a tool that starts inside the body (naming it),
// and enforce() allocates nothing.
#include <doctest/doctest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <string>
#include <vector>

#include <rkpm/correction/polynomial_bases.hpp>
#include <rkpm/contact/none.hpp>
#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/solver/energy.hpp>
#include <rkpm/discretization/particle_set.hpp>
#include <rkpm/discretization/shape_table.hpp>
#include <rkpm/kernel/cubic_spline.hpp>

#include "support/contact_fixtures.hpp"

// Count heap allocations while `counting` is set.
namespace {
std::atomic<bool> counting{false};
std::atomic<long> allocations{0};
}  // namespace
void* operator new(std::size_t n) {
  if (counting) ++allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

using namespace rkpm;
using namespace rkpm::contact;
using rkpm::test::identity_body;

TEST_CASE("a tool moving into a resting particle gives it the tool's velocity; reaction and work follow") {
  const double V = 2.0, U = 0.5, m = 3.0, dt = 1e-3;
  identity_body body{{{0.5, 0.0}}, {m}};  // touching the floor at t = 0
  SUBCASE("frictionless, normal motion") {
    particle_to_segment<enforcement::paper> contact(
        {rigid_tool("lifter", {{-1, 0}, {2, 0}}, side::left, tool_motion::constant_velocity(vec2(U, V)))});
    contact.setup(body.view(), body.slaves());
    std::vector<vec2> d{vec2::Zero()}, v{vec2::Zero()};
    const contact_result r = contact.enforce(body.view(), dt, dt, d, v);
    CHECK(v[0].isApprox(vec2(0, V)));  // no friction: the tangential tool motion is not passed on
    CHECK(d[0].isApprox(vec2(0, V * dt)));
    CHECK(contact.reactions()[0].isApprox(vec2(0, -m * V / dt)));
    const std::vector<vec2> rest{vec2::Zero()};
    CHECK(impulse_work_at(body.m[0], v[0], rest[0], rest[0]) == doctest::Approx(0.5 * m * V * V));
    CHECK(r.max_penetration == doctest::Approx(V * dt));
  }
  SUBCASE("sticking friction: the particle moves with the tool") {
    particle_to_segment<enforcement::effective_mass, friction::coulomb> contact(
        {rigid_tool("lifter", {{-1, 0}, {2, 0}}, side::left, tool_motion::constant_velocity(vec2(U, V)))},
        friction::coulomb{1.0});
    contact.setup(body.view(), body.slaves());
    std::vector<vec2> d{vec2::Zero()}, v{vec2::Zero()};
    const contact_result r = contact.enforce(body.view(), dt, dt, d, v);
    CHECK(v[0].isApprox(vec2(U, V)));
    CHECK(contact.reactions()[0].isApprox(vec2(-m * U / dt, -m * V / dt)));
    const std::vector<vec2> rest{vec2::Zero()};
    CHECK(r.active == 1);
    CHECK(impulse_work_at(body.m[0], v[0], rest[0], rest[0]) == doctest::Approx(0.5 * m * (U * U + V * V)));
  }
  SUBCASE("prescribed motion: the mean tool velocity over the step") {
    auto u = [](double t) { return vec2(std::sin(t), 0.5 * t * t); };
    auto w = [](double t) { return vec2(std::cos(t), t); };
    particle_to_segment<enforcement::paper, friction::coulomb> contact(
        {rigid_tool("shaker", {{-1, 0}, {2, 0}}, side::left, tool_motion::prescribed(u, w))}, friction::coulomb{5.0});
    contact.setup(body.view(), body.slaves());
    const double t = 1.0;
    std::vector<vec2> d{vec2(0, 0.5 * (t - dt) * (t - dt))}, v{vec2::Zero()};  // on the tool at t - dt
    contact.enforce(body.view(), t, dt, d, v);
    CHECK(v[0].x() == doctest::Approx((std::sin(t) - std::sin(t - dt)) / dt).epsilon(1e-12));
    CHECK(v[0].y() == doctest::Approx((0.5 * t * t - 0.5 * (t - dt) * (t - dt)) / dt).epsilon(1e-12));
  }
}

TEST_CASE("sliding under gravity down a slope and across a vertex onto the flat") {
  // Valley: slope y = -x for x < 0, then flat y = 0; body above. Frictionless: the particle
  // accelerates at g sin 45, reaches the kink with sqrt(2 g h), and the flat keeps only the
  // horizontal part of that velocity (the normal part is removed in one step).
  const double grav = 10.0, h = 0.5, dt = 1e-4;
  identity_body body{{{-h, h}}, {1.0}};
  particle_to_segment<enforcement::paper> contact({rigid_tool("valley", {{-1, 1}, {0, 0}, {3, 0}}, side::left)});
  contact.setup(body.view(), body.slaves());
  std::vector<vec2> d{vec2::Zero()}, v{vec2::Zero()};
  double t = 0.0, worst_on_slope = 0.0, worst_on_flat = 0.0;
  const double t_bottom = std::sqrt(2.0 * h * std::sqrt(2.0) / (grav / std::sqrt(2.0)));
  while (t < 0.7) {
    v[0].y() -= dt * grav;
    d[0] += dt * v[0];
    t += dt;
    contact.enforce(body.view(), t, dt, d, v);
    const vec2 x = body.X[0] + d[0];
    if (x.x() < -1e-3) worst_on_slope = std::max(worst_on_slope, std::abs(x.x() + x.y()));
    if (x.x() > 1e-3) worst_on_flat = std::max(worst_on_flat, std::abs(x.y()));
    if (t < t_bottom - 0.01) CHECK(x.x() < 0.0);
  }
  CHECK(worst_on_slope < 1e-12);
  CHECK(worst_on_flat < 1e-12);
  const double speed_x = std::sqrt(2.0 * grav * h) / std::sqrt(2.0);
  CHECK(v[0].x() == doctest::Approx(speed_x).epsilon(0.01));
  CHECK(std::abs(v[0].y()) < 1e-9);
  CHECK((body.X[0] + d[0]).x() == doctest::Approx(speed_x * (0.7 - t_bottom)).epsilon(0.01));
}

TEST_CASE("the wheel punch pushes free particles with its own normal velocity") {
  // Punch of docs/method.md section 10.3 in mm, moving down at 10 mm/s; particles at rest below it.
  const double V = 10.0, dt = 1e-3;
  identity_body body{{{18, 27.9}, {11.5, 25.0}, {5, 27.9}, {25, 27.0}}, {1, 1, 1, 1}};
  const rigid_tool punch("punch", {{0, 38}, {10, 38}, {12, 28}, {24, 28}, {26, 38}, {34.5, 38}}, side::right,
                         tool_motion::constant_velocity(vec2(0, -V)));
  particle_to_segment<enforcement::paper> contact({punch});
  contact.setup(body.view(), body.slaves());
  std::vector<vec2> d(4, vec2::Zero()), v(4, vec2::Zero());
  double t = 0.0;
  while (t < 0.8) {  // 8 mm stroke
    d[0] += dt * v[0], d[1] += dt * v[1], d[2] += dt * v[2], d[3] += dt * v[3];
    t += dt;
    contact.enforce(body.view(), t, dt, d, v);
  }
  const vec2 n_slope = punch.normal(1), n_rim = punch.normal(3);
  CHECK(v[0].isApprox(vec2(0, -V)));                                         // under the web
  CHECK(v[1].isApprox(vec2(-V * n_slope.y() * n_slope), 1e-9));               // v = (v_tool . n) n
  CHECK(v[2] == vec2::Zero());                                               // in the hub recess, not reached
  CHECK(v[3].isApprox(vec2(-V * n_rim.y() * n_rim), 1e-9));                   // rim slope
  CHECK((body.X[0] + d[0]).y() == doctest::Approx(28.0 - V * t));
}

TEST_CASE("set-up: a tool starting inside the body is an error naming the tool and the particle") {
  identity_body body{{{0.5, 0.1}, {0.5, 0.3}, {0.7, 0.2}}, {1, 1, 1}};
  // Upper die at y = 0.2 pressing down; the body lies below it.
  auto die = [](double y) { return rigid_tool("upper die", {{-1, y}, {2, y}}, side::right); };
  particle_to_segment<> inside({die(0.2)});
  try {
    inside.setup(body.view(), body.slaves());
    FAIL("expected rkpm::error");
  } catch (const rkpm::error& e) {
    const std::string what = e.what();
    CHECK(what.find("upper die") != std::string::npos);
    CHECK(what.find("particle 1") != std::string::npos);
    CHECK(what.find("0.3") != std::string::npos);
  }
  particle_to_segment<> touching({die(0.3)});  // particle 1 exactly on the die: allowed
  CHECK_NOTHROW(touching.setup(body.view(), body.slaves()));

  // Sizes and masses.
  particle_to_segment<> contact({die(1.0)});
  contact_slaves bad = body.slaves();
  bad.particle.pop_back();
  CHECK_THROWS_AS(contact.setup(body.view(), bad), rkpm::error);
  const std::vector<double> short_m(2, 1.0);
  CHECK_THROWS_AS(contact.setup(contact_body{body.X, short_m}, body.slaves()), rkpm::error);
  identity_body massless{{{0.5, 0.1}}, {0.0}};
  CHECK_THROWS_AS(contact.setup(massless.view(), massless.slaves()), rkpm::error);
  std::vector<vec2> d(3, vec2::Zero()), v(3, vec2::Zero());
  CHECK_THROWS_AS(contact.enforce(body.view(), 0.1, 1e-3, d, v), rkpm::error);  // before setup
  contact.setup(body.view(), body.slaves());
  std::vector<vec2> short_d(2, vec2::Zero());
  CHECK_THROWS_AS(contact.enforce(body.view(), 0.1, 1e-3, short_d, v), rkpm::error);
}

TEST_CASE("enforce() does not allocate") {
  particle_set<2> particles = make_grid_particles<2>(vec2(0, 0), vec2(1, 1), Eigen::Vector2i(9, 9), 2.0);
  std::vector<vec2> X = particles.position;
  std::vector<double> m(X.size(), 1.0);
  const contact_body b{X, m};
  contact_slaves slaves;
  std::vector<vec2> at;
  for (index_t I = 0; I < particles.size(); ++I)
    if (X[I].x() == 0.0 || X[I].y() == 0.0 || X[I].x() == 1.0 || X[I].y() == 1.0) {
      slaves.particle.push_back(I);
      at.push_back(X[I]);
    }
  slaves.table = build_shape_table<kernel::cubic_spline, correction::linear, 2>(neighbor_search<2>(particles), at);
  particle_to_segment<enforcement::effective_mass, friction::coulomb> contact(
      {rigid_tool("floor", {{-1, 0}, {0.5, -0.001}, {2, 0}}, side::left),
       rigid_tool("top", {{-1, 1}, {2, 1}}, side::right,
                  tool_motion::prescribed([](double t) { return vec2(0, -t); }, [](double) { return vec2(0, -1); }))},
      friction::coulomb{0.2}, enforcement::effective_mass{.sweeps = 3});
  contact.setup(b, slaves);
  none no_contact;
  no_contact.setup(b, slaves);
  std::vector<vec2> d(X.size(), vec2::Zero()), v(X.size(), vec2(0.1, 0.0));
  contact_result r;
  counting = true;
  for (int step = 1; step <= 20; ++step) {
    for (auto& di : d) di.y() -= 1e-3;
    r = contact.enforce(b, step * 1e-3, 1e-3, d, v);
    no_contact.enforce(b, step * 1e-3, 1e-3, d, v);
  }
  counting = false;
  CHECK(allocations == 0);
  CHECK(r.active > 0);
}
