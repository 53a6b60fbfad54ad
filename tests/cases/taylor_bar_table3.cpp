// The paper's Taylor bar (cases/taylor_bar.hpp, docs/method.md section 10.1) run to its end, 80 us,
// at the paper's resolution (21 x 51 particles), with Q2 and with Q4, against the paper's Table 3:
// LS-DYNA's height 21.52 mm and impact-face radius 7.06 mm, the paper's RKPM 21.59 / 7.11 mm (Q2)
// and 21.58 / 7.06 mm (Q4). The references span [21.52, 21.59] mm in height and [7.06, 7.11] mm
// in radius; rkpm must fall within 0.5% of the first and 3% of the second:
//   - the height is a global measure (the top's travel, set by the momentum the wall takes and
//     the plastic work): codes with the same law agree on it to a few tenths of a percent (the
//     references differ by 0.3%). rkpm's is 0.1% below LS-DYNA's with either rule; the band
//     fails a change of 0.4% down or 0.9% up (a yield stress 3% higher lengthens the bar by 1%);
//   - the radius is the largest r of the particles that started on the impact face, one
//     particle at the edge of the mushroom, where discretizations differ most (the references
//     by 0.7%; rkpm's is 1.8% (Q4) and 2.1% (Q2) above LS-DYNA's): 3% of 7.06 mm is 0.21 mm,
//     1.3 radial spacings.
// The bar does not lift off the wall in the paper's case: its length (largest less smallest z)
// equals its height to 0.1%, 0.02 mm (the lowest particle is at the wall to the contact's
// penetration, far below that).
// The same bar re-referenced (docs/method.md section 5.8) against the Q2 run above (run once,
// shared): the kernels rebuilt whenever a point's principal stretch since the last rebuild
// exceeds 1.5, which fires at least three times; the final height and impact-face radius agree
// with the Lagrangian run's within 0.3% and 1%, mass is exact (the masses are the first model's),
// the energy ledger balances with its remap term, and the bar's momentum obeys Newton's law
// through every re-reference (the wall's impulse).
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/solver/make_solver.hpp>

#include "cases/taylor_bar.hpp"

namespace test_cases_taylor_bar_table3 {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

namespace {

using tb = cases::taylor_bar;
using contact_t = contact::particle_to_segment<contact::enforcement::paper, contact::friction::coulomb>;

// Table 3 of the paper, mm: the interval each of rkpm's measures is held to.
constexpr double lsdyna_height_mm = 21.52, lsdyna_radius_mm = 7.06;
constexpr double height_low_mm = lsdyna_height_mm, height_high_mm = tb::paper_height_q2_mm;  // 21.52 .. 21.59
constexpr double radius_low_mm = lsdyna_radius_mm, radius_high_mm = tb::paper_radius_q2_mm;  // 7.06 .. 7.11
constexpr double height_band = 0.005, radius_band = 0.03, length_band = 0.001;

struct final_shape {
  double height_mm = 0.0, radius_mm = 0.0, length_mm = 0.0;
  double momentum_error = 0.0, balance_error = 0.0, remap = 0.0, kinetic0 = 0.0;
  index_t rereferences = 0;
  bool mass_kept = false;
};

// The bar to the paper's end time; `when` re-references it (Q2 only, below).
template <class Quadrature>
final_shape run(rereference_policy when = {}) {
  using cfg = config<kernel::cubic_spline, correction::linear, Quadrature, tb::geometry_type, tb::material_type,
                     contact_t>;
  const tb::parameters p;  // the paper's: 227 m/s, 80 us, 21 x 51 particles at resolution 1
  run_options o;
  o.end_time = tb::end_time(p);
  o.rereference = when;
  auto s = make_solver<cfg>(tb::build<contact_t>(p, 1), o);
  const std::vector<double> mass = s.mass();
  const auto momentum_z = [&] {
    double P = 0.0;
    for (index_t I = 0; I < s.model().particle_count(); ++I) P += s.mass()[I] * s.coefficient_velocities()[I].y();
    return P;
  };
  const double P0 = momentum_z();
  s.run();
  final_shape r;
  for (const auto& [name, value] : tb::measure(s, p, {})) {
    if (name == "height_mm") r.height_mm = value;
    if (name == "radius_mm") r.radius_mm = value;
    if (name == "length_mm") r.length_mm = value;
  }
  double total_mass = 0.0;
  for (double m : mass) total_mass += m;
  r.momentum_error = std::abs(momentum_z() - P0 + s.tool_impulses()[0].y()) / (total_mass * p.velocity_m_s);
  r.balance_error = s.energy().balance_error();
  r.remap = s.energy().remap;
  r.kinetic0 = s.energy().initial_kinetic;
  r.rereferences = s.rereferences();
  r.mass_kept = s.mass() == mass;
  MESSAGE(Quadrature::name, std::string(when.enabled() ? " re-referenced" : ""), ", ", s.time() * 1e6, " us, ", s.steps(),
          " steps: height ", r.height_mm, " mm, length ", r.length_mm, " mm, radius ", r.radius_mm,
          " mm (Table 3: height ", height_low_mm, "-", height_high_mm, ", radius ", radius_low_mm, "-", radius_high_mm,
          ")");
  CHECK(s.time() == doctest::Approx(p.end_time_s).epsilon(1e-12));
  return r;
}

// The Lagrangian Q2 run, once for both test cases that read it.
const final_shape& lagrangian_q2() {
  static const final_shape r = run<quadrature::q2>();
  return r;
}

void check_against_table3(const final_shape& r) {
  CHECK(r.height_mm >= height_low_mm * (1.0 - height_band));
  CHECK(r.height_mm <= height_high_mm * (1.0 + height_band));
  CHECK(r.radius_mm >= radius_low_mm * (1.0 - radius_band));
  CHECK(r.radius_mm <= radius_high_mm * (1.0 + radius_band));
  CHECK(std::abs(r.length_mm - r.height_mm) <= length_band * r.height_mm);
}

}  // namespace

TEST_CASE("Taylor bar at 80 us with Q2: Table 3's height within 0.5%, radius within 3%, length = height") {
  check_against_table3(lagrangian_q2());
}

TEST_CASE("Taylor bar at 80 us with Q4: Table 3's height within 0.5%, radius within 3%, length = height") {
  check_against_table3(run<quadrature::q4>());
}

TEST_CASE("Taylor bar re-referenced by stretch: the Lagrangian run's height and radius") {
  const final_shape& lagrangian = lagrangian_q2();
  const final_shape rebuilt = run<quadrature::q2>({.max_stretch = 1.5, .every_steps = 0});
  CAPTURE(rebuilt.rereferences);
  CHECK(rebuilt.rereferences >= 3);
  CHECK(rebuilt.mass_kept);
  CHECK(rebuilt.height_mm == doctest::Approx(lagrangian.height_mm).epsilon(0.003));
  CHECK(rebuilt.radius_mm == doctest::Approx(lagrangian.radius_mm).epsilon(0.01));
  CHECK(rebuilt.momentum_error < 1e-9);
  CHECK(rebuilt.balance_error < 1e-2);
  CHECK(std::abs(rebuilt.remap) < 1e-2 * rebuilt.kinetic0);
}

}  // namespace test_cases_taylor_bar_table3
