// elastic_constants: derived moduli against hand-computed values for the paper's materials and
// rejection of out-of-range constants with a message that names the parameter.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include <rkpm/material/elastic.hpp>
#include <rkpm/material/elastic_constants.hpp>
#include <rkpm/material/j2_plasticity.hpp>

#include "support/error_message.hpp"

namespace test_unit_material_elastic_constants {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using rkpm::test::contains;
using rkpm::test::error_message;

using rkpm::material::elastic_constants;

TEST_CASE("copper constants (Taylor bar, spec section 5): derived moduli") {
  const elastic_constants c{117e9, 0.35, 8930.0};
  c.validate();
  // mu = 117 / 2.7, K = 117 / 0.9 = 130, lambda = 117 * 0.35 / 0.405 (GPa).
  CHECK(c.shear_modulus() == doctest::Approx(117e9 / 2.7).epsilon(1e-15));
  CHECK(c.bulk_modulus() == doctest::Approx(130e9).epsilon(1e-15));
  CHECK(c.lame_lambda() == doctest::Approx(40.95e9 / 0.405).epsilon(1e-15));
  // Independent identities: K = lambda + 2 mu / 3, E = 2 mu (1 + nu) = 3 K (1 - 2 nu).
  CHECK(c.bulk_modulus() == doctest::Approx(c.lame_lambda() + 2.0 * c.shear_modulus() / 3.0)
                                .epsilon(1e-14));
  // c_d = sqrt(E (1 - nu) / ((1 + nu) (1 - 2 nu) rho)) = 4585.6 m/s for copper.
  const double expected = std::sqrt(117e9 * 0.65 / (1.35 * 0.3 * 8930.0));
  CHECK(c.dilatational_wave_speed() == doctest::Approx(expected).epsilon(1e-14));
  CHECK(c.dilatational_wave_speed() == doctest::Approx(4585.6).epsilon(1e-4));
}

TEST_CASE("materials report density, wave speed and constants") {
  const elastic_constants al{71e9, 0.3, 2700.0};
  const rkpm::material::elastic e(al);
  const rkpm::material::j2_plasticity<rkpm::material::hardening::power_law> j2(
      al, {576.79e6, 0.01658, 0.3593});
  const double c = std::sqrt(71e9 * 0.7 / (1.3 * 0.4 * 2700.0));
  for (const double speed : {e.dilatational_wave_speed(), j2.dilatational_wave_speed()})
    CHECK(speed == doctest::Approx(c).epsilon(1e-14));
  CHECK(e.density() == 2700.0);
  CHECK(j2.density() == 2700.0);
  CHECK(&j2.constants() != &al);
  CHECK(j2.constants().youngs_modulus == 71e9);
}

TEST_CASE("out-of-range elastic constants are rejected with the parameter named") {
  const auto check_rejected = [](elastic_constants c, const std::string& parameter) {
    CAPTURE(parameter);
    const std::string message = error_message([&] { c.validate(); });
    CHECK(contains(message, parameter));
    // The material constructors validate too.
    CHECK(contains(error_message([&] { rkpm::material::elastic{c}; }), parameter));
    CHECK(contains(error_message([&] {
                     rkpm::material::j2_plasticity<rkpm::material::hardening::linear>(
                         c, {400e6, 100e6});
                   }),
                   parameter));
  };
  check_rejected({-117e9, 0.35, 8930.0}, "youngs_modulus");
  check_rejected({0.0, 0.35, 8930.0}, "youngs_modulus");
  check_rejected({NAN, 0.35, 8930.0}, "youngs_modulus");
  check_rejected({INFINITY, 0.35, 8930.0}, "youngs_modulus");
  check_rejected({117e9, 0.5, 8930.0}, "poisson_ratio");
  check_rejected({117e9, -1.2, 8930.0}, "poisson_ratio");
  check_rejected({117e9, -1.0, 8930.0}, "poisson_ratio");
  check_rejected({117e9, NAN, 8930.0}, "poisson_ratio");
  check_rejected({117e9, 0.35, 0.0}, "density");
  check_rejected({117e9, 0.35, -8930.0}, "density");

  // Values just inside the open range are accepted.
  CHECK(error_message([] { elastic_constants{1.0, 0.4999, 1.0}.validate(); }).empty());
  CHECK(error_message([] { elastic_constants{1.0, -0.9999, 1.0}.validate(); }).empty());
  // The message gives the offending value and the valid range.
  const std::string message =
      error_message([] { elastic_constants{117e9, 0.5, 8930.0}.validate(); });
  CHECK(contains(message, "0.5"));
  CHECK(contains(message, "(-1, 0.5)"));
}

}  // namespace test_unit_material_elastic_constants
