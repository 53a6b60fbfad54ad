// Hardening laws: flow stress, slope and exact work integral against the closed forms of
// docs/method.md section 10 (Taylor bar copper, wheel aluminium), and rejection of bad parameters.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include <rkpm/material/hardening.hpp>
#include <rkpm/material/j2_plasticity.hpp>

#include "support/error_message.hpp"

namespace test_unit_material_hardening {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using rkpm::test::contains;
using rkpm::test::error_message;

namespace h = rkpm::material::hardening;

TEST_CASE("linear hardening: Taylor bar copper, 400 MPa + 100 MPa eps_p") {
  const h::linear law{400e6, 100e6};
  law.validate();
  CHECK(law.flow_stress(0.0) == 400e6);
  CHECK(law.flow_stress(0.5) == doctest::Approx(450e6).epsilon(1e-15));
  CHECK(law.slope(0.3) == 100e6);
  // int_0.1^0.5 (400 + 100 e) de = 400 * 0.4 + 50 * (0.25 - 0.01) = 172 MJ/m^3.
  CHECK(law.integral(0.1, 0.5) == doctest::Approx(172e6).epsilon(1e-14));
}

TEST_CASE("power-law hardening: wheel aluminium, 576.79 MPa (0.01658 + eps_p)^0.3593") {
  const h::power_law law{576.79e6, 0.01658, 0.3593};
  law.validate();
  // The paper quotes the initial yield as 132.2 MPa.
  CHECK(law.flow_stress(0.0) == doctest::Approx(132.2e6).epsilon(5e-4));
  for (const double e : {0.0, 1e-3, 0.05, 0.5, 2.0}) {
    CAPTURE(e);
    const double base = 0.01658 + e;
    CHECK(law.flow_stress(e) == doctest::Approx(576.79e6 * std::pow(base, 0.3593)).epsilon(1e-14));
    // Slope against a central difference of the closed form (step relative to the base).
    const double d = 1e-5 * base;
    const double fd =
        576.79e6 * (std::pow(base + d, 0.3593) - std::pow(base - d, 0.3593)) / (2 * d);
    CHECK(law.slope(e) == doctest::Approx(fd).epsilon(1e-8));
    // The form the return mapping uses, from a known flow stress: the same slope.
    CHECK(law.slope(e, law.flow_stress(e)) == doctest::Approx(fd).epsilon(1e-8));
  }
  // Work integral against composite Simpson on [0.01, 0.4].
  const int n = 2000;
  const double a = 0.01, b = 0.4, step = (b - a) / n;
  double simpson = law.flow_stress(a) + law.flow_stress(b);
  for (int i = 1; i < n; ++i) simpson += (i % 2 ? 4.0 : 2.0) * law.flow_stress(a + i * step);
  simpson *= step / 3.0;
  CHECK(law.integral(a, b) == doctest::Approx(simpson).epsilon(1e-12));
  // From the flow stresses at the ends (the form j2_plasticity uses): the same integral.
  CHECK(law.integral(a, b, law.flow_stress(a), law.flow_stress(b)) == doctest::Approx(simpson).epsilon(1e-12));
}

TEST_CASE("power-law with exponent 0 is perfectly plastic") {
  const h::power_law law{200e6, 0.01, 0.0};
  law.validate();
  CHECK(law.flow_stress(0.7) == doctest::Approx(200e6).epsilon(1e-15));
  CHECK(law.slope(0.7) == 0.0);
}

TEST_CASE("bad hardening parameters are rejected with the parameter named") {
  const rkpm::material::elastic_constants copper{117e9, 0.35, 8930.0};
  const auto check_linear = [&](h::linear law, const std::string& parameter) {
    CAPTURE(parameter);
    CHECK(contains(error_message([&] { law.validate(); }), parameter));
    CHECK(contains(error_message([&] { rkpm::material::j2_plasticity<h::linear>(copper, law); }),
                   parameter));
  };
  check_linear({-400e6, 100e6}, "yield_stress");
  check_linear({0.0, 100e6}, "yield_stress");
  check_linear({NAN, 100e6}, "yield_stress");
  check_linear({400e6, -100e6}, "modulus");
  check_linear({400e6, INFINITY}, "modulus");

  const auto check_power = [&](h::power_law law, const std::string& parameter) {
    CAPTURE(parameter);
    CHECK(contains(error_message([&] { law.validate(); }), parameter));
    CHECK(contains(
        error_message([&] { rkpm::material::j2_plasticity<h::power_law>(copper, law); }),
        parameter));
  };
  check_power({-576.79e6, 0.01658, 0.3593}, "coefficient");
  check_power({576.79e6, 0.0, 0.3593}, "offset");
  check_power({576.79e6, -0.01, 0.3593}, "offset");
  check_power({576.79e6, 0.01658, -0.5}, "exponent");

  // The guard on eps0 + eps_p: a negative plastic strain never reaches pow() as a NaN.
  const h::power_law wheel{576.79e6, 0.01658, 0.3593};
  CHECK(contains(error_message([&] { (void)wheel.flow_stress(-0.1); }), "offset + eps_p"));

  // Solver settings of the return mapping.
  CHECK(contains(error_message([&] {
                   rkpm::material::j2_plasticity<h::power_law>(copper, wheel, 0.0);
                 }),
                 "newton_tolerance"));
  CHECK(contains(error_message([&] {
                   rkpm::material::j2_plasticity<h::power_law>(copper, wheel, 1e-12, 0);
                 }),
                 "max_newton_iterations"));
}

}  // namespace test_unit_material_hardening
