// Block forging (cases/block_forging.hpp, docs/method.md section 10.2), reduced: 11 x 11 particles
// instead of 21 x 21, and 20% compression instead of 60%. Physical invariants:
//   - no slave particle crosses either moving tool by more than 2% of the particle spacing;
//   - plastic incompressibility: the deformed area sum_q J_q w_q stays within a few % of the
//     initial one (only the elastic volume change, p / K ~ 0.5%, is allowed);
//   - barrelling starts: friction holds the faces back, so the block is wider at mid-height
//     than at the tool faces;
//   - symmetry: the set-up is symmetric about x = 0 and about the block's centre (a half turn).
//     Q4 (2x2 Gauss) keeps both, so the solution is mirror symmetric to round-off. Q2's two
//     points lie on one diagonal of each cell, (-,-) and (+,+): a half turn maps the rule onto
//     itself but a mirror does not, so with Q2 only the half-turn symmetry holds exactly;
//   - the top tool is pushed back (positive reaction), with the magnitude of the plane-strain
//     flow load: about (2 / sqrt 3) sigma_y times the contact width, raised by hardening and
//     friction (slab method), with inertia and contact noise averaged out over the last tenth.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <type_traits>
#include <vector>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/solver/make_solver.hpp>

#include "cases/block_forging.hpp"

namespace test_cases_block_forging {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

namespace {

using bf = cases::block_forging;
using contact_t = contact::particle_to_segment<contact::enforcement::paper, contact::friction::coulomb>;

bf::parameters reduced() {
  bf::parameters p;
  p.particles_per_side = 11;
  p.end_time_s = 0.2 * p.height_m / (2.0 * p.tool_velocity_m_s);  // 20% compression
  return p;
}

// Largest |x_I - S(x_{I'})| over the particles, for an isometry S that maps the reference grid
// onto itself (I' the partner of I: X_I' = S(X_I)).
double symmetry_error(const std::vector<vec2>& X, const std::vector<vec2>& x, const std::function<vec2(vec2)>& S,
                      double h) {
  double worst = 0.0;
  const std::size_t n = X.size();
  for (std::size_t I = 0; I < n; ++I) {
    std::size_t partner = n;
    for (std::size_t J = 0; J < n; ++J)
      if ((X[J] - S(X[I])).norm() < 1e-9 * h) partner = J;
    REQUIRE(partner < n);
    worst = std::max(worst, (x[I] - S(x[partner])).norm());
  }
  return worst;
}

}  // namespace

TEST_CASE_TEMPLATE("block forging to 20%: tools not crossed, volume kept, barrelling, symmetry, tool force", Q,
                   quadrature::q4, quadrature::q2) {
  using cfg = config<kernel::cubic_spline, correction::linear, Q, bf::geometry_type, bf::material_type, contact_t>;
  const bf::parameters p = reduced();
  run_options o;
  o.end_time = bf::end_time(p);
  auto s = make_solver<cfg>(bf::build<contact_t>(p, 1), o);

  const double h = p.width_m / (p.particles_per_side - 1.0), v = p.tool_velocity_m_s;
  const auto& X = s.model().particles.position;
  const index_t n = s.model().particle_count();

  // The top tool's mean force over the last tenth of the run: its impulse from the first step
  // past 0.9 T to the end, over that time.
  double worst_depth = 0.0, late_start = -1.0, late_start_impulse = 0.0;
  s.run(
      [&](const auto& s) {
        const double t = s.time();
        const auto x = s.particle_positions();
        const double bottom = v * t, top = p.height_m - v * t;
        for (index_t J : s.slave_particles())
          worst_depth = std::max({worst_depth, bottom - x[J].y(), x[J].y() - top});
        if (t > 0.9 * o.end_time && late_start < 0.0) {
          late_start = t;
          late_start_impulse = s.tool_impulses()[1].y();
        }
      },
      1);
  const double late_impulse = s.tool_impulses()[1].y() - late_start_impulse, late_time = s.time() - late_start;

  const auto x = s.particle_positions();
  // Volume (area per metre of depth) from the quadrature: sum_q J_q w_q against sum_q w_q.
  double area0 = 0.0, area = 0.0;
  for (index_t q = 0; q < s.model().point_count(); ++q) {
    area0 += s.model().points.weight[q];
    area += s.model().points.weight[q] * s.point_det_F(q);
  }
  // Widths of the face rows and of the middle row (reference rows of particles).
  auto row_width = [&](double y_ref) {
    double lo = 1e30, hi = -1e30;
    for (index_t I = 0; I < n; ++I)
      if (std::abs(X[I].y() - y_ref) < 1e-9 * h) {
        lo = std::min(lo, x[I].x());
        hi = std::max(hi, x[I].x());
      }
    return hi - lo;
  };
  const double w_bottom = row_width(0.0), w_top = row_width(p.height_m), w_mid = row_width(0.5 * p.height_m);
  const double yc = 0.5 * p.height_m;
  const double mirror = symmetry_error(X, x, [](vec2 a) { return vec2(-a.x(), a.y()); }, h);
  const double half_turn = symmetry_error(X, x, [yc](vec2 a) { return vec2(-a.x(), 2.0 * yc - a.y()); }, h);
  const double force = late_impulse / late_time;
  const double plane_strain_flow = 2.0 / std::sqrt(3.0) * p.yield_stress_Pa;

  MESSAGE(Q::name, ": ", s.steps(), " steps; worst depth ", worst_depth / h, " h; area change ", area / area0 - 1.0,
          "; widths bottom ", w_bottom, " mid ", w_mid, " top ", w_top, " m; mirror asymmetry ", mirror / h,
          " h, half-turn asymmetry ", half_turn / h, " h; top tool force ", force, " N/m = ",
          force / (plane_strain_flow * w_top), " x (2/sqrt3) sigma_y w_face; balance error ",
          s.energy().balance_error());

  CHECK(worst_depth < 0.02 * h);
  CHECK(std::abs(area / area0 - 1.0) < 0.02);
  // 20% reduction at constant area: the mean width is 1.25 W; the middle bulges past the faces.
  CHECK(w_mid > w_bottom + 0.05 * h);
  CHECK(w_mid > w_top + 0.05 * h);
  CHECK(w_mid > 1.1 * p.width_m);
  CHECK(half_turn < 1e-9 * h);
  if constexpr (std::is_same_v<Q, quadrature::q4>) CHECK(mirror < 1e-9 * h);
  CHECK(force > 0.0);
  CHECK(force > 0.8 * plane_strain_flow * w_top);
  CHECK(force < 1.6 * plane_strain_flow * w_mid);
  CHECK(s.energy().balance_error() < 0.02);
}

}  // namespace test_cases_block_forging
