// Johnson-Cook damage (material::johnson_cook, docs/method.md (32b)-(32c)) away from uniaxial
// tension: one material point driven through deformation gradients at a constant equivalent
// strain rate (100/s, steps of 5e-4), its damage D and its plastic strain at failure against
//   D(eps_p) = int_0^eps_p de / eps_f(sigma*(e), rate*, T(e)),
//   eps_f = (D1 + D2 exp(D3 sigma*)) (1 + D4 ln max(rate*, 1)) (1 + D5 T*),
//   sigma* = mean stress / von Mises stress (positive in tension), the flow stress at e,
// written out and integrated here (RK4 in e, with the adiabatic temperature dT/de = beta
// sigma_y / (rho c_p) alongside when the point heats), on four paths:
//   - simple shear (J = 1: sigma* = 0, eps_f = (D1 + D2) (1 + D4 ln rate*));
//   - uniaxial compression (sigma* = -1/3: exp(D3 sigma*) > 1 with D3 < 0);
//   - heated (the D5 term): pure shear at 800 K without heating, and from 600 K heated by its
//     plastic work (83 K by failure);
//   - a path whose triaxiality changes: pure shear, then under a superposed mean tension, shear
//     again, then under a mean pressure (the volume change is elastic and apart from the deviator
//     in the Hencky model, so sigma* = K ln J / q follows J at once, with no transient of the
//     deviator).
// Each path is checked twice: D after every step against D(eps_p), and the step that fails the
// point against the strain where the integral reaches 1.
// The tolerance on D, from the step: the code adds dgamma / eps_f per step (32b), with sigma* at
// the step's end, T at its start and the step's own plastic rate; the integral differs from that
// sum by
//   - the change of 1/eps_f across each step (the sum is a Riemann sum): at most the sum over the
//     steps of de |d(1/eps_f)|, which the integral adds up along the point's steps (0 on the
//     isothermal paths of constant sigma*, 3e-5 heated, 3e-4 on the changing path, where
//     sigma* = p / q falls from 0.77 while q rises at the start of the tension);
//   - the rate: the plastic rate falls short of the applied one by the elastic strain's rate,
//     h / (3 mu) of it (h the hardening slope), which lowers eps_f by D4 and sigma*'s q by C times
//     that fraction: about (D4 + C |D3 sigma*|) (q - A) / (3 mu eps_f) of D, 3.4e-5 in shear (as
//     measured) and below 1e-4 on every path;
//   - the temperature one step late: beta sigma_y de / (rho c_p) = 0.05 K, D5 dT / ((T_m - T_r)
//     (1 + D5 T*)) < 5e-5 of D;
// so |D - D(eps_p)| <= (the Riemann bound) + 1e-4 along each path; a wrong sign of sigma*, a lost
// D4 or D5 term or the wrong flow stress in sigma* miss by percents. The strain at failure: the
// point had not failed at the start of the step that failed it and failed within that step's
// plastic strain (at most its equivalent strain, 5e-4), each to the tolerance on D times eps_f.
// The damage constants have Johnson & Cook's form with D3 < 0 (tension the more damaging) and a
// ductility chosen so that every path fails by eps_p = 1.5, within 3,000 steps: eps_f = 0.43 at
// sigma* = 1/2, 0.85 in shear, 1.37 at -1/3, before the rate and temperature factors.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <rkpm/material/johnson_cook.hpp>

#include "support/tensors.hpp"

namespace test_unit_material_johnson_cook_damage {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using rkpm::mat3;
namespace h = rkpm::material::hardening;
namespace mat = rkpm::material;

namespace {

using rkpm::test::diagonal;
using rkpm::test::von_mises;

// OFHC copper's flow stress (Johnson & Cook 1983): A, B, n, C, reference rate, m, room and melt.
const h::johnson_cook copper_flow{90e6, 292e6, 0.31, 0.025, 1.0, 1.09, 294.0, 1356.0};
const mat::elastic_constants copper{124e9, 0.34, 8960.0};
const double specific_heat = 383.0, rho_c = 8960.0 * specific_heat;  // J/(kg K), J/(m^3 K)
const mat::johnson_cook_damage ductility{0.05, 0.8, -1.5, 0.014, 1.12};

const double rate = 100.0;        // 1/s: the equivalent strain rate of every path (rate* = 100)
const double strain_step = 5e-4;  // the equivalent strain of a step
const double dt = strain_step / rate;
const double rate_and_lag = 1e-4;  // on D, besides the Riemann sum's bound (the top of the file)

// (32c) and (24b) written out here, not the law's code.
double homologous(double T) {
  const auto& l = copper_flow;
  return std::clamp((T - l.room_temperature) / (l.melt_temperature - l.room_temperature), 0.0, 1.0);
}
double failure_strain(double triaxiality, double T) {
  const auto& d = ductility;
  const double log_rate = std::log(std::max(rate / copper_flow.reference_rate, 1.0));
  return (d.D1 + d.D2 * std::exp(d.D3 * triaxiality)) * (1.0 + d.D4 * log_rate) * (1.0 + d.D5 * homologous(T));
}
double flow_stress(double e, double T) {
  const auto& l = copper_flow;
  return (l.A + l.B * std::pow(e, l.n)) * (1.0 + l.C * std::log(std::max(rate / l.reference_rate, 1.0))) *
         (1.0 - std::pow(homologous(T), l.m));
}

// The damage integral and the adiabatic temperature as functions of eps_p, advanced by RK4 in
// steps of 1e-5 to increasing eps_p; triaxiality(q) gives sigma* at the flow stress q.
struct damage_integral {
  double beta;  // Taylor-Quinney fraction (0: isothermal)
  double T;     // K, at e
  double e = 0.0, D = 0.0;
  double crossing = -1.0;  // where D reached 1 (-1: not yet)
  // sum over the advances of (e_end - e_start) |1/eps_f(e_end) - 1/eps_f(e_start)|: how far a
  // sum of de / eps_f taken at either end of each advance can be from the integral (1/eps_f is
  // monotone along an advance).
  double riemann_bound = 0.0;

  template <class Triaxiality>
  void advance_to(double target, Triaxiality triaxiality) {
    const auto slopes = [&](double ee, double TT) {
      const double q = flow_stress(ee, TT);
      return std::pair{1.0 / failure_strain(triaxiality(q), TT), beta * q / rho_c};
    };
    if (e < target) {
      const double e_start = e, f_start = slopes(e, T).first;
      advance(target, slopes);
      riemann_bound += (e - e_start) * std::abs(slopes(e, T).first - f_start);
    }
  }
  template <class Slopes>
  void advance(double target, Slopes slopes) {
    while (e < target) {
      const double hh = std::min(1e-5, target - e);
      const auto [d1, t1] = slopes(e, T);
      const auto [d2, t2] = slopes(e + hh / 2, T + hh / 2 * t1);
      const auto [d3, t3] = slopes(e + hh / 2, T + hh / 2 * t2);
      const auto [d4, t4] = slopes(e + hh, T + hh * t3);
      const double D_start = D;
      D += hh / 6 * (d1 + 2 * d2 + 2 * d3 + d4);
      T += hh / 6 * (t1 + 2 * t2 + 2 * t3 + t4);
      if (D_start < 1.0 && D >= 1.0) crossing = e + hh * (1.0 - D_start) / (D - D_start);
      e += hh;
    }
  }
  // Where the integral reaches (or reached) 1, continued from here at the triaxiality law given.
  template <class Triaxiality>
  double failure(Triaxiality triaxiality) const {
    damage_integral ahead = *this;
    while (ahead.crossing < 0.0) ahead.advance_to(ahead.e + 1e-3, triaxiality);
    return ahead.crossing;
  }
};

// What a path records: the largest |D - D(eps_p)| before failure, the step that failed the point
// (eps_p at its start and end) and where the integral reaches 1 in it.
struct path_record {
  double worst_damage = 0.0;
  double eps_p_before = -1.0, eps_p_after = -1.0, integral_failure = -1.0;
  double temperature = 0.0, integral_temperature = 0.0;  // at failure
  double worst_triaxiality = 0.0;                       // |sigma* of the stress returned - the path's|
  double riemann_bound = 0.0;                           // the integral's, over the code's steps
  int steps = 0;
};

// Steps the point until it fails: step(k, s) advances s to the path's k-th deformation gradient
// and returns the Kirchhoff stress; triaxiality_of_step(k, q) is the path's sigma* in step k at
// the flow stress q.
template <class Step, class Triaxiality>
path_record drive(const mat::johnson_cook& jc, double beta, Step step, Triaxiality triaxiality_of_step) {
  auto s = jc.initial_state();
  damage_integral integral{beta, s.temperature};
  path_record r;
  for (int k = 1; k <= 4000; ++k) {
    const auto triaxiality = [&](double q) { return triaxiality_of_step(k, q); };
    const double before = s.equivalent_plastic_strain;
    const mat3 tau = step(k, s);
    r.steps = k;
    if (s.failed()) {
      r.eps_p_before = before;
      r.eps_p_after = s.equivalent_plastic_strain;
      r.integral_failure = integral.failure(triaxiality);
      r.temperature = s.temperature;
      integral.advance_to(r.eps_p_after, triaxiality);
      r.integral_temperature = integral.T;
      break;
    }
    integral.advance_to(s.equivalent_plastic_strain, triaxiality);
    r.riemann_bound = integral.riemann_bound;
    r.worst_damage = std::max(r.worst_damage, std::abs(s.damage - integral.D));
    if (s.equivalent_plastic_strain > 0.0) {
      const double q = von_mises(tau);
      r.worst_triaxiality = std::max(r.worst_triaxiality, std::abs(tau.trace() / 3.0 / q - triaxiality(q)));
    }
  }
  MESSAGE("failed after ", r.steps, " steps at eps_p ", r.eps_p_before, " -> ", r.eps_p_after, " (the integral: ",
          r.integral_failure, "); T ", r.temperature, " K (the integral: ", r.integral_temperature,
          " K); largest |D - D(eps_p)| ", r.worst_damage, " (Riemann bound ", r.riemann_bound,
          "); largest triaxiality difference ", r.worst_triaxiality);
  return r;
}

void check(const path_record& r) {
  REQUIRE(r.eps_p_after > 0.0);  // failed
  const double tolerance = r.riemann_bound + rate_and_lag;
  CHECK(r.worst_damage <= tolerance);
  // The step that failed the point contains the strain where the integral reaches 1: the point
  // had not failed at the step's start, and failed within one step's plastic strain (at most the
  // step's equivalent strain; the integral's slope 1/eps_f turns the tolerance on D into one on
  // eps_p: eps_f < 3 here). Not the failing step's own eps_p as the upper end: the uniaxial
  // step's lateral solve goes through failed copies of the state there.
  CHECK(r.integral_failure >= r.eps_p_before - 3.0 * tolerance);
  CHECK(r.integral_failure <= r.eps_p_before + strain_step + 3.0 * tolerance);
}

// Pure shear in the x-y plane (deviatoric log strain (a, -a, 0), equivalent 2a / sqrt 3) at the
// equivalent strain rate `rate`, with the elastic volume change ln J = theta.
mat3 pure_shear(int k, double theta) {
  const double a = std::sqrt(3.0) / 2.0 * strain_step * k;
  return diagonal(std::exp(a + theta / 3.0), std::exp(-a + theta / 3.0), std::exp(theta / 3.0));
}

}  // namespace

TEST_CASE("johnson_cook damage in simple shear: sigma* = 0, the point fails at eps_p = (D1 + D2)(1 + D4 ln rate*)") {
  const mat::johnson_cook jc(copper, copper_flow, mat::johnson_cook_heating{specific_heat, 0.0}, ductility);
  const auto step = [&](int k, mat::johnson_cook_state& s) {
    mat3 F = mat3::Identity();
    F(0, 1) = std::sqrt(3.0) * strain_step * k;  // gamma' = sqrt 3 x the equivalent rate
    return jc.kirchhoff_stress(F, s, {dt, k * dt, s.temperature});
  };
  const path_record r = drive(jc, 0.0, step, [](int, double) { return 0.0; });
  check(r);
  const double eps_f = (0.05 + 0.8) * (1.0 + 0.014 * std::log(rate));
  CHECK(r.integral_failure == doctest::Approx(eps_f).epsilon(1e-9));  // the integral is eps_p / eps_f here
  CHECK(r.worst_triaxiality <= 1e-10);  // ln J = 0 to round-off
}

TEST_CASE("johnson_cook damage in uniaxial compression: sigma* = -1/3, eps_f = (D1 + D2 exp(-D3 / 3))(1 + D4 ln rate*)") {
  const mat::johnson_cook jc(copper, copper_flow, mat::johnson_cook_heating{specific_heat, 0.0}, ductility);
  // Uniaxial stress along x: the lateral log strain with tau22 = tau33 = 0 by the secant method
  // on copies of the state, then the state advances.
  double lateral = 0.0;
  const auto step = [&](int k, mat::johnson_cook_state& s) {
    const double axial = -strain_step * k;  // plastic flow is isochoric: the equivalent strain is |axial|
    const auto stress = [&](double x, mat::johnson_cook_state& state) {
      const mat3 F = diagonal(std::exp(axial), std::exp(x), std::exp(x));
      return jc.kirchhoff_stress(F, state, {dt, k * dt, s.temperature});
    };
    const auto lateral_stress = [&](double x) {
      auto trial = s;
      return stress(x, trial)(1, 1);
    };
    double x0 = lateral, x1 = x0 + 1e-6, r0 = lateral_stress(x0), r1 = lateral_stress(x1);
    for (int it = 0; it < 80 && std::abs(r1) > 1e-11 * copper_flow.A && r1 != r0; ++it) {
      const double x2 = x1 - r1 * (x1 - x0) / (r1 - r0);
      x0 = x1;
      r0 = r1;
      x1 = x2;
      r1 = lateral_stress(x1);
    }
    REQUIRE(std::abs(r1) <= 1e-9 * copper_flow.A);
    lateral = x1;
    return stress(x1, s);
  };
  const path_record r = drive(jc, 0.0, step, [](int, double) { return -1.0 / 3.0; });
  check(r);
  const double eps_f = (0.05 + 0.8 * std::exp(1.5 / 3.0)) * (1.0 + 0.014 * std::log(rate));
  CHECK(r.integral_failure == doctest::Approx(eps_f).epsilon(1e-9));
  CHECK(r.worst_triaxiality <= 1e-8);  // uniaxial indeed (the lateral stress to 1e-9 of A)
}

TEST_CASE("johnson_cook damage heated: the D5 term at 800 K, and along the adiabatic temperature from 600 K") {
  SUBCASE("800 K, no heating: eps_f = (D1 + D2)(1 + D4 ln rate*)(1 + D5 T*)") {
    const mat::johnson_cook jc(copper, copper_flow, mat::johnson_cook_heating{specific_heat, 0.0, 800.0}, ductility);
    const auto step = [&](int k, mat::johnson_cook_state& s) {
      return jc.kirchhoff_stress(pure_shear(k, 0.0), s, {dt, k * dt, s.temperature});
    };
    const path_record r = drive(jc, 0.0, step, [](int, double) { return 0.0; });
    check(r);
    const double eps_f = 0.85 * (1.0 + 0.014 * std::log(rate)) * (1.0 + 1.12 * (800.0 - 294.0) / (1356.0 - 294.0));
    CHECK(r.integral_failure == doctest::Approx(eps_f).epsilon(1e-9));
    CHECK(r.temperature == 800.0);
  }
  SUBCASE("from 600 K, heated by the plastic work (beta = 0.9)") {
    const mat::johnson_cook jc(copper, copper_flow, mat::johnson_cook_heating{specific_heat, 0.9, 600.0}, ductility);
    const auto step = [&](int k, mat::johnson_cook_state& s) {
      return jc.kirchhoff_stress(pure_shear(k, 0.0), s, {dt, k * dt, s.temperature});
    };
    const path_record r = drive(jc, 0.9, step, [](int, double) { return 0.0; });
    check(r);
    CHECK(r.temperature - 600.0 > 50.0);  // the heating matters: D5 dT / (T_m - T_r) > 5% of eps_f
    CHECK(r.temperature == doctest::Approx(r.integral_temperature).epsilon(1e-4));
  }
}

TEST_CASE("johnson_cook damage along a path whose triaxiality changes: shear, tension, shear, pressure") {
  const mat::johnson_cook jc(copper, copper_flow, mat::johnson_cook_heating{specific_heat, 0.0}, ductility);
  // Pure shear with a mean stress p = K ln J that changes with eps_p: none until 0.1, +200 MPa
  // until 0.3 (sigma* from 0.77 to 0.62 as the flow stress grows), none until 0.4, then -150 MPa
  // (sigma* from -0.44 to -0.37) until the point fails, at 0.76 by the integral (0.60 if the
  // last phase were shear, 1.46 with the mean stresses' signs swapped). A phase starts at the
  // step after eps_p passed its bound; the step's triaxiality is its phase's from its start.
  const double K = copper.bulk_modulus();
  const double bound[] = {0.1, 0.3, 0.4}, mean_stress[] = {0.0, 200e6, 0.0, -150e6};
  int phase = 0;
  std::vector<int> phase_of_step(4001, 0);
  const auto step = [&](int k, mat::johnson_cook_state& s) {
    if (phase < 3 && s.equivalent_plastic_strain >= bound[phase]) ++phase;
    phase_of_step[k] = phase;
    return jc.kirchhoff_stress(pure_shear(k, mean_stress[phase] / K), s, {dt, k * dt, s.temperature});
  };
  const path_record r = drive(jc, 0.0, step, [&](int k, double q) { return mean_stress[phase_of_step[k]] / q; });
  CHECK(phase == 3);  // the point failed under pressure, after the three other phases
  check(r);
  CHECK(r.worst_triaxiality <= 1e-9);
  // The phases count: with the triaxiality of shear throughout the point would fail at 0.905.
  CHECK(std::abs(r.integral_failure - 0.85 * (1.0 + 0.014 * std::log(rate))) > 0.1);
}

// (32f): with opens_cracks, a point that fails with its largest principal stress tensile records
// that principal direction as its crack normal, a point that fails under pressure records none,
// and without opens_cracks no point records one. Stretched along n at 30 degrees (isochoric, with
// a superposed volume increase of 1%), and in pure shear under a volume decrease of 2% (the mean
// stress K ln J = -2.6 GPa, far below the deviator's 2 mu e < 0.5 GPa).
TEST_CASE("johnson_cook damage that opens cracks: the crack normal is the tensile principal direction") {
  mat::johnson_cook_damage opening = ductility;
  opening.opens_cracks = true;
  const mat::johnson_cook jc(copper, copper_flow, mat::johnson_cook_heating{specific_heat, 0.0}, opening);
  const mat::johnson_cook closed(copper, copper_flow, mat::johnson_cook_heating{specific_heat, 0.0}, ductility);
  CHECK(jc.opens_cracks());
  CHECK(!closed.opens_cracks());
  const double angle = 0.5235987755982988;  // 30 degrees
  const rkpm::vec2 n(std::cos(angle), std::sin(angle));
  mat3 Q = mat3::Identity();
  Q.topLeftCorner<2, 2>() << n[0], -n[1], n[1], n[0];
  const auto stretched = [&](int k) {
    const double a = strain_step * k;  // the equivalent strain of an isochoric stretch (a, -a/2, -a/2)
    return mat3(std::exp(0.01 / 3.0) * Q * diagonal(std::exp(a), std::exp(-0.5 * a), std::exp(-0.5 * a)) * Q.transpose());
  };
  const auto fail_along = [&](const mat::johnson_cook& law, auto F_of_step) {
    auto s = law.initial_state();
    for (int k = 1; k <= 4000 && !s.failed(); ++k) law.kirchhoff_stress(F_of_step(k), s, {dt, k * dt, s.temperature});
    REQUIRE(s.failed());
    return rkpm::vec2(s.crack_normal);
  };
  const rkpm::vec2 normal = fail_along(jc, stretched);
  CHECK(normal.norm() == doctest::Approx(1.0).epsilon(1e-14));
  CHECK(std::abs(normal.dot(n)) == doctest::Approx(1.0).epsilon(1e-12));
  // Under pressure with these constants eps_f = 0.05 + 0.8 exp(1.5 x 9) would never be reached:
  // a constant failure strain there.
  const mat::johnson_cook pressed(copper, copper_flow, mat::johnson_cook_heating{specific_heat, 0.0},
                                  mat::johnson_cook_damage{0.3, 0.0, 0.0, 0.0, 0.0, true});
  CHECK(fail_along(pressed, [](int k) { return pure_shear(k, -0.02); }).norm() == 0.0);
  CHECK(fail_along(closed, stretched).norm() == 0.0);
}

}  // namespace test_unit_material_johnson_cook_damage
