// The scalar radial-return equation q_trial - 3 mu dgamma - sigma_y(eps_p + dgamma) = 0:
// closed form for linear hardening, safeguarded Newton for the power law (converges in a few
// iterations over the whole range of trial stresses, the root checked by bisection), and an
// rkpm::error naming the residual and the iteration count when it cannot converge.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include <rkpm/material/j2_plasticity.hpp>
#include <rkpm/material/radial_return.hpp>

namespace test_unit_material_radial_return {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using rkpm::material::radial_return;
namespace h = rkpm::material::hardening;

namespace {

const double three_mu = 3.0 * 71e9 / 2.6;  // aluminium
const h::power_law wheel{576.79e6, 0.01658, 0.3593};

// Root of the return equation by plain bisection, as an independent reference.
template <class H>
double bisection_root(const H& law, double q_trial, double eps_p) {
  double lo = 0.0, hi = q_trial / three_mu;
  for (int i = 0; i < 300; ++i) {
    const double mid = 0.5 * (lo + hi);
    (q_trial - three_mu * mid - law.flow_stress(eps_p + mid) > 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// A user law that softens: sigma_y falls with eps_p.
struct softening {
  static constexpr std::string_view name = "softening";
  double flow_stress(double e) const { return 300e6 * std::exp(-5.0 * e) + 50e6; }
  double slope(double e) const { return -1.5e9 * std::exp(-5.0 * e); }
};
static_assert(rkpm::Hardening<softening>);

}  // namespace

TEST_CASE("linear hardening: closed-form increment, no iterations") {
  const h::linear law{400e6, 100e6};
  const double q_trial = 900e6, eps_p = 0.2;
  const auto r = radial_return(law, q_trial, three_mu, eps_p, 1e-12, 50);
  CHECK(r.iterations == 0);
  CHECK(r.increment == doctest::Approx((900e6 - 420e6) / (three_mu + 100e6)).epsilon(1e-15));
  CHECK(std::abs(r.residual) < 1e-14 * q_trial);
}

TEST_CASE("power law: Newton converges in a few iterations over the whole range") {
  int worst = 0;
  for (const double eps_p : {0.0, 1e-4, 0.05, 1.0, 5.0}) {
    const double yield = wheel.flow_stress(eps_p);
    // From barely above yield to a trial stress 100 times the flow stress (a huge step).
    for (const double factor : {1.0 + 1e-9, 1.001, 1.1, 2.0, 10.0, 100.0}) {
      const double q_trial = factor * yield;
      CAPTURE(eps_p);
      CAPTURE(factor);
      const auto r = radial_return(wheel, q_trial, three_mu, eps_p, 1e-12, 50);
      CHECK(std::abs(r.residual) <= 1e-12 * q_trial);
      CHECK(r.increment > 0.0);
      CHECK(r.increment == doctest::Approx(bisection_root(wheel, q_trial, eps_p)).epsilon(1e-10));
      // The flow stress it returns is the law's at the new strain (j2_plasticity's plastic work
      // reads it instead of evaluating the law again).
      CHECK(r.flow_stress == doctest::Approx(wheel.flow_stress(eps_p + r.increment)).epsilon(1e-15));
      worst = std::max(worst, r.iterations);
    }
  }
  // Newton on this concave law approaches the root monotonically from below; quadratic
  // convergence keeps the count small.
  CHECK(worst <= 5);
  MESSAGE("most Newton iterations needed: " << worst);
}

TEST_CASE("a Newton that cannot converge throws with the residual and the iteration count") {
  const double q_trial = 50.0 * wheel.flow_stress(0.0);
  std::string message;
  try {
    (void)radial_return(wheel, q_trial, three_mu, 0.0, 1e-12, 1);
  } catch (const rkpm::error& e) {
    message = e.what();
  }
  CAPTURE(message);
  CHECK(message.find("did not converge") != std::string::npos);
  CHECK(message.find("residual") != std::string::npos);
  CHECK(message.find("after 1 iterations") != std::string::npos);
  CHECK(message.find("max_newton_iterations") != std::string::npos);

  // The same limit set on the material surfaces through kirchhoff_stress.
  const rkpm::material::j2_plasticity<h::power_law> law({71e9, 0.3, 2700.0}, wheel, 1e-12, 1);
  auto s = law.initial_state();
  rkpm::mat3 F = rkpm::mat3::Identity();
  F(0, 0) = 1.3;
  CHECK_THROWS_WITH_AS(law.kirchhoff_stress(F, s), doctest::Contains("residual"), rkpm::error);
}

TEST_CASE("a softening user law is still bracketed: bisection keeps eps_p + dgamma >= eps_p") {
  // sigma_y falls with eps_p (slope negative): Newton steps can leave [0, q_trial / 3 mu] and are
  // replaced by bisection; the root still satisfies the return equation.
  const softening law;
  const double q_trial = 2.0 * law.flow_stress(0.1);
  const auto r = radial_return(law, q_trial, three_mu, 0.1, 1e-12, 100);
  CHECK(std::abs(r.residual) <= 1e-12 * q_trial);
  CHECK(r.increment == doctest::Approx(bisection_root(law, q_trial, 0.1)).epsilon(1e-10));
}

}  // namespace test_unit_material_radial_return
