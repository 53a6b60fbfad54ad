// contact_increment (contact_kernel.hpp), the force kernel of every contact pass, against values
// computed by hand from (56)-(58):
//   paper, frictionless: f_n = m_s g / dt^2; the impulse dt f_n / m_s on a lone slave of mass m_s
//   is g / dt, the normal velocity that lands it on the segment in the step; no tangential force;
//   effective_mass: f_n with m_sh; later sweeps add omega times the increment, never below zero;
//   coulomb: below the cap the sticking force -m v_T / dt (stick), above it mu f_n along it (slip).
#include <doctest/doctest.h>

#include <cmath>

#include <rkpm/contact/contact_kernel.hpp>
#include <rkpm/contact/enforcement.hpp>
#include <rkpm/contact/friction.hpp>

using namespace rkpm;
using namespace rkpm::contact;

namespace {
// A slave 2e-3 inside a floor (normal +y), moving down at 3 m/s and sideways at 0.5 m/s.
contact_state floor_contact() {
  return {.gap = 2e-3, .relative_velocity = vec2(0.5, -3.0), .normal = vec2(0.0, 1.0), .own_mass = 2.0,
          .shared_mass = 0.5};
}
constexpr double dt = 1e-4;
}  // namespace

TEST_CASE("paper, frictionless: the normal impulse brings the slave onto the segment") {
  const contact_state c = floor_contact();
  double fn = 0.0;
  vec2 ft = vec2::Zero();
  const vec2 df = contact_increment(c, dt, 0, enforcement::paper{}, friction::frictionless{}, fn, ft);
  const double expected = 2.0 * 2e-3 / (dt * dt);  // m_s g / dt^2 = 4e5 N
  CHECK(fn == doctest::Approx(expected).epsilon(1e-14));
  CHECK(df.x() == 0.0);
  CHECK(df.y() == doctest::Approx(expected).epsilon(1e-14));
  CHECK(ft == vec2::Zero());
  // A lone slave of mass m_s: v_n after the impulse is -3 + g / dt = 17 m/s, so that with the
  // predicted position 2e-3 inside, d += dt^2 f_n / m_s lands it on the segment.
  CHECK(c.relative_velocity.y() + dt * fn / c.own_mass == doctest::Approx(-3.0 + 2e-3 / dt).epsilon(1e-14));
  CHECK(-c.gap + dt * dt * fn / c.own_mass == doctest::Approx(0.0).epsilon(1e-14));
}

TEST_CASE("a slave that left the segment by more than its force is let go: f_n never below zero") {
  contact_state c = floor_contact();
  double fn = 100.0;
  vec2 ft = vec2::Zero();
  c.gap = -1.0;  // measured again in a later sweep: far outside
  const vec2 df = contact_increment(c, dt, 1, enforcement::effective_mass{}, friction::frictionless{}, fn, ft);
  CHECK(fn == 0.0);
  CHECK(df == vec2(0.0, -100.0));
}

TEST_CASE("effective_mass: m_sh in (56); a later sweep adds the relaxed increment") {
  const contact_state c = floor_contact();
  const enforcement::effective_mass e{.sweeps = 3, .relaxation = 0.5};
  double fn = 0.0;
  vec2 ft = vec2::Zero();
  contact_increment(c, dt, 0, e, friction::frictionless{}, fn, ft);
  CHECK(fn == doctest::Approx(0.5 * 2e-3 / (dt * dt)).epsilon(1e-14));  // m_sh g / dt^2 = 1e5 N
  const vec2 df = contact_increment(c, dt, 1, e, friction::frictionless{}, fn, ft);
  CHECK(df.y() == doctest::Approx(0.5 * 1e5).epsilon(1e-14));
  CHECK(fn == doctest::Approx(1.5e5).epsilon(1e-14));
}

TEST_CASE("coulomb: stick below the bound mu f_n, slip at it") {
  const contact_state c = floor_contact();
  // Sticking force -m_s v_T / dt = -2 * 0.5 / 1e-4 = -1e4 N along x; f_n = 4e5 N.
  SUBCASE("stick: mu f_n = 4e4 N > 1e4 N") {
    double fn = 0.0;
    vec2 ft = vec2::Zero();
    const vec2 df = contact_increment(c, dt, 0, enforcement::paper{}, friction::coulomb{.coefficient = 0.1}, fn, ft);
    CHECK(ft.x() == doctest::Approx(-1e4).epsilon(1e-14));
    CHECK(ft.y() == 0.0);
    CHECK(df.x() == doctest::Approx(-1e4).epsilon(1e-14));
    // The slave stops relative to the tool: v_T + dt f_t / m_s = 0.
    CHECK(std::abs(c.relative_velocity.x() + dt * ft.x() / c.own_mass) < 1e-14);
  }
  SUBCASE("slip: mu f_n = 4e3 N < 1e4 N") {
    double fn = 0.0;
    vec2 ft = vec2::Zero();
    contact_increment(c, dt, 0, enforcement::paper{}, friction::coulomb{.coefficient = 0.01}, fn, ft);
    CHECK(ft.x() == doctest::Approx(-0.01 * fn).epsilon(1e-14));
    CHECK(ft.y() == 0.0);
  }
}
