// A block dropped onto a fixed rigid wall, through the full explicit solver (issue 4), with each
// enforcement policy (paper, effective_mass, penalty):
//   - no slave particle's physical position x_J = X_J + sum_I N_I(X_J) d_I lies below the wall by
//     more than a stated fraction of the particle spacing h, after any step;
//   - Newton's law for the whole body: P(t) - P(0) = M g t - sum_steps reaction dt (the reaction
//     is the force on the tool, so the body receives minus it). Internal forces sum to zero by
//     the partition of unity and the contact forces are redistributed with it (P7), so this holds
//     to round-off;
//   - the energy balance closes with the contact work booked: with a constant dt the discrete
//     identity is exact up to the full-step kinetic energy term (see energy_tail), while the
//     contact work is a large term of it, and a fixed wall does no positive work.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <vector>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/material/elastic.hpp>
#include <rkpm/solver/make_solver.hpp>

namespace test_numeric_contact_drop {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

namespace {

// Soft elastic block, 0.1 m square, 11 x 11 particles (h = 0.01 m): c_p ~ 37 m/s, stable step
// ~ 3.4e-4 s; dt = 1.5e-4 s. It starts 0.2 h above the wall at 1 m/s: contact from t ~ 2 ms,
// the compression wave travels down and back up the block (2 H / c ~ 5.5 ms) and it rebounds.
constexpr double E = 1e6, nu = 0.3, rho = 1000.0;
constexpr double W = 0.1, H = 0.1, h = 0.01, gap0 = 0.2 * h, V0 = 1.0, g = 9.81;
constexpr double dt = 1.5e-4, T = 0.02;
constexpr int nx = 11, ny = 11;

struct drop_result {
  double worst_depth = 0.0;     // deepest physical slave position below the wall after a step (m)
  double max_predicted = 0.0;   // largest gap before correction (solver's max_penetration)
  double momentum_error = 0.0;  // |P(T) - P(0) - M g T - impulse| / (M V0)
  double impulse_y = 0.0;       // -sum reaction_y dt, received by the body
  double final_vy = 0.0;        // P_y / M at the end
  double identity_error = 0.0;  // max |imbalance - energy tail change| / K0
  double balance_error = 0.0;
  double contact_work = 0.0;    // / K0
  double steps_in_contact = 0;
  double mass = 0.0;            // M, per metre of thickness
};

template <class Dynamics>
double energy_tail(const Dynamics& s) {
  // The balance uses the kinetic energy at full steps, v(n) = v(n+1/2) - dt a(n) / 2; the
  // central-difference identity then reads imbalance(n) = tail(n) - tail(0) with
  // tail = sum_I m_I dt^2 |a_I|^2 / 8 (a from internal and body forces): bounded, O(dt^2), not
  // accumulating. Any error in booking the contact work would appear on top of it.
  double tail = 0.0;
  for (index_t I = 0; I < s.model().particle_count(); ++I) {
    const vec2 f = s.mass()[I] * vec2(0.0, -g) - s.internal_force()[I];
    tail += dt * dt / 8.0 * f.squaredNorm() / s.mass()[I];
  }
  return tail;
}

template <class Contact>
drop_result drop(Contact contact) {
  using cfg = config<kernel::cubic_spline, correction::linear, quadrature::q4, geometry::plane_strain,
                     material::elastic, Contact>;
  const vec2 lo(0.0, gap0), hi(W, gap0 + H);
  problem_for<cfg> p{.particles = make_grid_particles<2>(lo, hi, Eigen::Vector2i(nx, ny), 2.0),
                     .mesh = make_grid_mesh(lo, hi, Eigen::Vector2i(nx, ny)),
                     .material = material::elastic(material::elastic_constants{E, nu, rho}),
                     .contact = std::move(contact),
                     .initial_velocity = [](const vec2&) { return vec2(0.0, -V0); },
                     .body_force = vec2(0.0, -g)};
  run_options o;
  o.end_time = T;
  o.fixed_time_step = dt;
  auto s = make_solver<cfg>(std::move(p), o);

  double M = 0.0;
  for (double m : s.mass()) M += m;
  auto momentum = [&] {
    vec2 P = vec2::Zero();
    for (index_t I = 0; I < s.model().particle_count(); ++I) P += s.mass()[I] * s.coefficient_velocities()[I];
    return P;
  };
  const vec2 P0 = momentum();
  const double K0 = s.energy().initial_kinetic, tail0 = energy_tail(s);
  drop_result r;
  double t_prev = 0.0;
  s.run(
      [&](const auto& s) {
        const double step = s.time() - t_prev;
        t_prev = s.time();
        if (s.last_contact().active > 0) ++r.steps_in_contact;
        // The last step is shortened to land on T; the tail formula assumes the constant dt.
        if (std::abs(step - dt) < 1e-9 * dt)
          r.identity_error = std::max(r.identity_error, std::abs(s.energy().imbalance() - (energy_tail(s) - tail0)) / K0);
        const auto x = s.particle_positions();
        for (index_t J : s.slave_particles()) r.worst_depth = std::max(r.worst_depth, -x[J].y());
      },
      1);
  const vec2 impulse = -s.tool_impulses()[0];  // the wall's reaction is the body's push on it
  const vec2 dP = momentum() - P0;
  r.momentum_error = (dP - (vec2(0.0, -M * g * s.time()) + impulse)).norm() / (M * V0);
  r.impulse_y = impulse.y();
  r.mass = M;
  r.final_vy = momentum().y() / M;
  r.balance_error = s.energy().balance_error();
  r.contact_work = s.energy().contact / K0;
  r.max_predicted = s.max_penetration();
  MESSAGE(Contact::name, ": worst depth after a step ", r.worst_depth / h, " h, largest predicted gap ",
          r.max_predicted / h, " h, momentum error ", r.momentum_error, ", impulse ", r.impulse_y,
          " N s (M V0 = ", M * V0, "), final mean vy ", r.final_vy, ", steps in contact ", r.steps_in_contact,
          ", energy identity error ", r.identity_error, ", balance_error ", r.balance_error,
          ", contact work / K0 ", r.contact_work);
  return r;
}

contact::rigid_tool wall() {
  return contact::rigid_tool("wall", {vec2(-0.1, 0.0), vec2(0.2, 0.0)}, contact::side::left,
                             contact::tool_motion::fixed());
}

}  // namespace

TEST_CASE_TEMPLATE("a block dropped on a fixed wall: no penetration, impulse = momentum change, energy closes",
                   E_, contact::enforcement::paper, contact::enforcement::effective_mass,
                   contact::enforcement::penalty) {
  using contact_t = contact::particle_to_segment<E_, contact::friction::frictionless>;
  E_ enforcement{};
  double tolerance = 0.01 * h;  // the gap is closed on the predicted configuration
  // effective_mass: the default projected Jacobi sweeps with the shared effective mass (61a), which
  // does not over-close a flat row of slaves that share coefficients (docs/method.md section 6.6).
  if constexpr (std::is_same_v<E_, contact::enforcement::penalty>) {
    // k dt^2 / m_slave ~ 0.5 for the edge particles (m = rho h^2 / 2 = 0.05 kg per metre): stable,
    // and it closes about half the gap per step, so some penetration remains while in contact.
    enforcement.stiffness = 1e6;
    tolerance = 0.05 * h;
  }
  const drop_result r = drop(contact_t({wall()}, {}, enforcement));
  CHECK(r.worst_depth < tolerance);
  CHECK(r.steps_in_contact > 20);
  // The body came to the wall at V0 and left it moving up: the wall's impulse exceeds M V0.
  CHECK(r.impulse_y > r.mass * V0);
  CHECK(r.final_vy > 0.0);
  CHECK(r.momentum_error < 1e-12);
  CHECK(r.identity_error < 1e-10);
  CHECK(r.contact_work < -0.01);  // a large term: leaving it out would break the identity
  CHECK(r.balance_error < 0.05);
}

TEST_CASE("penetration test fails for a wall the contact does not know about") {
  // The same observer, with contact against a wall 0.5 h lower: the body falls through y = 0.
  using contact_t = contact::particle_to_segment<contact::enforcement::effective_mass, contact::friction::frictionless>;
  const drop_result r = drop(contact_t({contact::rigid_tool("low wall", {vec2(-0.1, -0.5 * h), vec2(0.2, -0.5 * h)},
                                                            contact::side::left)}));
  CHECK(r.worst_depth > 0.4 * h);
}

}  // namespace test_numeric_contact_drop
