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
//     itself but a mirror does not, so with Q2 only the half-turn symmetry holds exactly.
// Against the closed forms of docs/method.md section 10.2 (plane-strain compression of a
// rigid-plastic block, k = sigma_y / sqrt 3, h the tool gap, c the contact width, A0 the area):
//   - the widths from volume constancy (97): W0 <= w_face <= A0 / h <= w_mid <= 2 A0 / h - W0;
//   - the top tool's force (mean over the last tenth: inertia and contact noise averaged out)
//     between the lower bound (94), 2 k0 c at the initial yield stress with the contact width
//     of the particles touching the tool, and the upper bound (95), 2 k_max (A0 / h + c'^2 / 4h)
//     at the largest flow stress reached, c' that width plus one spacing (the contact reaches
//     at most half a spacing past the outermost particle touching on each side); the slab
//     estimate (96), 2 k c (exp(mu c / h) - 1) / (mu c / h), is printed beside.
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

TEST_CASE_TEMPLATE("block forging to 20%: tools not crossed, volume kept, symmetry, widths and tool force within the bounds (94)-(97)", Q,
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
  // The width of the top tool's contact: the x-extent of the particles within 1% of a spacing
  // of it (faces and any side particles folded onto it), and the tool gap, at a time.
  struct contact_width {
    double c = 0.0, gap = 0.0;
  };
  auto measure_contact = [&](const auto& s) {
    const auto x = s.particle_positions();
    const double top = p.height_m - v * s.time();
    double lo = 1e30, hi = -1e30;
    for (index_t I = 0; I < n; ++I)
      if (x[I].y() > top - 0.01 * h) {
        lo = std::min(lo, x[I].x());
        hi = std::max(hi, x[I].x());
      }
    return contact_width{hi - lo, bf::gap(p, s.time())};
  };
  contact_width late_contact;
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
          late_contact = measure_contact(s);
        }
      },
      1);
  const double late_impulse = s.tool_impulses()[1].y() - late_start_impulse, late_time = s.time() - late_start;
  const contact_width end_contact = measure_contact(s);

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

  // The closed forms of docs/method.md section 10.2 over the averaging window (its start and
  // end), with the flow stresses of the linear hardening law: the initial one, which every point
  // has at least, and the largest reached (at the end: eps_p only grows).
  double eps_p_max = 0.0;
  for (const auto& st : s.point_states()) eps_p_max = std::max(eps_p_max, st.equivalent_plastic_strain);
  const double k0 = p.yield_stress_Pa / std::sqrt(3.0);
  const double k_max = (p.yield_stress_Pa + p.hardening_modulus_Pa * eps_p_max) / std::sqrt(3.0);
  const double A0 = p.width_m * p.height_m;
  const auto lower_94 = [&](const contact_width& cw) { return 2.0 * k0 * cw.c; };
  const auto upper_95 = [&](const contact_width& cw) {
    const double c = cw.c + h;
    return 2.0 * k_max * (A0 / cw.gap + c * c / (4.0 * cw.gap));
  };
  const auto slab_96 = [&](const contact_width& cw, double k) {
    const double a = p.friction * cw.c / cw.gap;
    return 2.0 * k * cw.c * std::expm1(a) / a;
  };
  const double lower = std::min(lower_94(late_contact), lower_94(end_contact));
  const double upper = std::max(upper_95(late_contact), upper_95(end_contact));
  const double gap = bf::gap(p, s.time()), mean_width = A0 / gap;

  MESSAGE(Q::name, ": ", s.steps(), " steps; worst depth ", worst_depth / h, " h; area change ", area / area0 - 1.0,
          "; widths bottom ", w_bottom, " mid ", w_mid, " top ", w_top, " m; mirror asymmetry ", mirror / h,
          " h, half-turn asymmetry ", half_turn / h, " h; A0/h ", mean_width, " m, bounds (97) [", p.width_m, ", ",
          2.0 * mean_width - p.width_m, "] m; contact width ", late_contact.c, " .. ", end_contact.c,
          " m; max eps_p ", eps_p_max, "; top tool force ", force, " N/m, lower bound (94) ", lower,
          " (ratio ", force / lower, "), upper bound (95) ", upper, " (ratio ", force / upper, "), slab (96) ",
          slab_96(late_contact, k0), " .. ", slab_96(end_contact, k_max), "; balance error ",
          s.energy().balance_error());

  CHECK(worst_depth < 0.02 * h);
  CHECK(std::abs(area / area0 - 1.0) < 0.02);
  // 20% reduction at constant area: the mean width is 1.25 W; the middle bulges past the faces.
  CHECK(w_mid > w_bottom + 0.05 * h);
  CHECK(w_mid > w_top + 0.05 * h);
  // (97), the elastic change of the area (p / K < 1%) allowed for.
  for (const double w_face : {w_bottom, w_top}) {
    CHECK(w_face >= p.width_m * (1.0 - 1e-3));
    CHECK(w_face <= mean_width * 1.01);
  }
  CHECK(w_mid >= mean_width * 0.99);
  CHECK(w_mid <= (2.0 * mean_width - p.width_m) * 1.01);
  CHECK(half_turn < 1e-9 * h);
  if constexpr (std::is_same_v<Q, quadrature::q4>) CHECK(mirror < 1e-9 * h);
  CHECK(force > 0.0);
  CHECK(force >= lower);
  CHECK(force <= upper);
  CHECK(s.energy().balance_error() < 0.02);
}

}  // namespace test_cases_block_forging
