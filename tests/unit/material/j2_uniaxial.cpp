// J2 plasticity on coaxial paths (fixed principal axes), where the finite-strain model in log
// strains reduces exactly to 1D small-strain plasticity in (ln stretch, Kirchhoff stress) and the
// radial return is exact for any step size:
//   - uniaxial strain F = diag(exp(e), 1, 1), loading and reverse yielding, closed form;
//   - uniaxial stress (lateral stretches solved so tau22 = tau33 = 0), linear hardening closed
//     form and the power law against an RK4 integration of d sigma / d eps.
// Checked: stresses, eps_p, lateral stretch, consistency q = sigma_y(eps_p), plastic
// incompressibility det(b_e)^(1/2) = det F, plastic work = int sigma_y d eps_p.
#include <doctest/doctest.h>

#include <cmath>
#include <Eigen/LU>  // determinant

#include <rkpm/material/j2_plasticity.hpp>

#include "support/tensors.hpp"
#include "support/paper_materials.hpp"

namespace test_unit_material_j2_uniaxial {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using rkpm::mat3;
using rkpm::material::elastic_constants;
using rkpm::material::j2_plasticity;
namespace h = rkpm::material::hardening;

namespace {

using rkpm::test::diagonal;
using rkpm::test::von_mises;

using namespace rkpm::test::paper_materials;
const double E = 117e9, nu = 0.35;
const double mu = copper_mu, K = copper_K;

// Uniaxial stress step: F = diag(exp(e11), l, l) with l such that tau22 = 0 (secant on ln l).
// Advances `state` and returns tau; `lateral` carries the guess in and the solution out.
template <class Law>
mat3 uniaxial_stress_step(const Law& law, typename Law::state_type& state, double e11,
                          double& lateral, double stress_scale) {
  const auto trial = [&](double x, typename Law::state_type& s) {
    return law.kirchhoff_stress(diagonal(std::exp(e11), std::exp(x), std::exp(x)), s);
  };
  const auto residual = [&](double x) {
    auto s = state;
    return trial(x, s)(1, 1);
  };
  double x0 = std::log(lateral), x1 = x0 - 1e-4;
  double r0 = residual(x0), r1 = residual(x1);
  for (int it = 0; it < 60 && std::abs(r1) > 1e-10 * stress_scale; ++it) {
    const double x2 = x1 - r1 * (x1 - x0) / (r1 - r0);
    x0 = x1;
    r0 = r1;
    x1 = x2;
    r1 = residual(x1);
  }
  REQUIRE(std::abs(r1) <= 1e-10 * stress_scale);
  lateral = std::exp(x1);
  return trial(x1, state);
}

}  // namespace

TEST_CASE("uniaxial strain, linear hardening: loading and reverse yielding in closed form") {
  // Log strain e along x, none across. With the signed plastic strain p (plastic log strain
  // tensor p (1, -1/2, -1/2)) and accumulated eps_p: q = 2 mu |e - 1.5 p|, mean stress K e,
  // tau11 = K e + 4/3 mu (e - 1.5 p), tau22 = tau33 = K e - 2/3 mu (e - 1.5 p).
  const double s0 = 400e6, H = 100e6;
  const double e_max = 0.2, e_min = -0.1;
  const double p1 = (2 * mu * e_max - s0) / (3 * mu + H);  // after loading to e_max
  const auto exact = [&](double e, bool unloading, double& p, double& eps_p) {
    if (!unloading) {
      p = eps_p = std::max(0.0, (2 * mu * e - s0) / (3 * mu + H));
    } else {
      // Reverse yield once 2 mu (1.5 p1 - e) exceeds s0 + H p1; then p = p1 - d, eps_p = p1 + d.
      const double d = std::max(0.0, (2 * mu * (1.5 * p1 - e) - s0 - H * p1) / (3 * mu + H));
      p = p1 - d;
      eps_p = p1 + d;
    }
  };

  const j2_plasticity<h::linear> law(copper, copper_hardening);
  auto state = law.initial_state();
  int plastic_steps = 0, reverse_plastic_steps = 0;
  const int n_load = 40, n_unload = 30;
  for (int step = 1; step <= n_load + n_unload; ++step) {
    const bool unloading = step > n_load;
    const double e = unloading ? e_max + (e_min - e_max) * (step - n_load) / n_unload
                               : e_max * step / n_load;
    const double eps_p_before = state.equivalent_plastic_strain;
    const mat3 tau = law.kirchhoff_stress(diagonal(std::exp(e), 1.0, 1.0), state);
    double p = 0, eps_p = 0;
    exact(e, unloading, p, eps_p);
    CAPTURE(step);
    CAPTURE(e);
    const double scale = K * std::abs(e) + s0;
    CHECK(std::abs(tau(0, 0) - (K * e + 4.0 / 3.0 * mu * (e - 1.5 * p))) < 1e-11 * scale);
    CHECK(std::abs(tau(1, 1) - (K * e - 2.0 / 3.0 * mu * (e - 1.5 * p))) < 1e-11 * scale);
    CHECK(std::abs(tau(2, 2) - tau(1, 1)) < 1e-11 * scale);
    CHECK(std::abs(tau(0, 1)) < 1e-11 * scale);
    CHECK(state.equivalent_plastic_strain == doctest::Approx(eps_p).epsilon(1e-11).scale(1e-3));
    if (state.equivalent_plastic_strain > eps_p_before) {
      ++(unloading ? reverse_plastic_steps : plastic_steps);
      CHECK(von_mises(tau) ==
            doctest::Approx(copper_hardening.flow_stress(state.equivalent_plastic_strain))
                .epsilon(1e-10));
    } else {
      CHECK(von_mises(tau) <= copper_hardening.flow_stress(state.equivalent_plastic_strain));
    }
    // Plastic work = int sigma_y d eps_p = s0 eps_p + H eps_p^2 / 2 (monotone eps_p).
    const double ep = state.equivalent_plastic_strain;
    CHECK(state.plastic_work == doctest::Approx(s0 * ep + 0.5 * H * ep * ep).epsilon(1e-11));
    // Plastic incompressibility: det b_e = J^2 = exp(2 e).
    CHECK(state.elastic_left_cauchy_green.full().determinant() ==
          doctest::Approx(std::exp(2 * e)).epsilon(1e-13));
  }
  CHECK(plastic_steps > 30);
  CHECK(reverse_plastic_steps > 10);
}

TEST_CASE("uniaxial stress, linear hardening: sigma = s0 + E_t (eps - s0 / E) in log strain") {
  const double s0 = 400e6, H = 100e6;
  const double Et = E * H / (E + H);
  const j2_plasticity<h::linear> law(copper, copper_hardening);
  auto state = law.initial_state();
  double lateral = 1.0;
  int plastic_steps = 0;
  for (int step = 1; step <= 30; ++step) {
    const double eps = 0.3 * step / 30.0;  // log strain along x, 0.01 per step
    const double eps_p_before = state.equivalent_plastic_strain;
    const mat3 tau = uniaxial_stress_step(law, state, eps, lateral, s0);
    const double sigma = eps <= s0 / E ? E * eps : s0 + Et * (eps - s0 / E);
    const double eps_p = std::max(0.0, (sigma - s0) / H);
    CAPTURE(eps);
    CHECK(tau(0, 0) == doctest::Approx(sigma).epsilon(1e-10));
    CHECK(std::abs(tau(2, 2)) < 1e-9 * s0);
    CHECK(state.equivalent_plastic_strain == doctest::Approx(eps_p).epsilon(1e-9).scale(1e-3));
    // Lateral log strain: elastic -nu sigma / E plus the incompressible plastic part -eps_p / 2.
    CHECK(std::log(lateral) == doctest::Approx(-nu * sigma / E - 0.5 * eps_p).epsilon(1e-9));
    // Elastic volume change only: ln J = tr(eps_e) = sigma / (3 K), and det(b_e)^(1/2) = J.
    const double J = std::exp(eps) * lateral * lateral;
    CHECK(std::log(J) == doctest::Approx(sigma / (3 * K)).epsilon(1e-8));
    CHECK(std::sqrt(state.elastic_left_cauchy_green.full().determinant()) ==
          doctest::Approx(J).epsilon(1e-13));
    if (state.equivalent_plastic_strain > eps_p_before) {
      ++plastic_steps;
      CHECK(von_mises(tau) ==
            doctest::Approx(copper_hardening.flow_stress(state.equivalent_plastic_strain))
                .epsilon(1e-10));
    }
    CHECK(state.plastic_work ==
          doctest::Approx(s0 * eps_p + 0.5 * H * eps_p * eps_p).epsilon(1e-8).scale(1.0));
  }
  CHECK(plastic_steps == 30);  // yield strain 400 / 117000 < 0.01: the first step yields
}

TEST_CASE("uniaxial stress, power law: against RK4 of d sigma / d eps = E H / (E + H)") {
  const double Ea = 71e9;
  const auto& law_h = wheel_hardening;
  // Independent 1D integration: on the yield surface sigma = sigma_y(eps_p), so
  // eps_p(sigma) = (sigma / K)^(1/n) - eps0 and H(sigma) = n K^(1/n) sigma^(1 - 1/n).
  const auto rate = [&](double sigma) {
    const double eps_p = std::pow(sigma / law_h.coefficient, 1.0 / law_h.exponent) - law_h.offset;
    const double H = law_h.slope(std::max(eps_p, 0.0));
    return Ea * H / (Ea + H);
  };
  const double sigma_y0 = law_h.flow_stress(0.0);
  const double eps_y = sigma_y0 / Ea;
  const auto rk4_sigma = [&](double eps_end) {
    const int n = 20000;
    const double step = (eps_end - eps_y) / n;
    double sigma = sigma_y0;
    for (int i = 0; i < n; ++i) {
      const double k1 = rate(sigma), k2 = rate(sigma + 0.5 * step * k1),
                   k3 = rate(sigma + 0.5 * step * k2), k4 = rate(sigma + step * k3);
      sigma += step / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    return sigma;
  };

  const j2_plasticity<h::power_law> law(aluminium, wheel_hardening);
  auto state = law.initial_state();
  double lateral = 1.0;
  const int n_steps = 50;
  for (int step = 1; step <= n_steps; ++step) {
    const double eps = 0.5 * step / n_steps;
    const mat3 tau = uniaxial_stress_step(law, state, eps, lateral, sigma_y0);
    if (step % 10 == 0) {
      CAPTURE(eps);
      const double sigma = rk4_sigma(eps);
      CHECK(tau(0, 0) == doctest::Approx(sigma).epsilon(1e-9));
      const double eps_p = eps - sigma / Ea;  // additive split of the 1D log strain
      CHECK(state.equivalent_plastic_strain == doctest::Approx(eps_p).epsilon(1e-8));
      CHECK(state.plastic_work ==
            doctest::Approx(law_h.integral(0.0, eps_p)).epsilon(1e-8));
    }
    CHECK(von_mises(tau) ==
          doctest::Approx(law_h.flow_stress(state.equivalent_plastic_strain)).epsilon(1e-10));
  }
}

TEST_CASE("power law, one large uniaxial-strain step: the local Newton converges") {
  // 2 mu (e - 1.5 eps_p) = sigma_y(eps_p), solved here by bisection.
  const double mu_a = 71e9 / 2.6;
  const double e = 0.4;
  double lo = 0.0, hi = e / 1.5;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (2 * mu_a * (e - 1.5 * mid) > wheel_hardening.flow_stress(mid) ? lo : hi) = mid;
  }
  const double eps_p = 0.5 * (lo + hi);
  for (const int n_steps : {1, 7, 100}) {
    const j2_plasticity<h::power_law> law(aluminium, wheel_hardening);
    auto state = law.initial_state();
    mat3 tau;
    for (int step = 1; step <= n_steps; ++step)
      tau = law.kirchhoff_stress(diagonal(std::exp(e * step / n_steps), 1.0, 1.0), state);
    CAPTURE(n_steps);
    CHECK(state.equivalent_plastic_strain == doctest::Approx(eps_p).epsilon(1e-12));
    CHECK(von_mises(tau) == doctest::Approx(wheel_hardening.flow_stress(eps_p)).epsilon(1e-11));
  }
}

}  // namespace test_unit_material_j2_uniaxial
