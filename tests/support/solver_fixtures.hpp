#pragma once
// Shared set-up for the solver tests: grid problems for any configuration, materials and
// contact policies built from their types, deformation gradients recomputed from the
// discrete_model tables (independently of the solver loop), a solver placed at a given
// displacement field after one step, and the assembled small-strain stiffness.

#include <Eigen/Dense>
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

namespace rkpm::test {

// The physics tests run problems of ~100 particles for ~1000 steps. With two OpenMP threads
// each step crosses several barriers that spin-wait; on a loaded 2-core machine a spinning
// thread waits for its descheduled partner and a step costs ~10 ms instead of ~0.1 ms. These
// tests therefore run serially; thread-count independence has its own test
// (tests/unit/solver/speed_and_determinism.cpp).
inline void run_serially() {
#ifdef _OPENMP
  omp_set_num_threads(1);
#endif
  Eigen::setNbThreads(1);
}

// Constants used unless a test says otherwise: copper-like, but round numbers.
inline material::elastic_constants steel_like() { return {200e9, 0.3, 7800.0}; }

// ---- materials and contact policies from their types --------------------------------------
template <class M>
M make_material(const material::elastic_constants& c) {
  if constexpr (std::is_same_v<M, material::elastic>)
    return M(c);
  else if constexpr (std::is_same_v<M, material::j2_plasticity<material::hardening::linear>>)
    return M(c, material::hardening::linear{0.002 * c.youngs_modulus, 0.01 * c.youngs_modulus});
  else
    return M(c, material::hardening::power_law{0.004 * c.youngs_modulus, 0.02, 0.3});
}

template <class Ct>
Ct make_contact(std::vector<contact::rigid_tool> tools, double penalty_stiffness = 1e12) {
  if constexpr (std::is_same_v<Ct, contact::none>) {
    return Ct{};
  } else {
    using E = typename Ct::enforcement_type;
    using F = typename Ct::friction_type;
    F friction{};
    if constexpr (std::is_same_v<F, contact::friction::coulomb>) friction.coefficient = 0.2;
    E enforcement{};
    if constexpr (std::is_same_v<E, contact::enforcement::penalty>) enforcement.stiffness = penalty_stiffness;
    return Ct(std::move(tools), friction, enforcement);
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
// Returned by pointer: a contact policy keeps pointers to the solver's own vectors, so the
// solver must not move after construction.
template <class Cfg>
std::unique_ptr<explicit_solver<Cfg>> solver_at(problem_for<Cfg> p, std::function<vec2(const vec2&)> u,
                                                double dt) {
  p.initial_velocity = [u, dt](const vec2& X) -> vec2 { return u(X) / dt; };
  run_options o;
  o.fixed_time_step = dt;
  o.end_time = 1.0;
  auto s = std::make_unique<explicit_solver<Cfg>>(std::move(p), o);
  s->step();
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
  std::vector<mat2> sw(m.point_count());
  std::vector<double> hw(m.point_count());
  for (index_t j = 0; j < 2 * n; ++j) {
    x[j / 2][j % 2] = 1.0;
    apply_elastic_stiffness<G>(m, c, x, kx, sw, hw);
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
