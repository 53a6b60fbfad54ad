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
#include <doctest/doctest.h>

#include <cmath>

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
};

template <class Quadrature>
final_shape run() {
  using cfg = config<kernel::cubic_spline, correction::linear, Quadrature, tb::geometry_type, tb::material_type,
                     contact_t>;
  const tb::parameters p;  // the paper's: 227 m/s, 80 us, 21 x 51 particles at resolution 1
  run_options o;
  o.end_time = tb::end_time(p);
  auto s = make_solver<cfg>(tb::build<contact_t>(p, 1), o);
  s.run();
  final_shape r;
  for (const auto& [name, value] : tb::measure(s, p, {})) {
    if (name == "height_mm") r.height_mm = value;
    if (name == "radius_mm") r.radius_mm = value;
    if (name == "length_mm") r.length_mm = value;
  }
  MESSAGE(Quadrature::name, ", ", s.time() * 1e6, " us, ", s.steps(), " steps: height ", r.height_mm, " mm, length ",
          r.length_mm, " mm, radius ", r.radius_mm, " mm (Table 3: height ", height_low_mm, "-", height_high_mm,
          ", radius ", radius_low_mm, "-", radius_high_mm, ")");
  CHECK(s.time() == doctest::Approx(p.end_time_s).epsilon(1e-12));
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
  check_against_table3(run<quadrature::q2>());
}

TEST_CASE("Taylor bar at 80 us with Q4: Table 3's height within 0.5%, radius within 3%, length = height") {
  check_against_table3(run<quadrature::q4>());
}

}  // namespace test_cases_taylor_bar_table3
