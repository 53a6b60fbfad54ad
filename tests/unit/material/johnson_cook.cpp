// material::johnson_cook (docs/method.md section 4.5) against what is known without the code:
//   - the flow stress (24b), its slopes and work integral in closed form;
//   - one point in uniaxial stress (a coaxial path: the log-strain model is 1D plasticity, q =
//     tau11) at a constant strain rate below and above the reference rate: the stress is the
//     Johnson-Cook curve at the point's plastic strain and rate and at the temperature of the
//     adiabatic ODE dT / deps_p = beta sigma_y / (rho c_p) integrated here by RK4 (32a);
//   - with C = 0 and no heating, the forms of the existing laws: A = 0 from eps_p = eps0 is the
//     power law K (eps0 + eps_p)^n, n = 1 is linear hardening (on a path that yields, unloads
//     and yields again, with shear and a hoop stretch);
//   - damage: a bar in uniaxial tension fails when eps_p reaches eps_f(sigma* = 1/3) (32c);
//     after failure no stress in tension and the pressure K ln J in compression (32d);
//   - melt: no deviatoric stress; a return that cannot converge is an error; bad constants.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <rkpm/material/hardening.hpp>
#include <rkpm/material/j2_plasticity.hpp>
#include <rkpm/material/johnson_cook.hpp>
#include <rkpm/material/radial_return.hpp>

#include "support/error_message.hpp"
#include "support/tensors.hpp"

namespace test_unit_material_johnson_cook {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using rkpm::mat3;
namespace h = rkpm::material::hardening;
namespace mat = rkpm::material;

namespace {

using rkpm::test::diagonal;
using rkpm::test::von_mises;

// OFHC copper (Johnson & Cook 1983, Table 1): A, B, n, C, reference rate, m, room and melt.
const h::johnson_cook copper_flow{90e6, 292e6, 0.31, 0.025, 1.0, 1.09, 294.0, 1356.0};
const mat::elastic_constants copper{124e9, 0.34, 8960.0};
const double rho_c = 8960.0 * 383.0;  // J/(m^3 K)

// Drives one point in uniaxial stress along x: at the axial log strain e (this step's end) the
// lateral log strain x with tau22 = tau33 = 0 is found by the secant method on copies of the
// state, then the state advances. Returns tau.
template <class M>
mat3 uniaxial_step(const M& m, typename M::state_type& s, double e, double& lateral, double dt) {
  const rkpm::material_step step{dt, 0.0, s.temperature};
  const auto stress = [&](double x, auto& state) {
    return m.kirchhoff_stress(diagonal(std::exp(e), std::exp(x), std::exp(x)), state, step);
  };
  const auto lateral_stress = [&](double x) {
    auto trial = s;
    return stress(x, trial)(1, 1);
  };
  double x0 = lateral, x1 = x0 - 1e-6, r0 = lateral_stress(x0), r1 = lateral_stress(x1);
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
}

// The adiabatic temperature as a function of eps_p at a fixed plastic strain rate: RK4 of
// dT / de = beta sigma_y(e, rate, T) / (rho c_p) from (0, T0), advanced to increasing e.
struct adiabatic_ode {
  h::johnson_cook law;
  double beta, rate, e = 0.0, T;
  double slope(double ee, double TT) const {
    return beta * (law.A + law.B * std::pow(ee, law.n)) * (1.0 + law.C * std::log(std::max(rate / law.reference_rate, 1.0))) *
           (1.0 - std::pow(std::clamp((TT - law.room_temperature) / (law.melt_temperature - law.room_temperature), 0.0, 1.0),
                           law.m)) /
           rho_c;
  }
  double at(double target) {
    while (e < target) {
      const double hh = std::min(1e-4, target - e);
      const double k1 = slope(e, T), k2 = slope(e + hh / 2, T + hh / 2 * k1), k3 = slope(e + hh / 2, T + hh / 2 * k2),
                   k4 = slope(e + hh, T + hh * k3);
      T += hh / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
      e += hh;
    }
    return T;
  }
};

// The same curve written out here (not the law's code): (A + B e^n)(1 + C ln max(r, 1))(1 - T*^m).
double jc_curve(double e, double rate, double T) {
  const auto& l = copper_flow;
  const double Ts = std::clamp((T - l.room_temperature) / (l.melt_temperature - l.room_temperature), 0.0, 1.0);
  return (l.A + l.B * std::pow(e, l.n)) * (1.0 + l.C * std::log(std::max(rate / l.reference_rate, 1.0))) *
         (1.0 - std::pow(Ts, l.m));
}

}  // namespace

TEST_CASE("johnson_cook flow stress: rate term never below 1, T* clamped to [0, 1], slopes and work integral") {
  const auto& l = copper_flow;
  l.validate();
  const rkpm::flow_point room{0.0, 294.0};
  CHECK(l.flow_stress(0.0, room) == 90e6);
  CHECK(l.flow_stress(0.2, room) == doctest::Approx(90e6 + 292e6 * std::pow(0.2, 0.31)).epsilon(1e-15));
  // Slower than the reference rate: no softening; faster: 1 + C ln rate*.
  CHECK(l.flow_stress(0.2, {0.01, 294.0}) == l.flow_stress(0.2, room));
  CHECK(l.flow_stress(0.2, {1e3, 294.0}) == doctest::Approx(l.flow_stress(0.2, room) * (1 + 0.025 * std::log(1e3))).epsilon(1e-15));
  // Below room temperature and with no temperature (NaN): T* = 0. At and above melt: 0.
  CHECK(l.flow_stress(0.2, {0.0, 200.0}) == l.flow_stress(0.2, room));
  CHECK(l.flow_stress(0.2, {0.0, NAN}) == l.flow_stress(0.2, room));
  CHECK(l.flow_stress(0.2, {0.0, 1356.0}) == 0.0);
  CHECK(l.flow_stress(0.2, {0.0, 2000.0}) == 0.0);
  CHECK(l.flow_stress(0.2, {0.0, 825.0}) ==
        doctest::Approx(l.flow_stress(0.2, room) * (1 - std::pow(0.5, 1.09))).epsilon(1e-15));
  for (double e : {0.01, 0.1, 0.5, 2.0})
    for (rkpm::flow_point at : {rkpm::flow_point{0.0, 294.0}, rkpm::flow_point{50.0, 600.0}}) {
      CAPTURE(e);
      const double de = 1e-7 * e, dr = 1e-6 * std::max(at.plastic_strain_rate, 1.0);
      CHECK(l.slope(e, at) == doctest::Approx((l.flow_stress(e + de, at) - l.flow_stress(e - de, at)) / (2 * de)).epsilon(1e-7));
      const rkpm::flow_point up{at.plastic_strain_rate + dr, at.temperature}, down{at.plastic_strain_rate - dr, at.temperature};
      CHECK(l.rate_slope(e, at) ==
            doctest::Approx(at.plastic_strain_rate > 1.0 ? (l.flow_stress(e, up) - l.flow_stress(e, down)) / (2 * dr) : 0.0)
                .epsilon(1e-6));
      // The work integral against Simpson's rule with 20,000 panels from e/2 to e.
      const double a = 0.5 * e, b = e;
      const int n = 20000;
      double simpson = l.flow_stress(a, at) + l.flow_stress(b, at);
      for (int i = 1; i < n; ++i) simpson += (i % 2 ? 4.0 : 2.0) * l.flow_stress(a + (b - a) * i / n, at);
      simpson *= (b - a) / (3.0 * n);
      CHECK(l.integral(a, b, at) == doctest::Approx(simpson).epsilon(1e-10));
      // What the return mapping uses: the same integral and slopes from the flow stresses it knows.
      const auto iso = l.at_temperature(at.temperature);
      CHECK(iso.integral(a, b, l.flow_stress(a, {0.0, at.temperature}), l.flow_stress(b, at), at.plastic_strain_rate) ==
            doctest::Approx(simpson).epsilon(1e-10));
      const auto [strain_slope, rate_slope] = iso.slopes_at_flow(e, at, l.flow_stress(e, at));
      CHECK(strain_slope == doctest::Approx(l.slope(e, at)).epsilon(1e-12));
      CHECK(rate_slope == doctest::Approx(l.rate_slope(e, at)).epsilon(1e-12));
    }
}

TEST_CASE("johnson_cook, uniaxial stress at a constant strain rate: the JC curve at the adiabatic ODE's temperature") {
  const mat::johnson_cook jc(copper, copper_flow, mat::johnson_cook_heating{383.0, 0.9});
  for (double rate : {0.1, 1e3}) {  // below and above the reference rate (1/s)
    CAPTURE(rate);
    auto s = jc.initial_state();
    CHECK(s.temperature == 294.0);
    adiabatic_ode ode{copper_flow, 0.9, rate, 0.0, 294.0};
    const int steps = 3000;
    const double total = 0.6, dt = total / rate / steps;
    double lateral = 0.0, worst = 0.0, worst_T = 0.0, worst_cache = 0.0, last_eps_p = 0.0;
    mat3 tau;
    for (int k = 1; k <= steps; ++k) {
      tau = uniaxial_step(jc, s, total * k / steps, lateral, dt);
      const double plastic_rate = (s.equivalent_plastic_strain - last_eps_p) / dt;
      last_eps_p = s.equivalent_plastic_strain;
      if (s.equivalent_plastic_strain < 0.02) continue;  // past the elastic-plastic transition
      const double T = ode.at(s.equivalent_plastic_strain);
      worst = std::max(worst, std::abs(tau(0, 0) / jc_curve(s.equivalent_plastic_strain, plastic_rate, T) - 1.0));
      worst_T = std::max(worst_T, std::abs(s.temperature - T));
      // The yield check's cached flow stress is (24b) at the state's eps_p and T (rate* <= 1).
      worst_cache = std::max(worst_cache, std::abs(s.flow_stress_at_rest /
                                                       copper_flow.flow_stress(s.equivalent_plastic_strain, {0.0, s.temperature}) - 1.0));
      // ... and T*^m, carried by the series from step to step, is pow's to round-off still.
      worst_cache = std::max(worst_cache, std::abs(s.homologous_power / copper_flow.homologous_power(s.temperature) - 1.0));
    }
    MESSAGE("rate ", rate, "/s: eps_p ", s.equivalent_plastic_strain, ", T ", s.temperature, " K, tau11 ", tau(0, 0),
            " Pa; largest relative stress difference ", worst, ", temperature ", worst_T, " K");
    CHECK(s.equivalent_plastic_strain > 0.55);
    CHECK(s.temperature - 294.0 > 30.0);  // the heating matters (about 3 % softening here)
    CHECK(worst < 1e-4);
    CHECK(worst_T < 0.02);
    CHECK(worst_cache < 1e-13);
    CHECK(von_mises(tau) == doctest::Approx(tau(0, 0)).epsilon(1e-8));  // uniaxial indeed
    // The temperature is beta W_p / (rho c_p) of the point's own plastic work.
    CHECK(s.temperature - 294.0 == doctest::Approx(0.9 * s.plastic_work / rho_c).epsilon(1e-12));
  }
}

TEST_CASE("johnson_cook with C = 0 and no heating: the power law from eps_p = eps0 with A = 0, linear hardening with n = 1") {
  const double dt = 1e-7;  // a high rate, which C = 0 ignores
  SUBCASE("power law") {
    const h::power_law pl{576.79e6, 0.01658, 0.3593};
    const mat::j2_plasticity<h::power_law> j2(copper, pl);
    const mat::johnson_cook jc(copper, h::johnson_cook{0.0, 576.79e6, 0.3593, 0.0, 1.0, 1.0, 294.0, 1356.0},
                               mat::johnson_cook_heating{383.0, 0.0});
    auto a = j2.initial_state();
    auto b = jc.initial_state(pl.offset);
    for (const mat3& F : rkpm::test::stretch_shear_path()) {
      const mat3 ta = j2.kirchhoff_stress(F, a), tb = jc.kirchhoff_stress(F, b, {dt, 0.0, 294.0});
      CHECK((ta - tb).norm() <= 1e-10 * ta.norm());
      CHECK(b.equivalent_plastic_strain - pl.offset == doctest::Approx(a.equivalent_plastic_strain).epsilon(1e-9));
      CHECK(b.plastic_work == doctest::Approx(a.plastic_work).epsilon(1e-9));
      CHECK(b.temperature == 294.0);
    }
    CHECK(a.equivalent_plastic_strain > 0.05);
  }
  SUBCASE("linear") {
    const mat::j2_plasticity<h::linear> j2(copper, h::linear{400e6, 100e6});
    const mat::johnson_cook jc(copper, h::johnson_cook{400e6, 100e6, 1.0, 0.0, 1.0, 1.0, 294.0, 1356.0},
                               mat::johnson_cook_heating{383.0, 0.0});
    auto a = j2.initial_state();
    auto b = jc.initial_state();
    for (const mat3& F : rkpm::test::stretch_shear_path()) {
      const mat3 ta = j2.kirchhoff_stress(F, a), tb = jc.kirchhoff_stress(F, b, {dt, 0.0, 294.0});
      CHECK((ta - tb).norm() <= 1e-10 * ta.norm());
      CHECK(b.equivalent_plastic_strain == doctest::Approx(a.equivalent_plastic_strain).epsilon(1e-9));
      CHECK(b.plastic_work == doctest::Approx(a.plastic_work).epsilon(1e-9));
    }
    CHECK(a.equivalent_plastic_strain > 0.05);
  }
}

TEST_CASE("johnson_cook damage: uniaxial tension fails at eps_f(sigma* = 1/3); then no tension, pressure in compression") {
  const mat::johnson_cook_damage d{0.54, 4.89, -3.03, 0.014, 1.12};  // OFHC copper (Johnson & Cook 1985)
  const mat::johnson_cook jc(copper, copper_flow, mat::johnson_cook_heating{383.0, 0.0}, d);  // isothermal: T* = 0
  const double rate = 100.0;
  const double eps_f = (0.54 + 4.89 * std::exp(-3.03 / 3.0)) * (1.0 + 0.014 * std::log(rate));
  auto s = jc.initial_state();
  const int steps = 4000;
  const double total = 2.0 * eps_f, dt = total / rate / steps;
  double lateral = 0.0, eps_p_at_failure = -1.0, last = 0.0, largest_step = 0.0;
  int k = 1;
  for (; k <= steps && !s.failed(); ++k) {
    uniaxial_step(jc, s, total * k / steps, lateral, dt);
    largest_step = std::max(largest_step, s.equivalent_plastic_strain - last);
    last = s.equivalent_plastic_strain;
  }
  REQUIRE(s.failed());
  eps_p_at_failure = s.equivalent_plastic_strain;
  MESSAGE("eps_f(1/3) = ", eps_f, ", failed at eps_p = ", eps_p_at_failure, " (steps of ", largest_step, ")");
  // The plastic rate is the applied one up to the elastic part (ln of it: ~1e-3 of D4 ln rate*).
  CHECK(eps_p_at_failure >= eps_f - 1e-3 * eps_f);
  CHECK(eps_p_at_failure <= eps_f + 2.0 * largest_step);
  // Failed, in tension: no stress at all.
  const mat3 stretched = diagonal(std::exp(total * k / steps), std::exp(lateral), std::exp(lateral));
  const mat3 t1 = jc.kirchhoff_stress(stretched, s, {dt, 0.0, s.temperature});
  CHECK(t1 == mat3::Zero());
  CHECK(jc.current_kirchhoff_stress(stretched, s) == mat3::Zero());
  // Failed, compressed and sheared: the pressure only, tau = K ln J 1 (plastic flow is isochoric,
  // so the elastic volume change is the total one).
  mat3 F = diagonal(0.9, 0.95, 0.97);
  F(0, 1) = 0.2;
  const double J = F.topLeftCorner<2, 2>().determinant() * F(2, 2);
  const mat3 t2 = jc.kirchhoff_stress(F, s, {dt, 0.0, s.temperature});
  const double p = copper.bulk_modulus() * std::log(J);
  CHECK(p < 0.0);
  CHECK((t2 - p * mat3::Identity()).norm() <= 1e-9 * std::abs(p));
  CHECK((jc.current_kirchhoff_stress(F, s) - t2).norm() <= 1e-9 * std::abs(p));
}

TEST_CASE("johnson_cook: molten points carry pressure only; the Newton return is bounded; bad constants are errors") {
  // At melt: the deviator of a shear disappears, the volume change keeps its pressure.
  const mat::johnson_cook molten(copper, copper_flow, mat::johnson_cook_heating{383.0, 0.9, 1356.0});
  auto s = molten.initial_state();
  mat3 F = diagonal(1.01, 0.98, 1.0);
  F(0, 1) = 0.05;
  const mat3 tau = molten.kirchhoff_stress(F, s, {1e-7, 0.0, s.temperature});
  CHECK(von_mises(tau) <= 1e-6 * std::abs(tau(0, 0)));
  CHECK(tau(0, 0) == doctest::Approx(copper.bulk_modulus() * std::log(1.01 * 0.98)).epsilon(1e-12));
  CHECK(s.temperature == 1356.0);

  // One Newton update is not enough from eps_p = 0 (infinite slope for n < 1).
  const mat::johnson_cook hasty(copper, copper_flow, mat::johnson_cook_heating{383.0}, std::nullopt, 1e-12, 1);
  auto h1 = hasty.initial_state();
  const std::string message = rkpm::test::error_message([&] { hasty.kirchhoff_stress(diagonal(1.01, 0.995, 0.995), h1, {1e-6, 0.0, 294.0}); });
  CHECK(rkpm::test::contains(message, "did not converge"));
  CHECK(rkpm::test::contains(message, "max_newton_iterations"));

  auto bad = copper_flow;
  bad.n = 1.5;
  CHECK(rkpm::test::contains(rkpm::test::error_message([&] { bad.validate(); }), "n = 1.5 is invalid"));
  bad = copper_flow;
  bad.melt_temperature = 200.0;
  CHECK(rkpm::test::contains(rkpm::test::error_message([&] { bad.validate(); }), "melt_temperature"));
  bad = copper_flow;
  bad.B = -1.0;
  CHECK(rkpm::test::contains(rkpm::test::error_message([&] { bad.validate(); }), "B = -1 is invalid"));
  CHECK(rkpm::test::contains(
      rkpm::test::error_message([&] { mat::johnson_cook(copper, copper_flow, mat::johnson_cook_heating{-1.0}); }),
      "specific_heat"));
}

TEST_CASE("johnson_cook: (1 + u)^p by the binomial series and T*^m carried from T to T + dT equal pow's") {
  for (double p : {0.31, 1.0, 1.09, 2.5})
    for (double u : {-1.0 / 32.0, -1e-3, -1e-9, 0.0, 1e-12, 1e-6, 0.01, 1.0 / 32.0}) {
      CAPTURE(p);
      CAPTURE(u);
      CHECK(h::johnson_cook::binomial_power(p, u) == doctest::Approx(std::pow(1.0 + u, p)).epsilon(4e-16));
    }
  for (double T : {294.0, 295.0, 600.0, 1300.0})
    for (double dT : {0.0, 1e-6, 0.3, 5.0, 100.0}) {  // the series while dT <= (T - T_room) / 32, pow beyond
      CAPTURE(T);
      CAPTURE(dT);
      const double after = copper_flow.homologous_power_after(T, copper_flow.homologous_power(T), T + dT);
      CHECK(after == doctest::Approx(copper_flow.homologous_power(T + dT)).epsilon(1e-15));
    }
  CHECK(copper_flow.homologous_power_after(1300.0, copper_flow.homologous_power(1300.0), 1400.0) == 1.0);  // melt
  CHECK(copper_flow.at_homologous_power(1.0).theta == 0.0);
}

TEST_CASE("johnson_cook: the return along the step (series for eps^n, no log per update) solves what the general rate branch solves") {
  const double three_mu = 3.0 * copper.shear_modulus();
  h::johnson_cook linear = copper_flow;
  linear.n = 1.0;  // the linear law: the curve's power without a series
  for (const h::johnson_cook& l : {copper_flow, linear})
  for (double T : {294.0, 700.0})
    for (double eps_n : {0.0, 1e-6, 0.05, 1.0})
      for (double rate : {0.5, 1.01, 1.1, 1e2, 1e4, 1e6})  // 1.01, 1.1: the root just past the kink at rate* = 1
        for (double dt : {1e-8, 1e-6}) {
          CAPTURE(l.n);
          CAPTURE(T);
          CAPTURE(eps_n);
          CAPTURE(rate);
          CAPTURE(dt);
          const auto iso = l.at_temperature(T);
          // The curve along the step against the flow stress and its slopes at rate dg / dt.
          const double y = iso.flow_stress(eps_n, {0.0, T});
          const auto curve = iso.along_step(eps_n, dt, y);
          for (double dg : {1e-9, 1e-4, 0.02 * eps_n, 0.2}) {
            if (!(dg > 0.0)) continue;
            const rkpm::flow_point at{dg / dt, T};
            const auto p = curve(dg, std::log(dg));
            CHECK(p.flow == doctest::Approx(l.flow_stress(eps_n + dg, at)).epsilon(1e-14));
            CHECK(p.dflow_dx == doctest::Approx(dg * l.slope(eps_n + dg, at) + dg / dt * l.rate_slope(eps_n + dg, at)).epsilon(1e-12));
            CHECK(1.0 + l.C * p.log_rate == doctest::Approx(l.rate_factor(dg / dt)).epsilon(1e-15));
          }
          // A trial stress past the rate-0 yield by 3 mu rate dt plus the overstress of `rate`.
          const double q = iso.flow_stress(eps_n, {rate, T}) + three_mu * rate * dt;
          const auto fast = rkpm::material::radial_return(iso, q, three_mu, eps_n, 1e-12, 50, y, {dt, 0.0, T});
          const auto general = rkpm::material::radial_return(l, q, three_mu, eps_n, 1e-12, 50, y, {dt, 0.0, T});
          CHECK(std::abs(fast.residual) <= 1e-12 * q);
          CHECK(fast.flow_stress == doctest::Approx(l.flow_stress(eps_n + fast.increment, {fast.increment / dt, T})).epsilon(1e-13));
          CHECK(fast.log_rate == doctest::Approx(std::log(std::max(1.0, fast.increment / dt / l.reference_rate))).epsilon(1e-13).scale(1.0));
          // Both roots within what the residual tolerance allows: |d dgamma| <= 2e-12 q / (3 mu).
          CHECK(std::abs(fast.increment - general.increment) <= 2e-12 * q / three_mu);
          CHECK(fast.iterations <= general.iterations + 1);
          // From a first guess (the last step's increment) on either side of the root, near it or
          // far from it: the same root.
          for (double factor : {1e-3, 0.5, 0.9, 1.1, 2.0, 1e3}) {
            CAPTURE(factor);
            const auto guessed = rkpm::material::radial_return(iso, q, three_mu, eps_n, 1e-12, 50, y, {dt, 0.0, T},
                                                               std::log(factor * general.increment));
            CHECK(std::abs(guessed.increment - general.increment) <= 2e-12 * q / three_mu);
          }
        }
}

TEST_CASE("johnson_cook: the return converges when the root lies just past the rate term's kink (rate* = 1)") {
  // A point of a refined Johnson-Cook Taylor bar at its first yield, where Chebyshev's update from
  // above the root crossed the kink, and Newton's from below it jumped back above, for 50 updates.
  const double three_mu = 3.0 * copper.shear_modulus();
  const double q = 93208030.6849361, eps_n = 4.557331937145441e-07, dt = 2.57313e-06 / 406;
  const auto iso = copper_flow.at_temperature(294.0);
  const double y = iso.flow_stress(eps_n, {0.0, 294.0});
  for (double guess : {0.0, 1e-12, 1e-9, 8e-8, 1e-7, 4.557e-7}) {
    CAPTURE(guess);
    const auto r = rkpm::material::radial_return(iso, q, three_mu, eps_n, 1e-12, 50, y, {dt, 0.0, 294.0}, std::log(guess));
    CHECK(std::abs(r.residual) <= 1e-12 * q);
    CHECK(r.increment / dt == doctest::Approx(1.0).epsilon(0.05));  // rate* just above 1
    CHECK(r.iterations <= 8);
  }
}

TEST_CASE("johnson_cook::set_temperature: a point at a conducted temperature is the point that starts there") {
  // A conducted field sets T between steps (thermal/heat_coupling.hpp): the state must then be the
  // one initial_state gives at T, with the same plastic strain (its cached flow stress and T*^m).
  const mat::johnson_cook jc(copper, copper_flow, mat::johnson_cook_heating{383.0, 0.9, 294.0});
  for (const double T : {294.0, 600.0, 1000.0}) {
    auto s = jc.initial_state(0.2);
    jc.set_temperature(s, T);
    const mat::johnson_cook there(copper, copper_flow, mat::johnson_cook_heating{383.0, 0.9, T});
    const auto fresh = there.initial_state(0.2);
    CHECK(s.temperature == T);
    CHECK(s.homologous_power == fresh.homologous_power);
    CHECK(s.flow_stress_at_rest == fresh.flow_stress_at_rest);
  }
  auto s = jc.initial_state(0.2);
  const double cold = s.flow_stress_at_rest;
  jc.set_temperature(s, 900.0);
  CHECK(s.flow_stress_at_rest < 0.8 * cold);  // (1 - T*^m) with T* = 0.57
}

TEST_CASE("johnson_cook: ln dt from the force loop (UpdatesWithStepLog) or taken by the law, the same bits") {
  const mat::johnson_cook jc(copper, copper_flow, mat::johnson_cook_heating{383.0, 0.9, 294.0});
  static_assert(rkpm::UpdatesWithStepLog<mat::johnson_cook>);
  const double dt = 1e-7;
  auto given = jc.initial_state(), taken = given;
  int yielded = 0;
  for (int n = 1; n <= 300; ++n) {
    const double e = 2e-4 * n;
    const mat3 F = diagonal(std::exp(e), std::exp(-0.5 * e), std::exp(-0.5 * e));
    const double before = given.equivalent_plastic_strain;
    const mat3 a = rkpm::material_update(jc, F, given, {dt, n * dt, given.temperature}, std::log(dt));
    const mat3 b = jc.kirchhoff_stress(F, taken, {dt, n * dt, taken.temperature});
    yielded += given.equivalent_plastic_strain > before;
    REQUIRE(a == b);  // equal values, neither NaN nor a signed zero in play: the same bits
    REQUIRE(given.log_last_increment == taken.log_last_increment);
  }
  CHECK(yielded > 200);
}

}  // namespace test_unit_material_johnson_cook
