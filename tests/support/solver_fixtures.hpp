#pragma once
// Shared set-up for the solver tests: grid problems for any configuration, materials and
// contact policies built from their types, deformation gradients recomputed from the
// discrete_model tables (independently of the solver loop), a solver placed at a given
// displacement field after one step, and the assembled small-strain stiffness.

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <type_traits>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include <rkpm/rkpm.hpp>
#include <rkpm/solver/policies.hpp>

#include "cases/contact_setup.hpp"

namespace rkpm::test {

// The physics tests run problems of ~100 particles for ~1000 steps. With two OpenMP threads
// each step crosses several barriers that spin-wait; on a loaded 2-core machine a spinning
// thread waits for its descheduled partner and a step costs ~10 ms instead of ~0.1 ms. These
// tests therefore run serially; thread-count independence has its own test
// (tests/unit/solver/step_allocations_and_threads.cpp).
inline void run_serially() {
#ifdef _OPENMP
  omp_set_num_threads(1);
#endif
  Eigen::setNbThreads(1);
}

// Constants used unless a test says otherwise: steel-like round numbers (E = 200 GPa, nu = 0.3,
// rho0 = 7800 kg/m^3), not the paper's copper (117 GPa, 0.35, 8930 kg/m^3).
inline material::elastic_constants steel_like() { return {200e9, 0.3, 7800.0}; }

// ---- materials and contact policies from their types --------------------------------------
template <class M>
M make_material(const material::elastic_constants& c) {
  if constexpr (std::is_same_v<M, material::elastic>)
    return M(c);
  else if constexpr (std::is_same_v<M, material::j2_plasticity<material::hardening::linear>>)
    return M(c, material::hardening::linear{0.002 * c.youngs_modulus, 0.01 * c.youngs_modulus});
  else if constexpr (std::is_same_v<M, material::j2_plasticity<material::hardening::power_law>>)
    return M(c, material::hardening::power_law{0.004 * c.youngs_modulus, 0.02, 0.3});
  else if constexpr (std::is_same_v<M, material::johnson_cook>)  // copper's shape, with damage
    return M(c, material::hardening::johnson_cook{0.001 * c.youngs_modulus, 0.003 * c.youngs_modulus, 0.31, 0.025,
                                                  1.0, 1.09, 294.0, 1356.0},
             material::johnson_cook_heating{383.0}, material::johnson_cook_damage{0.54, 4.89, -3.03, 0.014, 1.12});
  else if constexpr (std::is_same_v<M, material::zerilli_armstrong>)  // copper's fcc shape
    return M(c,
             material::hardening::zerilli_armstrong{material::hardening::zerilli_armstrong::lattice_type::fcc,
                                                    0.0003 * c.youngs_modulus, 0.0, 0.007 * c.youngs_modulus, 0.0028,
                                                    0.000115, 0.0, 0.0, 1.0, 1356.0},
             material::zerilli_armstrong_heating{383.0, 0.9, 294.0});
  else
    return M{c};  // a test's own material, an aggregate of its elastic constants first
}

// Built as the cases build theirs (cases/contact_setup.hpp), with Coulomb friction 0.2 when the
// policy has friction; contact::none takes no tools.
template <class Ct>
Ct make_contact(std::vector<contact::rigid_tool> tools, double penalty_stiffness = 1e12) {
  if constexpr (std::is_same_v<Ct, contact::none>) {
    return Ct{};
  } else {
    const double friction = std::is_same_v<typename Ct::friction_type, contact::friction::coulomb> ? 0.2 : 0.0;
    return cases::make_contact<Ct>(std::move(tools), friction, penalty_stiffness);
  }
}

// A flat fixed tool along y = y0 from x0 to x1 with the body above it.
inline contact::rigid_tool flat_tool_below(double x0, double x1, double y0) {
  // Direction +x: the left side of the polyline is +y, where the body lies.
  return contact::rigid_tool("anvil", {vec2(x0, y0), vec2(x1, y0)}, contact::side::left,
                             contact::tool_motion::fixed());
}

// ---- problems on a regular grid ----------------------------------------------------------
// Support factor s (a = s h): a quadratic basis needs more than 2 neighbours per direction at a
// corner, so more than 2 h.
template <class C>
inline constexpr double default_support = std::is_same_v<C, correction::quadratic> ? 2.5 : 2.0;

template <class Cfg>
problem_for<Cfg> grid_problem(const vec2& lo, const vec2& hi, const Eigen::Vector2i& n,
                              const material::elastic_constants& c = steel_like(),
                              double support = default_support<typename Cfg::correction_type>) {
  return problem_for<Cfg>{.particles = make_grid_particles<2>(lo, hi, n, support),
                          .mesh = make_grid_mesh(lo, hi, n),
                          .material = make_material<typename Cfg::material_type>(c),
                          .contact = make_contact<typename Cfg::contact_type>({}),
                          .initial_velocity = {},
                          .constraints = {},
                          .body_force = vec2::Zero(),
                          .slave_particles = {}};
}

// Holds the bottom face (y = 0) of a section of height `height` and moves its top face down at
// `speed` m/s, reached linearly over `ramp` s (a cylinder or block squeezed from above).
template <class P>
void squeeze_from_top(P& p, double height, double speed, double ramp) {
  for (index_t I = 0; I < static_cast<index_t>(p.particles.position.size()); ++I) {
    const double y = p.particles.position[I][1];
    if (y > height - 1e-9) p.constraints.push_back({I, 1, [=](double t) { return -speed * std::min(1.0, t / ramp); }});
    if (y < 1e-9) p.constraints.push_back({I, 1, [](double) { return 0.0; }});
  }
}

// Moves every interior node of a grid mesh (and the particle at the same place) by a
// deterministic fraction of the spacing, so that cells are non-affine quadrilaterals; the
// boundary stays put, so particle volumes still add up to the cell area.
inline void distort_interior(particle_set<2>& p, background_mesh& m, const vec2& h, double fraction) {
  const auto boundary = m.boundary_nodes();
  std::vector<char> on(m.node.size(), 0);
  for (index_t b : boundary) on[b] = 1;
  for (index_t i = 0; i < static_cast<index_t>(m.node.size()); ++i) {
    if (on[i]) continue;
    const vec2 shift(fraction * h[0] * std::sin(1.7 * i + 0.3), fraction * h[1] * std::cos(2.3 * i + 0.1));
    m.node[i] += shift;
    p.position[i] += shift;
  }
}

// ---- kinematics recomputed from the tables -----------------------------------------------
template <class G>
std::vector<mat3> deformation_gradients(const discrete_model& m, const std::vector<vec2>& d) {
  std::vector<mat3> out(m.point_count());
  const auto& t = m.at_points;
  for (index_t q = 0; q < m.point_count(); ++q) {
    mat3 F = mat3::Identity();
    vec2 u = vec2::Zero();
    for (index_t e = t.offset[q]; e < t.offset[q + 1]; ++e) {
      F.topLeftCorner<2, 2>() += d[t.neighbor[e]] * t.grad[e].transpose();
      u += t.N[e] * d[t.neighbor[e]];
    }
    F(2, 2) = G::out_of_plane_stretch(u, m.points.position[q]);
    out[q] = F;
  }
  return out;
}

// A solver of configuration Cfg whose coefficients after one step are d_I = u(X_I): the
// initial velocity is u / dt with a fixed step dt far below the stable one, and the initial
// acceleration is zero (undeformed body, no body force), so d = dt * (u / dt) to round-off.
template <class Cfg>
solver_for<Cfg> solver_at(problem_for<Cfg> p, std::function<vec2(const vec2&)> u, double dt) {
  p.initial_velocity = [u, dt](const vec2& X) -> vec2 { return u(X) / dt; };
  run_options o;
  o.fixed_time_step = dt;
  o.end_time = dt;  // the one step taken
  auto s = make_solver<Cfg>(std::move(p), o);
  s.step();
  return s;
}

// Safe fixed step for solver_at: far below any stable step of a grid with spacing h.
inline double tiny_step(double h, const material::elastic_constants& c) {
  return 1e-3 * h / c.dilatational_wave_speed();
}

// ---- assembled stiffness -----------------------------------------------------------------
// Dense small-strain stiffness K (2n x 2n, dof 2I + k) assembled column by column from
// apply_elastic_stiffness.
template <class G>
Eigen::MatrixXd assemble_stiffness(const discrete_model& m, const material::elastic_constants& c) {
  const index_t n = m.particle_count();
  Eigen::MatrixXd K(2 * n, 2 * n);
  std::vector<vec2> x(n, vec2::Zero()), kx(n);
  for (index_t j = 0; j < 2 * n; ++j) {
    x[j / 2][j % 2] = 1.0;
    apply_elastic_stiffness<G>(m, c, x, kx);
    x[j / 2][j % 2] = 0.0;
    for (index_t I = 0; I < n; ++I) K.block<2, 1>(2 * I, j) = kx[I];
  }
  return K;
}

// Lumped masses rho0 V_I of a model, per dof (2n).
inline Eigen::VectorXd dof_masses(const discrete_model& m, double density) {
  Eigen::VectorXd M(2 * m.particle_count());
  for (index_t I = 0; I < m.particle_count(); ++I) M[2 * I] = M[2 * I + 1] = density * m.lumped_volume[I];
  return M;
}

}  // namespace rkpm::test

namespace rkpm::test {

// Contact policies that stop a particle within one step (as opposed to a penalty spring).
template <class Ct>
inline constexpr bool is_kinematic_contact = false;
template <class F>
inline constexpr bool is_kinematic_contact<contact::particle_to_segment<contact::enforcement::paper, F>> = true;
template <class F>
inline constexpr bool is_kinematic_contact<contact::particle_to_segment<contact::enforcement::effective_mass, F>> =
    true;

// ---- one covering configuration: a few steps of a small impact, with sanity checks --------
// A 6 x 5 block (r from 0 in axisymmetric runs) moving down at 50 m/s with a shearing
// perturbation, a fixed flat tool 0.05 h below it for contact configurations. Checks:
// finite coefficients, positive det F, the energy balance, linear momentum (plane strain,
// no contact: sum m v is conserved since sum f_int = 0; axisymmetric: the axial component),
// and contact engaged where there is a tool.
template <class Cfg>
energy_balance check_combination(int steps = 40, double time_step_fraction = 0.0) {
  INFO(Cfg::name());
  run_serially();
  using G = typename Cfg::geometry_type;
  using Ct = typename Cfg::contact_type;
  constexpr bool has_contact = !std::is_same_v<Ct, contact::none>;
  const material::elastic_constants c{200e9, 0.3, 7800.0};
  const vec2 lo(G::is_axisymmetric ? 0.0 : -2e-3, 0.0), hi(lo[0] + 4e-3, 3e-3);
  const Eigen::Vector2i n(6, 5);
  const double h = 0.75e-3, V = 50.0;
  auto p = grid_problem<Cfg>(lo, hi, n, c);
  if constexpr (has_contact) {
    // Penalty stiffness well below the lumped-mass / time-step limit (masses carry 2 pi r in
    // axisymmetric runs, so the particles near the axis are light).
    const double k = G::is_axisymmetric ? 1e7 : 1e9;
    p.contact = make_contact<Ct>({flat_tool_below(lo[0] - 2e-3, hi[0] + 2e-3, -0.05 * h)}, k);
  }
  p.initial_velocity = [&](const vec2& X) {
    const double s = (X[1] - lo[1]) / (hi[1] - lo[1]);
    return vec2(G::is_axisymmetric ? 0.2 * V * (X[0] - lo[0]) / (hi[0] - lo[0]) : 0.4 * V * s * s,
                -V * (1.0 + 0.2 * std::sin(3.0 * s)));
  };
  run_options o;
  o.end_time = 1.0;
  if (time_step_fraction > 0.0) o.time_step_fraction = time_step_fraction;
  auto s = make_solver<Cfg>(std::move(p), o);
  auto momentum = [&] {
    vec2 P = vec2::Zero();
    for (index_t I = 0; I < s.model().particle_count(); ++I) P += s.mass()[I] * s.coefficient_velocities()[I];
    return P;
  };
  const vec2 P0 = momentum();
  double largest_active = 0;
  for (int k = 0; k < steps; ++k) {
    s.step();
    largest_active = std::max<double>(largest_active, static_cast<double>(s.last_contact().active));
  }
  bool finite = true;
  for (const vec2& d : s.coefficients()) finite = finite && d.allFinite();
  for (const vec2& v : s.coefficient_velocities()) finite = finite && v.allFinite();
  CHECK(finite);
  double min_det = 1e300;
  for (index_t q = 0; q < s.model().point_count(); ++q) min_det = std::min(min_det, s.point_det_F(q));
  CHECK(min_det > 0.5);
  CHECK(s.time() > 0.0);
  const auto& e = s.energy();
  MESSAGE(Cfg::name() << ": " << s.steps() << " steps, dt " << s.time_step() << ", balance error "
                      << e.balance_error() << ", kinetic " << e.kinetic << " / " << e.initial_kinetic << ", plastic "
                      << e.plastic << ", contact work " << e.contact << ", active contacts (max) " << largest_active
                      << ", max penetration " << s.max_penetration());
  // Kinematic enforcement (paper, effective_mass) stops particles within one step; the impact
  // excites the highest modes, for which the integer-step energy of central differences is off
  // by O((omega dt)^2). Its balance error is therefore O(dt^2) (numeric/combinations_part3.cpp
  // checks the rate) and ~10 % at the default step; smooth loads close within 1 %.
  constexpr bool kinematic = is_kinematic_contact<Ct>;
  CHECK(e.balance_error() < (kinematic ? 0.2 : 1e-2));
  CHECK(std::isfinite(e.kinetic + e.internal + e.contact + e.constraint));
  // Adiabatic heating (material::johnson_cook, docs/method.md (32a)): over the body the heat,
  // sum_q w_q rho0 c_p (T_q - T0), is beta times the plastic work the ledger counts.
  using M = typename Cfg::material_type;
  if constexpr (requires(const M& m) { m.heat_per_work(); }) {
    const M m = make_material<M>(c);
    const double T0 = m.initial_state().temperature;
    double rise = 0.0, work = 0.0;
    for (index_t q = 0; q < s.model().point_count(); ++q) {
      rise += s.model().points.weight[q] * (s.point_states()[q].temperature - T0);
      work += s.model().points.weight[q] * s.point_states()[q].plastic_work;
    }
    CHECK(work > 0.0);
    CHECK(work == doctest::Approx(e.plastic).epsilon(1e-12));
    CHECK(rise == doctest::Approx(m.heat_per_work() * work).epsilon(1e-12));
    MESSAGE("mean temperature rise " << rise / s.model().points.weight.size() << " K-weight, plastic work " << work);
  }
  const vec2 P = momentum();
  if constexpr (!has_contact) {
    if constexpr (G::is_axisymmetric) CHECK(std::abs(P[1] - P0[1]) < 1e-12 * P0.norm());
    else CHECK((P - P0).norm() < 1e-12 * P0.norm());
  } else {
    CHECK(largest_active > 0);
    CHECK(s.max_penetration() < h);
    CHECK(P[1] > P0[1]);  // the tool pushes the body up
    CHECK(e.contact < 0.0);  // the impact removes kinetic energy
  }
  return e;
}

// The covering row Cfg again with each rule beyond the paper (policies::extended_quadratures)
// in place of its own: the rows hold every kernel, correction, geometry, material and contact
// policy, so every such rule meets every policy of the other families. The solver type does
// not depend on the rule (only the discrete model's tables do), so this costs run time, not
// instantiations.
template <class Cfg>
void check_combination_with_every_rule() {
  boost::hana::for_each(policies::extended_quadratures, [](auto rule) {
    check_combination<typename Cfg::template with_quadrature<typename decltype(rule)::type>>();
  });
}

}  // namespace rkpm::test
