// Axisymmetric uniform radial expansion. With the ends held axially (u_z = 0 at z = 0, Lz) and
// the outer surface moving radially at V R0, u_r = V t r, u_z = 0 is an exact solution of the
// dynamic problem: eps_rr = eps_theta = ln(1 + V t), eps_zz = 0, the stress is uniform with
// sigma_rr = sigma_theta, so div sigma = 0 and the constant velocity V r needs no acceleration.
// The run starts from that velocity field (initial_velocity = (V r, 0)).
// Checks: physical displacements at every particle against (V t r, 0), relative to the outer
// displacement; the axis u_r (physical values through s.particle_displacements()) at round-off
// relative to the outer displacement (the axis is held by the solver's constraint projection
// on physical values, not on coefficients); sigma_rr = sigma_theta at the points.
// The tolerance on the field is not round-off: Gauss quadrature of RK functions does not
// integrate the divergence of a uniform stress exactly (no integration constraint), which
// leaves a small residual force on interior particles; we measure and bound it.

#include <doctest/doctest.h>

#include "support/solver_fixtures.hpp"

namespace test_numeric_axisymmetric_expansion {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

namespace {

struct expansion {
  double field = 0.0;    // max |u - (V t r, 0)| / (V t R0) over the particles
  double axis = 0.0;     // max |u_r| / (V t R0) over the axis particles
  double mean_rr = 0.0;  // volume-weighted mean sigma_rr, relative to the closed form
  double mean_tt = 0.0;  // the same for sigma_theta
  double balance = 0.0;  // energy().balance_error()
};

template <class Cfg>
expansion expand(int n) {
  const material::elastic_constants c{117e9, 0.35, 8930.0};
  const double R0 = 3.2e-3, Lz = 6.4e-3;
  const double strain = 2e-3, end_time = 20.0 * R0 / c.dilatational_wave_speed();
  const double V = strain / end_time;
  auto p = test::grid_problem<Cfg>(vec2(0, 0), vec2(R0, Lz), Eigen::Vector2i(n, n), c);
  p.initial_velocity = [V](const vec2& X) { return vec2(V * X[0], 0.0); };
  for (index_t I = 0; I < p.particles.size(); ++I) {
    const vec2& X = p.particles.position[I];
    if (X[0] == R0) p.constraints.push_back({I, 0, [V, R0](double) { return V * R0; }});
    if (X[1] == 0.0 || X[1] == Lz) p.constraints.push_back({I, 1, {}});
  }
  run_options o;
  o.end_time = end_time;
  auto s = make_solver<Cfg>(std::move(p), o);
  s.run();
  const double t = s.time();
  CHECK(t == doctest::Approx(end_time).epsilon(1e-12));
  const double outer = V * t * R0;
  const auto u = s.particle_displacements();
  expansion r;
  for (index_t I = 0; I < s.model().particle_count(); ++I) {
    const vec2& X = s.model().particles.position[I];
    r.field = std::max(r.field, (u[I] - vec2(V * t * X[0], 0.0)).norm() / outer);
    if (X[0] == 0.0) r.axis = std::max(r.axis, std::abs(u[I][0]) / outer);
  }
  // Closed form of the uniform state: eps_rr = eps_tt = ln(1 + V t), eps_zz = 0,
  // tau_rr = tau_tt = (2 lambda + 2 mu) eps, sigma = tau / J with J = (1 + V t)^2.
  const double eps = std::log1p(V * t), J = (1.0 + V * t) * (1.0 + V * t);
  const double sigma = (2.0 * c.lame_lambda() + 2.0 * c.shear_modulus()) * eps / J;
  double w = 0.0, rr = 0.0, tt = 0.0;
  for (index_t q = 0; q < s.model().point_count(); ++q) {
    const mat3 sig = s.point_cauchy_stress(q);
    w += s.model().points.weight[q];
    rr += s.model().points.weight[q] * sig(0, 0);
    tt += s.model().points.weight[q] * sig(2, 2);
  }
  r.mean_rr = std::abs(rr / w / sigma - 1.0);
  r.mean_tt = std::abs(tt / w / sigma - 1.0);
  r.balance = s.energy().balance_error();
  return r;
}

template <class Cfg>
void check_rule(const std::string& rule, double coarse_bound) {
  const auto coarse = expand<Cfg>(9), fine = expand<Cfg>(17);
  for (const auto* r : {&coarse, &fine}) {
    MESSAGE(rule << std::string(r == &coarse ? " 9x9" : " 17x17") << ": field error " << r->field << ", axis u_r "
                 << r->axis << ", mean sigma_rr " << r->mean_rr << ", mean sigma_tt " << r->mean_tt
                 << ", balance " << r->balance);
    CHECK(r->axis < 1e-12);
    CHECK(r->balance < 1e-4);
  }
  CHECK(coarse.field < coarse_bound);
  CHECK(fine.field < 0.6 * coarse.field);  // consistent: the error falls about like h
  CHECK(coarse.mean_rr < 0.1 * coarse_bound);
  CHECK(coarse.mean_tt < 0.1 * coarse_bound);
}

}  // namespace

TEST_CASE("uniform radial expansion stays u_r = a r; the axis stays at u_r = 0") {
  test::run_serially();
  using cfg_q4 = config<kernel::cubic_spline, correction::linear, quadrature::q4, geometry::axisymmetric,
                        material::elastic, contact::none>;
  // q4: 0.3 % at 9 x 9 particles.
  check_rule<cfg_q4>("q4", 1e-2);
  // q2 (the diagonal Gauss pair) is about 25 times less accurate here: 9 % at 9 x 9, 4 % at 17 x 17.
  check_rule<cfg_q4::with_quadrature<quadrature::q2>>("q2", 0.15);
}

}  // namespace test_numeric_axisymmetric_expansion
