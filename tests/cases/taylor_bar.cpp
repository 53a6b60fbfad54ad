// The Taylor bar (cases/taylor_bar.hpp, docs/method.md section 10.1), reduced: the paper's 21 x 51
// particles but only the first microseconds of the impact. Physical invariants, checked after
// every step through the observer (no stored numbers):
//   - no slave particle's physical position lies below the wall by more than 2% of the axial
//     spacing (the contact closes the gap on the predicted configuration);
//   - energy balance kinetic + internal = initial kinetic + contact within 1%;
//   - the impact face only spreads (its radius grows) and the bar only shortens;
//   - u_r = 0 on the axis to round-off (the axisymmetric constraint acts on physical velocities);
//   - plastic flow has started at the impact face, and it is largest there;
//   - Newton's law along z: P_z(t) - P_z(0) = -sum_steps reaction_z dt (internal forces sum to
//     zero by the partition of unity; the axis constraint acts on r only; no body force);
//   - the case's measures at the end: its height is the largest z and its length the largest
//     less the smallest z of the particles (the impact face is below z = 0 by the contact's
//     small penetration here, above it once the bar lifts off: the length is not the height).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/solver/make_solver.hpp>

#include "cases/taylor_bar.hpp"

namespace test_cases_taylor_bar {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

namespace {

using tb = cases::taylor_bar;
using contact_t = contact::particle_to_segment<contact::enforcement::paper, contact::friction::coulomb>;

struct impact_record {
  double end_time = 0.0;
  double h_r = 0.0, h_z = 0.0;        // particle spacings
  double worst_depth = 0.0;           // deepest slave below z = 0 after any step (m)
  double radius_decrease = 0.0;       // largest step-to-step shrink of the impact-face radius (m)
  double height_increase = 0.0;       // largest step-to-step growth of the height (m)
  double radius0 = 0.0, radius = 0.0; // impact-face radius at t = 0 and at the end
  double height0 = 0.0, height = 0.0;
  double axis_ur = 0.0;               // largest |u_r| of an axis particle over the run
  double momentum_error = 0.0;        // |dP_z - impulse_z| / (M V)
  double impulse_z = 0.0, mass = 0.0; // wall impulse received by the bar; mass (per radian)
  double balance_error = 0.0;
  double min_eps_p_face = 1e30;       // smallest eps_p of the quadrature points in the lowest cell row
  double max_eps_p_face = 0.0;        // largest eps_p in the lowest tenth of the bar
  double max_eps_p_top = 0.0;         // largest eps_p in the highest tenth
  double lowest = 0.0;                // smallest z of the particles at the end (m)
  double measured_height_mm = 0.0, measured_length_mm = 0.0;  // the case's measure() at the end
  long steps = 0;
};

template <class Quadrature>
impact_record impact(double end_time) {
  using cfg = config<kernel::cubic_spline, correction::linear, Quadrature, tb::geometry_type, tb::material_type,
                     contact_t>;
  tb::parameters p;
  p.end_time_s = end_time;
  run_options o;
  o.end_time = tb::end_time(p);
  auto s = make_solver<cfg>(tb::build<contact_t>(p, 1), o);

  impact_record r;
  r.end_time = end_time;
  r.h_r = p.radius_m / (p.radial_particles - 1.0);
  r.h_z = p.height_m / (p.axial_particles - 1.0);
  const auto& X = s.model().particles.position;
  const index_t n = s.model().particle_count();
  auto momentum_z = [&] {
    double P = 0.0;
    for (index_t I = 0; I < n; ++I) P += s.mass()[I] * s.coefficient_velocities()[I].y();
    return P;
  };
  for (double m : s.mass()) r.mass += m;
  const double P0 = momentum_z();
  double radius_prev = -1.0, height_prev = -1.0;
  s.run(
      [&](const auto& s) {
        const auto x = s.particle_positions();
        for (index_t J : s.slave_particles()) r.worst_depth = std::max(r.worst_depth, -x[J].y());
        double radius = 0.0, height = 0.0;
        for (index_t I = 0; I < n; ++I) {
          if (X[I].y() <= 1e-12) radius = std::max(radius, x[I].x());
          height = std::max(height, x[I].y());
          if (X[I].x() <= 1e-12) r.axis_ur = std::max(r.axis_ur, std::abs(x[I].x()));
        }
        if (radius_prev >= 0.0) {
          r.radius_decrease = std::max(r.radius_decrease, radius_prev - radius);
          r.height_increase = std::max(r.height_increase, height - height_prev);
        } else {
          r.radius0 = radius;
          r.height0 = height;
        }
        radius_prev = r.radius = radius;
        height_prev = r.height = height;
      },
      1);
  {
    const auto x = s.particle_positions();
    r.lowest = x[0].y();
    for (const vec2& xi : x) r.lowest = std::min(r.lowest, xi.y());
    for (const auto& [name, value] : tb::measure(s, p, {})) {
      if (name == "height_mm") r.measured_height_mm = value;
      if (name == "length_mm") r.measured_length_mm = value;
    }
  }
  r.impulse_z = -s.tool_impulses()[0].y();  // the wall's reaction is the bar's push on it
  r.momentum_error = std::abs(momentum_z() - P0 - r.impulse_z) / (r.mass * p.velocity_m_s);
  r.balance_error = s.energy().balance_error();
  r.steps = static_cast<long>(s.steps());
  const auto& points = s.model().points;
  for (index_t q = 0; q < s.model().point_count(); ++q) {
    const double z = points.position[q].y(), eps = s.point_states()[q].equivalent_plastic_strain;
    if (z < r.h_z) r.min_eps_p_face = std::min(r.min_eps_p_face, eps);
    if (z < 0.1 * p.height_m) r.max_eps_p_face = std::max(r.max_eps_p_face, eps);
    if (z > 0.9 * p.height_m) r.max_eps_p_top = std::max(r.max_eps_p_top, eps);
  }
  MESSAGE(Quadrature::name, ", ", end_time * 1e6, " us, ", r.steps, " steps: worst depth ", r.worst_depth / r.h_z,
          " h_z; radius ", r.radius0 * 1e3, " -> ", r.radius * 1e3, " mm (largest shrink ", r.radius_decrease,
          " m); height ", r.height0 * 1e3, " -> ", r.height * 1e3, " mm (largest growth ", r.height_increase,
          " m); axis |u_r| ", r.axis_ur, " m; momentum error ", r.momentum_error, " (impulse ", r.impulse_z,
          ", M V ", r.mass * p.velocity_m_s, "); balance error ", r.balance_error, "; eps_p face min ",
          r.min_eps_p_face, " max ", r.max_eps_p_face, ", top max ", r.max_eps_p_top);
  return r;
}

void check(const impact_record& r, const tb::parameters& p) {
  CHECK(r.worst_depth < 0.02 * r.h_z);
  CHECK(r.balance_error < 0.01);
  // Monotone to round-off of the positions (1e-12 of the bar size).
  CHECK(r.radius_decrease <= 1e-12 * p.height_m);
  CHECK(r.height_increase <= 1e-12 * p.height_m);
  // Noticeable spreading: the mushroom starts at once (the face is plastic from the first steps).
  CHECK(r.radius > r.radius0 + 0.5 * r.h_r);
  // The top still moves at about V (the unloading wave has not slowed it much yet).
  CHECK(r.height < r.height0 - 0.5 * p.velocity_m_s * r.end_time);
  CHECK(r.height > r.height0 - 1.01 * p.velocity_m_s * r.end_time);
  CHECK(r.axis_ur < 1e-12 * p.radius_m);
  CHECK(r.min_eps_p_face > 0.0);
  CHECK(r.max_eps_p_face > 10.0 * r.max_eps_p_top);
  // The wall pushed up on the bar: a positive impulse, a fair part of M V in a few microseconds.
  CHECK(r.impulse_z > 0.05 * r.mass * p.velocity_m_s);
  CHECK(r.momentum_error < 1e-10);
  // The measures: the height is the top's z, the length the top's less the lowest point's.
  CHECK(r.measured_height_mm == r.height * 1e3);
  CHECK(r.lowest != 0.0);  // so that the length and the height differ
  CHECK(r.measured_length_mm == doctest::Approx((r.height - r.lowest) * 1e3).epsilon(1e-14));
}

}  // namespace

TEST_CASE("Taylor bar, first 10 us with Q2: contact, energy, monotone shape, axis, plasticity, momentum") {
  check(impact<quadrature::q2>(10e-6), tb::parameters{});
}

TEST_CASE("Taylor bar, first 4 us with Q4: the same invariants") {
  check(impact<quadrature::q4>(4e-6), tb::parameters{});
}

// The library has no unit of its own: the same bar given in millimetres, microseconds and
// milligrams (a consistent set: stress in GPa, density in mg/mm^3 = 1e3 kg/m^3, velocity in
// mm/us = 1e3 m/s, force in kN, energy in J) takes the same steps to the same shape. Every
// tolerance inside (the axis, the contact depth, the stable step, the moment conditioning) is
// relative; an absolute one would show here.
TEST_CASE("Taylor bar in mm, us and mg: the SI run's steps, shape, plastic strain and energies") {
  using cfg = config<kernel::cubic_spline, correction::linear, quadrature::q2, tb::geometry_type, tb::material_type,
                     contact_t>;
  const double end_time_s = 6e-6;
  tb::parameters si;
  si.end_time_s = end_time_s;
  tb::parameters mm = si;
  const double length = 1e3, time = 1e6, stress = 1e-9, density = 1e-3;  // SI value x factor = mm-us-mg value
  mm.radius_m = si.radius_m * length;
  mm.height_m = si.height_m * length;
  mm.velocity_m_s = si.velocity_m_s * length / time;
  mm.end_time_s = si.end_time_s * time;
  mm.youngs_modulus_Pa = si.youngs_modulus_Pa * stress;
  mm.yield_stress_Pa = si.yield_stress_Pa * stress;
  mm.hardening_modulus_Pa = si.hardening_modulus_Pa * stress;
  mm.density_kg_m3 = si.density_kg_m3 * density;

  auto run = [](const tb::parameters& p) {
    run_options o;
    o.end_time = tb::end_time(p);
    auto s = make_solver<cfg>(tb::build<contact_t>(p, 1), o);
    s.run();
    return s;
  };
  const auto a = run(si);
  const auto b = run(mm);
  REQUIRE(a.steps() == b.steps());
  CHECK(b.time_step() == doctest::Approx(a.time_step() * time).epsilon(1e-12));
  const auto xa = a.particle_positions(), xb = b.particle_positions();
  double shape = 0.0, moved = 0.0;
  for (std::size_t I = 0; I < xa.size(); ++I) {
    shape = std::max(shape, (xb[I] / length - xa[I]).norm());
    moved = std::max(moved, (xa[I] - a.model().particles.position[I]).norm());
  }
  MESSAGE(a.steps(), " steps; largest particle displacement ", moved * 1e3, " mm; SI and mm-us-mg shapes differ by ",
          shape / moved, " of it");
  CHECK(moved > 0.5e-3);  // the bar has moved and flattened: a real comparison
  CHECK(shape < 1e-10 * moved);
  double eps_a = 0.0, eps_b = 0.0;
  for (const auto& st : a.point_states()) eps_a = std::max(eps_a, st.equivalent_plastic_strain);
  for (const auto& st : b.point_states()) eps_b = std::max(eps_b, st.equivalent_plastic_strain);
  CHECK(eps_a > 0.01);
  CHECK(eps_b == doctest::Approx(eps_a).epsilon(1e-9));
  // Energy: mg mm^2 / us^2 = 1 J, so the ledgers agree as they stand.
  CHECK(b.energy().kinetic == doctest::Approx(a.energy().kinetic).epsilon(1e-9));
  CHECK(b.energy().plastic == doctest::Approx(a.energy().plastic).epsilon(1e-9));
  CHECK(b.energy().contact == doctest::Approx(a.energy().contact).epsilon(1e-9));
  // Force: kN, so the wall's impulse in kN us = 1e-3 N s.
  CHECK(b.tool_impulses()[0].y() * 1e-3 == doctest::Approx(a.tool_impulses()[0].y()).epsilon(1e-9));
}

}  // namespace test_cases_taylor_bar
