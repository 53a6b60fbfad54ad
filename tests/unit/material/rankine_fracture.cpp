// material::rankine_fracture (docs/method.md section 4.7, (102)-(107)) against what is known
// without the code:
//   - uniaxial stress, F = diag(exp(e), exp(-nu e), exp(-nu e)): the Hencky effective stresses are
//     (E e, 0, 0), so the law is the 1D bilinear curve: E e up to sigma_t at eps0, the line
//     sigma_t (eps_f - e) / (eps_f - eps0) down to 0 at eps_f, 0 after;
//   - the dissipation: G_c / h after failure, and along any uniaxial path the work of the stress
//     (trapezoidal rule) minus the stored energy tau e / 2 (the secant's); h and h/2 dissipate
//     G_c / h and 2 G_c / h per unit volume, G_c per unit crack area both;
//   - unloading and reloading on the secant (1 - D) E with no dissipation; after failure
//     compression with the undamaged modulus and no tension;
//   - the crack normal of a tension rotated by 30 degrees; bad constants and snap-back refused.
// Every update's stress is also checked against current_kirchhoff_stress (the same bits).
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <rkpm/concepts/material.hpp>
#include <rkpm/core/bitwise.hpp>
#include <rkpm/material/elastic.hpp>
#include <rkpm/kernel/cubic_spline.hpp>
#include <rkpm/kernel/quartic_spline.hpp>
#include <rkpm/material/rankine_fracture.hpp>

#include "support/error_message.hpp"

namespace test_unit_material_rankine_fracture {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using rkpm::mat3;
using rkpm::material::elastic_constants;
using rkpm::material::rankine_fracture;

static_assert(rkpm::Material<rankine_fracture>);
static_assert(rkpm::bitwise_value<rankine_fracture::state_type>);

namespace {

// A PMMA-like brittle polymer: strains of a few percent, so that the log strains of exp(e) are
// exact to well below the 1e-12 the stresses are checked to.
const elastic_constants pmma{3.0e9, 0.35, 1180.0};
const double E = 3.0e9, nu = 0.35;
const double sigma_t = 70e6;  // Pa
const double G_c = 500.0;     // J/m^2
const double h = 0.25e-3;     // m
const double eps0 = sigma_t / E;

double failure_strain(double band) { return 2.0 * G_c / (sigma_t * band); }

mat3 uniaxial(double e) {
  mat3 F = mat3::Zero();
  F(0, 0) = std::exp(e);
  F(1, 1) = F(2, 2) = std::exp(-nu * e);
  return F;
}

mat3 rotation(double angle) {
  mat3 R = mat3::Identity();
  R(0, 0) = R(1, 1) = std::cos(angle);
  R(0, 1) = -std::sin(angle);
  R(1, 0) = std::sin(angle);
  return R;
}

// One material point driven through F's, checking each stress against current_kirchhoff_stress.
struct point {
  rankine_fracture law;
  rankine_fracture::state_type s = law.initial_state();
  bool same_bits = true;
  mat3 update(const mat3& F) {
    const mat3 tau = law.kirchhoff_stress(F, s);
    same_bits = same_bits && law.current_kirchhoff_stress(F, s) == tau;
    return tau;
  }
};

// The uniaxial path through `targets` (linear legs of `per_leg` steps each), with the stress
// work int tau11 de by the trapezoidal rule, checked at every step against the stored energy
// tau11 e / 2 plus the dissipation; returns the largest misfit over the path.
struct uniaxial_run {
  double work = 0.0, largest_misfit = 0.0;
  std::vector<double> e, tau11;
};
uniaxial_run drive(point& p, const std::vector<double>& targets, int per_leg) {
  uniaxial_run run;
  double e = 0.0, tau = 0.0;
  for (const double target : targets) {
    const double start = e;
    for (int k = 1; k <= per_leg; ++k) {
      const double next = start + (target - start) * k / per_leg;
      const double next_tau = p.update(uniaxial(next))(0, 0);
      run.work += 0.5 * (tau + next_tau) * (next - e);
      e = next;
      tau = next_tau;
      run.e.push_back(e);
      run.tau11.push_back(tau);
      run.largest_misfit = std::max(run.largest_misfit, std::abs(run.work - 0.5 * tau * e - p.s.fracture_work));
    }
  }
  return run;
}

}  // namespace

TEST_CASE("rankine: uniaxial stress follows E e, then the softening line to 0 at eps_f") {
  point p{rankine_fracture(pmma, sigma_t, G_c, h)};
  const double eps_f = failure_strain(h);
  REQUIRE(p.law.damage_onset_strain() == doctest::Approx(eps0).epsilon(1e-15));
  REQUIRE(p.law.failure_strain() == doctest::Approx(eps_f).epsilon(1e-15));
  // Up to eps0 exactly, then on to 1.5 eps_f.
  const int n = 400;
  double peak = 0.0;
  for (int k = 1; k <= 2 * n; ++k) {
    const double e = k <= n ? eps0 * k / n : eps0 + (1.5 * eps_f - eps0) * (k - n) / n;
    const mat3 tau = p.update(uniaxial(e));
    peak = std::max(peak, tau(0, 0));
    // The lateral stresses vanish for Hencky on this path, whole or degraded.
    CHECK(std::abs(tau(1, 1)) < 1e-12 * sigma_t);
    CHECK(std::abs(tau(2, 2)) < 1e-12 * sigma_t);
    CHECK(std::abs(tau(0, 1)) < 1e-12 * sigma_t);
    if (e <= eps0) {
      // To the stress scale sigma_t: ln(exp(e)^2) / 2 is e to 1e-16 absolute, not relative.
      CHECK(std::abs(tau(0, 0) - E * e) < 1e-12 * sigma_t);
      // At e = eps0 itself kappa may pass eps0 by a rounding.
      if (k < n) {
        CHECK(p.s.damage == 0.0);
        CHECK(p.s.fracture_work == 0.0);
        CHECK(p.s.crack_normal.norm() == 0.0);
      } else {
        CHECK(p.s.damage < 1e-12);
        CHECK(p.s.fracture_work < 1e-12 * G_c / h);
      }
    } else if (e < eps_f) {
      CHECK(std::abs(tau(0, 0) - sigma_t * (eps_f - e) / (eps_f - eps0)) < 1e-12 * sigma_t);
      CHECK(p.s.damage == doctest::Approx(1.0 - (eps0 / e) * (eps_f - e) / (eps_f - eps0)).epsilon(1e-12));
      CHECK_FALSE(p.s.failed());
    } else {
      CHECK(std::abs(tau(0, 0)) < 1e-12 * sigma_t);
      CHECK(p.s.failed());
    }
    CHECK(p.s.equivalent_plastic_strain == 0.0);
  }
  // The peak: the path passes e = eps0.
  CHECK(std::abs(peak - sigma_t) < 1e-12 * sigma_t);
  CHECK(p.same_bits);
}

TEST_CASE("rankine: the dissipation is G_c / h, and the work of the stress minus the stored energy") {
  const double eps_f = failure_strain(h);
  point p{rankine_fracture(pmma, sigma_t, G_c, h)};
  const uniaxial_run run = drive(p, {1.2 * eps_f}, 20000);
  CHECK(p.s.fracture_work == doctest::Approx(G_c / h).epsilon(1e-14));
  CHECK(p.s.plastic_work == p.s.fracture_work);
  CHECK(run.work == doctest::Approx(G_c / h).epsilon(1e-4));
  CHECK(run.largest_misfit < 1e-4 * G_c / h);
  // Unloading, compression and reloading on the way: the same ledger at every step.
  point q{rankine_fracture(pmma, sigma_t, G_c, h)};
  const double e1 = eps0 + 0.4 * (eps_f - eps0), e2 = eps0 + 0.7 * (eps_f - eps0);
  const uniaxial_run cycled = drive(q, {e1, -0.5 * eps0, e1, e2, 0.0, 1.2 * eps_f}, 4000);
  CHECK(q.s.fracture_work == doctest::Approx(G_c / h).epsilon(1e-14));
  CHECK(cycled.largest_misfit < 1e-4 * G_c / h);
  CHECK(p.same_bits);
  CHECK(q.same_bits);
}

TEST_CASE("rankine: h and h/2 dissipate G_c per unit crack area both") {
  double per_area[2];
  for (int i = 0; i < 2; ++i) {
    const double band = i == 0 ? h : h / 2;
    point p{rankine_fracture(pmma, sigma_t, G_c, band)};
    const uniaxial_run run = drive(p, {1.2 * failure_strain(band)}, 20000);
    CHECK(run.largest_misfit < 1e-4 * G_c / band);
    CHECK(run.work * band == doctest::Approx(G_c).epsilon(1e-4));
    per_area[i] = p.s.fracture_work * band;
    if (i == 1) CHECK(p.s.fracture_work == doctest::Approx(2.0 * G_c / h).epsilon(1e-14));
  }
  CHECK(per_area[0] == doctest::Approx(G_c).epsilon(1e-14));
  CHECK(per_area[1] == doctest::Approx(G_c).epsilon(1e-14));
}

TEST_CASE("rankine: unloading and reloading follow the secant (1 - D) E with no dissipation") {
  const double eps_f = failure_strain(h);
  point p{rankine_fracture(pmma, sigma_t, G_c, h)};
  const double e1 = eps0 + 0.5 * (eps_f - eps0);
  drive(p, {e1}, 500);
  const double D = p.s.damage, W = p.s.fracture_work, kappa = p.s.kappa;
  const double peak = sigma_t * (eps_f - e1) / (eps_f - eps0);
  REQUIRE(D > 0.0);
  REQUIRE(D < 1.0);
  for (const double e : {0.8 * e1, 0.5 * e1, 0.1 * e1, 1e-6, 0.3 * e1, 0.9 * e1, e1}) {
    const double tau = p.update(uniaxial(e))(0, 0);
    CHECK(std::abs(tau - (1.0 - D) * E * e) < 1e-12 * sigma_t);
    CHECK(p.s.damage == D);
    CHECK(p.s.fracture_work == W);
    CHECK(p.s.kappa == kappa);
  }
  // Back at e1: the stress it left.
  CHECK(std::abs(p.update(uniaxial(e1))(0, 0) - peak) < 1e-12 * sigma_t);
  // Compression with damage: the undamaged modulus (the crack closes).
  CHECK(std::abs(p.update(uniaxial(-0.5 * eps0))(0, 0) + 0.5 * sigma_t) < 1e-12 * sigma_t);
  CHECK(p.s.damage == D);
  CHECK(p.same_bits);
}

TEST_CASE("rankine: a broken point carries compression with the undamaged modulus and no tension") {
  point p{rankine_fracture(pmma, sigma_t, G_c, h)};
  drive(p, {1.2 * failure_strain(h)}, 500);
  REQUIRE(p.s.failed());
  const double W = p.s.fracture_work;
  for (const double e : {-1e-3, -1e-2}) {
    const mat3 tau = p.update(uniaxial(e));
    CHECK(tau(0, 0) == doctest::Approx(-E * std::abs(e)).epsilon(1e-12));
    CHECK(std::abs(tau(1, 1)) < 1e-12 * sigma_t);
  }
  for (const double e : {1e-3, 1e-2}) CHECK(p.update(uniaxial(e)).norm() < 1e-12 * sigma_t);
  // Pure shear of principal stretches exp(+-g) along 20 degrees: the tensile principal stress is
  // gone, the compressive one -2 mu g stays, in its direction.
  const double g = 0.01, mu = E / (2.0 * (1.0 + nu)), angle = 20.0 * std::numbers::pi / 180.0;
  mat3 stretch = mat3::Identity();
  stretch(0, 0) = std::exp(g);
  stretch(1, 1) = std::exp(-g);
  const mat3 R = rotation(angle);
  const mat3 tau = p.update(R * stretch * R.transpose());
  mat3 expected = mat3::Zero();
  expected(1, 1) = -2.0 * mu * g;
  CHECK((tau - R * expected * R.transpose()).norm() < 1e-12 * 2.0 * mu * g);
  // Hydrostatic compression: the elastic law's stress.
  const mat3 squeeze = 0.99 * mat3::Identity();
  auto es = rkpm::material::elastic(pmma).initial_state();
  CHECK((p.update(squeeze) - rkpm::material::elastic(pmma).kirchhoff_stress(squeeze, es)).norm() <
        1e-12 * sigma_t);
  CHECK(p.s.fracture_work == W);
  CHECK(p.same_bits);
}

TEST_CASE("rankine: the crack normal is the direction of the tension that opened it") {
  const double eps_f = failure_strain(h);
  const double angle = 30.0 * std::numbers::pi / 180.0;
  const mat3 R = rotation(angle);
  point p{rankine_fracture(pmma, sigma_t, G_c, h)};
  for (int k = 1; k <= 100; ++k) {
    const double e = 0.5 * (eps0 + eps_f) * k / 100;
    const mat3 tau = p.update(R * uniaxial(e) * R.transpose());
    // The rotated uniaxial stress (objectivity).
    CHECK((tau - R * p.law.current_kirchhoff_stress(uniaxial(e), p.s) * R.transpose()).norm() < 1e-12 * sigma_t);
    if (e <= eps0) CHECK(p.s.crack_normal.norm() == 0.0);
  }
  REQUIRE(p.s.damage > 0.0);
  const rkpm::vec2 direction(std::cos(angle), std::sin(angle));
  CHECK(p.s.crack_normal.norm() == doctest::Approx(1.0).epsilon(1e-14));
  CHECK(std::abs(p.s.crack_normal.dot(direction)) == doctest::Approx(1.0).epsilon(1e-12));
  // A later tension along another direction grows the same crack: the normal stays.
  const rkpm::vec2 first = p.s.crack_normal;
  const double D = p.s.damage;
  const mat3 across = rotation(angle + std::numbers::pi / 2);
  p.update(across * uniaxial(0.8 * eps_f) * across.transpose());
  CHECK(p.s.damage > D);
  CHECK(p.s.crack_normal == first);
  CHECK(p.same_bits);
}

TEST_CASE("rankine: bad constants and a band too wide for the fracture energy are refused") {
  using rkpm::test::contains;
  using rkpm::test::error_message;
  for (const double bad : {0.0, -1.0, std::nan("")}) {
    const std::string strength = error_message([&] { rankine_fracture(pmma, bad, G_c, h); });
    CHECK(contains(strength, "tensile_strength"));
    CHECK(contains(strength, "Pa is invalid"));
    const std::string energy = error_message([&] { rankine_fracture(pmma, sigma_t, bad, h); });
    CHECK(contains(energy, "fracture_energy"));
    CHECK(contains(energy, "J/m^2 is invalid"));
    const std::string band = error_message([&] { rankine_fracture(pmma, sigma_t, G_c, bad); });
    CHECK(contains(band, "band_width"));
    CHECK(contains(band, "m is invalid"));
    CHECK(contains(band, "band_width_of_support"));
  }
  // 2 G_c E / sigma_t^2 = 6.12e-4 m: a band of 1 mm snaps back; one just below it is accepted.
  const double widest = 2.0 * G_c * E / (sigma_t * sigma_t);
  const std::string snap = error_message([&] { rankine_fracture(pmma, sigma_t, G_c, 1e-3); });
  CHECK(contains(snap, "band_width h = 0.001 m"));
  CHECK(contains(snap, "2 G_c E / sigma_t^2"));
  CHECK(contains(snap, fmt::format("{} m", widest)));
  CHECK(contains(snap, "snaps back"));
  CHECK(contains(snap, "finer particles"));
  CHECK(contains(snap, "smaller band width"));
  CHECK(error_message([&] { rankine_fracture(pmma, sigma_t, G_c, 0.999 * widest); }).empty());
  CHECK(rankine_fracture(pmma, sigma_t, G_c, h).largest_band_width() == doctest::Approx(widest).epsilon(1e-15));
  // The window's width at equal area (107): 3a/4 and 4a/5.
  CHECK(rankine_fracture::band_width_of_support<kernel::cubic_spline>(1.5e-3) == doctest::Approx(1.125e-3).epsilon(1e-12));
  CHECK(rankine_fracture::band_width_of_support<kernel::quartic_spline>(1.5e-3) == doctest::Approx(1.2e-3).epsilon(1e-12));
}

}  // namespace test_unit_material_rankine_fracture
