// Voce hardening (material/hardening/voce.hpp, docs/method.md (24a)) against its closed forms:
// the law itself (flow stress, slope, work integral), then J2 plasticity with it on paths whose
// answer is known without the code: uniaxial stress and uniaxial strain (coaxial paths, where
// the log-strain model is 1D plasticity exactly and the return is exact for any step), and
// simple shear in its small-strain limit. The paths are driven in plastic strain: at a chosen
// eps_p the closed form gives the strain that reaches it, and the model must return that eps_p.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include <rkpm/material/hardening.hpp>
#include <rkpm/material/j2_plasticity.hpp>
#include <rkpm/solver/config.hpp>

#include "support/tensors.hpp"
#include "support/error_message.hpp"

namespace test_unit_material_voce {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using rkpm::mat3;
namespace h = rkpm::material::hardening;

namespace {

using rkpm::test::diagonal;
using rkpm::test::von_mises;

const rkpm::material::elastic_constants copper{117e9, 0.35, 8930.0};
const double mu = copper.shear_modulus(), K = copper.bulk_modulus(), E = copper.youngs_modulus;
const h::voce law{100e6, 150e6, 12.0, 50e6};  // sigma_0, Q, b, H

// The plastic strain p at which f(p) = 0 for an increasing f (bisection, independent of the code).
template <class F>
double root(F f, double lo, double hi) {
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) > 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

TEST_CASE("voce: flow stress, slope and work integral in closed form") {
  law.validate();
  CHECK(law.flow_stress(0.0) == 100e6);
  // sigma_0 + Q (1 - e^-b e) + H e at e = 0.1: 100 + 150 (1 - e^-1.2) + 5 MPa.
  CHECK(law.flow_stress(0.1) == doctest::Approx(100e6 + 150e6 * (1.0 - std::exp(-1.2)) + 5e6).epsilon(1e-15));
  // Saturated: sigma_0 + Q + H e.
  CHECK(law.flow_stress(10.0) == doctest::Approx(250e6 + 500e6).epsilon(1e-12));
  for (double e : {0.0, 0.01, 0.1, 0.5, 2.0}) {
    CAPTURE(e);
    CHECK(law.slope(e) == doctest::Approx(150e6 * 12.0 * std::exp(-12.0 * e) + 50e6).epsilon(1e-15));
    const double step = 1e-6;
    CHECK(law.slope(e + step) == doctest::Approx((law.flow_stress(e + 2 * step) - law.flow_stress(e)) / (2 * step))
                                     .epsilon(1e-6));
  }
  // The integral against Simpson's rule with 2,000 panels (error ~1e-13 relative here).
  const double a = 0.02, b = 0.7;
  const int n = 2000;
  double simpson = law.flow_stress(a) + law.flow_stress(b);
  for (int i = 1; i < n; ++i) simpson += (i % 2 ? 4.0 : 2.0) * law.flow_stress(a + (b - a) * i / n);
  simpson *= (b - a) / (3.0 * n);
  CHECK(law.integral(a, b) == doctest::Approx(simpson).epsilon(1e-12));
  CHECK(law.integral(0.3, 0.3) == 0.0);
  // Q = 0 is linear hardening.
  const h::voce no_saturation{400e6, 0.0, 7.0, 100e6};
  const h::linear linear{400e6, 100e6};
  for (double e : {0.0, 0.2, 1.5}) {
    CHECK(no_saturation.flow_stress(e) == linear.flow_stress(e));
    CHECK(no_saturation.slope(e) == linear.slope(e));
    CHECK(no_saturation.integral(0.0, e) == doctest::Approx(linear.integral(0.0, e)).epsilon(1e-15));
  }
}

TEST_CASE("voce: bad constants are refused with the constant named") {
  using rkpm::test::contains;
  using rkpm::test::error_message;
  CHECK(contains(error_message([] { h::voce{-1.0, 1e8, 10.0, 0.0}.validate(); }), "yield_stress"));
  CHECK(contains(error_message([] { h::voce{1e8, -1e8, 10.0, 0.0}.validate(); }), "saturation_stress"));
  CHECK(contains(error_message([] { h::voce{1e8, 1e8, 0.0, 0.0}.validate(); }), "saturation_rate"));
  CHECK(contains(error_message([] { h::voce{1e8, 1e8, 10.0, -1.0}.validate(); }), "modulus"));
  CHECK_THROWS_AS(rkpm::material::j2_plasticity<h::voce>(copper, h::voce{1e8, 1e8, std::nan(""), 0.0}), rkpm::error);
}

TEST_CASE("voce in J2: uniaxial stress reaches sigma_y(eps_p) at the closed-form strain e = sigma_y / E + eps_p") {
  // Uniaxial stress in log strains: axial elastic strain tau / E, lateral -nu tau / E - eps_p / 2.
  // F = diag(exp(e), l, l) with l solved so that tau22 = tau33 = 0 (secant, to 1e-10 of sigma_y).
  const rkpm::material::j2_plasticity<h::voce> j2(copper, law);
  auto s = j2.initial_state();
  double lateral = 1.0;
  for (double p : {0.001, 0.01, 0.03, 0.08, 0.2, 0.5}) {
    CAPTURE(p);
    const double sigma = law.flow_stress(p), e = sigma / E + p;
    const auto stress = [&](double x, auto& state) {
      return j2.kirchhoff_stress(diagonal(std::exp(e), std::exp(x), std::exp(x)), state);
    };
    const auto lateral_stress = [&](double x) {
      auto trial = s;
      return stress(x, trial)(1, 1);
    };
    double x0 = std::log(lateral), x1 = x0 - 1e-4, r0 = lateral_stress(x0), r1 = lateral_stress(x1);
    for (int it = 0; it < 60 && std::abs(r1) > 1e-10 * sigma; ++it) {
      const double x2 = x1 - r1 * (x1 - x0) / (r1 - r0);
      x0 = x1;
      r0 = r1;
      x1 = x2;
      r1 = lateral_stress(x1);
    }
    REQUIRE(std::abs(r1) <= 1e-10 * sigma);
    const mat3 tau = stress(x1, s);
    lateral = std::exp(x1);
    CHECK(s.equivalent_plastic_strain == doctest::Approx(p).epsilon(1e-8));
    CHECK(tau(0, 0) == doctest::Approx(sigma).epsilon(1e-9));
    CHECK(std::abs(tau(2, 2)) <= 1e-9 * sigma);
    CHECK(x1 == doctest::Approx(-copper.poisson_ratio * sigma / E - 0.5 * p).epsilon(1e-8));
    // Monotone loading: the work is the integral of sigma_y (24a) up to eps_p.
    CHECK(s.plastic_work == doctest::Approx(law.integral(0.0, s.equivalent_plastic_strain)).epsilon(1e-12));
  }
}

TEST_CASE("voce in J2: uniaxial strain, q = sigma_y(eps_p) at e = sigma_y / (2 mu) + 3/2 eps_p, also in one step") {
  // F = diag(exp(e), 1, 1): q = 2 mu (e - 3/2 eps_p), mean stress K e, whatever the step.
  const rkpm::material::j2_plasticity<h::voce> j2(copper, law);
  for (const bool one_step : {false, true}) {
    CAPTURE(one_step);
    auto s = j2.initial_state();
    for (double p : {0.002, 0.02, 0.1, 0.4, 1.0}) {
      CAPTURE(p);
      const double e = law.flow_stress(p) / (2.0 * mu) + 1.5 * p;
      if (one_step) s = j2.initial_state();
      const mat3 tau = j2.kirchhoff_stress(diagonal(std::exp(e), 1.0, 1.0), s);
      CHECK(s.equivalent_plastic_strain == doctest::Approx(p).epsilon(1e-11));
      CHECK(von_mises(tau) == doctest::Approx(law.flow_stress(p)).epsilon(1e-11));
      CHECK(tau.trace() / 3.0 == doctest::Approx(K * e).epsilon(1e-12));
      CHECK(tau(1, 1) == doctest::Approx(tau(2, 2)).epsilon(1e-12));
    }
  }
}

TEST_CASE("voce in J2: simple shear in its small-strain limit, tau12 = sigma_y(eps_p) / sqrt(3)") {
  // For g << 1: g = tau12 / mu + sqrt(3) eps_p with sqrt(3) tau12 = sigma_y(eps_p); eps_p from
  // sqrt(3) mu (g - sqrt(3) eps_p) = sigma_y(eps_p) by bisection. Finite-strain terms are O(g).
  const h::voce soft{20e6, 30e6, 500.0, 1e9};
  const rkpm::material::j2_plasticity<h::voce> j2(copper, soft);
  const double g = 1e-3;
  const double p = root([&](double x) { return soft.flow_stress(x) - std::sqrt(3.0) * mu * (g - std::sqrt(3.0) * x); },
                        0.0, g);
  REQUIRE(p > 1e-4);  // the shear yields, well into the exponential part (b eps_p ~ 0.25)
  auto s = j2.initial_state();
  mat3 tau;
  for (int i = 1; i <= 200; ++i) {
    mat3 F = mat3::Identity();
    F(0, 1) = g * i / 200.0;
    tau = j2.kirchhoff_stress(F, s);
  }
  CHECK(s.equivalent_plastic_strain == doctest::Approx(p).epsilon(2e-3));
  CHECK(tau(0, 1) == doctest::Approx(soft.flow_stress(p) / std::sqrt(3.0)).epsilon(2e-3));
  CHECK(von_mises(tau) == doctest::Approx(soft.flow_stress(s.equivalent_plastic_strain)).epsilon(1e-10));
}

TEST_CASE("voce is a Hardening of the list and makes a typed configuration") {
  static_assert(rkpm::Hardening<h::voce>);
  static_assert(rkpm::Material<rkpm::material::j2_plasticity<h::voce>>);
  using method = rkpm::config<>::with_material<rkpm::material::j2_plasticity<h::voce>>;
  CHECK(method::name() == "cubic-linear-q2-plane_strain-j2+voce-none");
  bool listed = false;
  boost::hana::for_each(h::laws, [&](auto t) { listed = listed || std::is_same_v<typename decltype(t)::type, h::voce>; });
  CHECK(listed);
}

}  // namespace test_unit_material_voce
