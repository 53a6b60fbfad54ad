// material::zerilli_armstrong (docs/method.md section 4.6) against what is known without the code:
//   - the flow stress (24c) of both lattices written out here, its slopes against differences,
//     its work integral against Simpson's rule, the rate term never below 1, melt;
//   - one point stretched at a constant strain rate along an isochoric path (F = diag(e^e,
//     e^(-e/2), e^(-e/2)): coaxial, so the log-strain model is 1D plasticity and the von Mises
//     stress is the flow stress), both lattices, below and above the reference rate: the stress is
//     (24c) at the point's plastic strain and rate and at the temperature of the adiabatic ODE
//     dT / deps_p = beta sigma_y / (rho c_p) integrated here by RK4 (32e);
//   - melt: pressure only; a return that cannot converge is an error; bad constants are errors.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <rkpm/material/zerilli_armstrong.hpp>

#include "support/error_message.hpp"
#include "support/tensors.hpp"

namespace test_unit_material_zerilli_armstrong {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using rkpm::mat3;
namespace h = rkpm::material::hardening;
namespace mat = rkpm::material;
using lattice = h::zerilli_armstrong::lattice_type;

namespace {

using rkpm::test::diagonal;
using rkpm::test::von_mises;

// OFHC copper, fcc (Zerilli & Armstrong 1987): C0 = 65 MPa, C2 = 890 MPa, C3 = 0.0028 /K,
// C4 = 0.000115 /K; the elastic constants, density and heat of cases/taylor_bar_johnson_cook.json.
const h::zerilli_armstrong copper_flow{lattice::fcc, 65e6, 0.0, 890e6, 0.0028, 0.000115, 0.0, 0.0, 1.0, 1356.0};
const mat::elastic_constants copper{124e9, 0.34, 8960.0};
const double copper_rho_c = 8960.0 * 383.0;
// Armco iron, bcc (Zerilli & Armstrong 1987: C1 = 1033 MPa, C3 = 0.00698 /K, C4 = 0.000415 /K,
// C5 = 266 MPa, n = 0.289; C0 = 50 MPa chosen here), a reference rate of 10 /s to exercise it.
const h::zerilli_armstrong iron_flow{lattice::bcc, 50e6, 1033e6, 0.0, 0.00698, 0.000415, 266e6, 0.289, 10.0, 1811.0};
const mat::elastic_constants iron{211e9, 0.29, 7870.0};
const double iron_rho_c = 7870.0 * 452.0;

// (24c) written out here (not the law's code).
double za_curve(const h::zerilli_armstrong& l, double e, double rate, double T) {
  if (T >= l.melt_temperature) return 0.0;
  const double activated = std::exp(-l.C3 * T + l.C4 * T * std::log(std::max(rate / l.reference_rate, 1.0)));
  return l.lattice == lattice::fcc ? l.C0 + l.C2 * std::sqrt(e) * activated
                                   : l.C0 + l.C1 * activated + l.C5 * std::pow(e, l.n);
}

// The adiabatic temperature as a function of eps_p at a fixed plastic strain rate: RK4 of
// dT / de = beta sigma_y(e, rate, T) / (rho c_p) from (0, T0), advanced to increasing e.
struct adiabatic_ode {
  h::zerilli_armstrong law;
  double beta, rho_c, rate, e = 0.0, T;
  double slope(double ee, double TT) const { return beta * za_curve(law, ee, rate, TT) / rho_c; }
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

// An isochoric stretch along x with log strain e: theta = 0, q = |tau11 - tau22|.
mat3 isochoric(double e) { return diagonal(std::exp(e), std::exp(-0.5 * e), std::exp(-0.5 * e)); }

}  // namespace

TEST_CASE("zerilli_armstrong flow stress: both lattices, rate term never below 1, melt, slopes and work integral") {
  for (const h::zerilli_armstrong& l : {copper_flow, iron_flow}) {
    CAPTURE(l.lattice == lattice::fcc);
    l.validate();
    const double ref = l.reference_rate;
    // Slower than the reference rate: as at the reference rate; faster: exp(C4 T ln rate*).
    CHECK(l.flow_stress(0.2, {0.01 * ref, 300.0}) == l.flow_stress(0.2, {0.0, 300.0}));
    for (double e : {0.0, 0.01, 0.2, 1.5})
      for (double rate : {0.0, 0.5 * ref, 2.0 * ref, 1e4})
        for (double T : {77.0, 300.0, 900.0}) {
          CAPTURE(e);
          CAPTURE(rate);
          CAPTURE(T);
          CHECK(l.flow_stress(e, {rate, T}) == doctest::Approx(za_curve(l, e, rate, T)).epsilon(1e-14));
        }
    CHECK(l.flow_stress(0.0, {0.0, 300.0}) ==
          doctest::Approx(l.lattice == lattice::fcc ? 65e6 : 50e6 + 1033e6 * std::exp(-0.00698 * 300.0)).epsilon(1e-14));
    // At and above melt: 0, and so the slopes and the work.
    for (double T : {l.melt_temperature, l.melt_temperature + 100.0}) {
      CHECK(l.flow_stress(0.2, {1e3, T}) == 0.0);
      CHECK(l.slope(0.2, {1e3, T}) == 0.0);
      CHECK(l.rate_slope(0.2, {1e3, T}) == 0.0);
      CHECK(l.integral(0.1, 0.2, {1e3, T}) == 0.0);
    }
    for (double e : {0.01, 0.1, 0.5, 2.0})
      for (rkpm::flow_point at : {rkpm::flow_point{0.0, 294.0}, rkpm::flow_point{50.0 * ref, 600.0}}) {
        CAPTURE(e);
        CAPTURE(at.plastic_strain_rate);
        const double de = 1e-7 * e, dr = 1e-6 * at.plastic_strain_rate;
        CHECK(l.slope(e, at) == doctest::Approx((l.flow_stress(e + de, at) - l.flow_stress(e - de, at)) / (2 * de)).epsilon(1e-7));
        const rkpm::flow_point up{at.plastic_strain_rate + dr, at.temperature}, down{at.plastic_strain_rate - dr, at.temperature};
        CHECK(l.rate_slope(e, at) ==
              doctest::Approx(dr > 0.0 ? (l.flow_stress(e, up) - l.flow_stress(e, down)) / (2 * dr) : 0.0).epsilon(1e-6));
        // What the return mapping uses: both slopes from the flow stress it knows.
        const auto [strain_slope, rate_slope] = l.slopes_at_flow(e, at, l.flow_stress(e, at));
        CHECK(strain_slope == doctest::Approx(l.slope(e, at)).epsilon(1e-12));
        CHECK(rate_slope == doctest::Approx(l.rate_slope(e, at)).epsilon(1e-12));
        // The work integral against Simpson's rule with 20,000 panels from e/2 to e.
        const double a = 0.5 * e, b = e;
        const int n = 20000;
        double simpson = l.flow_stress(a, at) + l.flow_stress(b, at);
        for (int i = 1; i < n; ++i) simpson += (i % 2 ? 4.0 : 2.0) * l.flow_stress(a + (b - a) * i / n, at);
        simpson *= (b - a) / (3.0 * n);
        CHECK(l.integral(a, b, at) == doctest::Approx(simpson).epsilon(1e-10));
      }
  }
}

TEST_CASE("zerilli_armstrong, a constant strain rate: the ZA curve at the adiabatic ODE's temperature, fcc and bcc") {
  struct material_case {
    std::string label;
    mat::elastic_constants elastic;
    h::zerilli_armstrong flow;
    double specific_heat, rho_c;
  };
  for (const material_case& m : {material_case{"fcc copper", copper, copper_flow, 383.0, copper_rho_c},
                                 material_case{"bcc iron", iron, iron_flow, 452.0, iron_rho_c}}) {
    const mat::zerilli_armstrong za(m.elastic, m.flow, mat::zerilli_armstrong_heating{m.specific_heat, 0.9, 294.0});
    for (double rate_star : {0.1, 1e3}) {  // below and above the reference rate
      const double rate = rate_star * m.flow.reference_rate;
      CAPTURE(m.label);
      CAPTURE(rate);
      auto s = za.initial_state();
      CHECK(s.temperature == 294.0);
      adiabatic_ode ode{m.flow, 0.9, m.rho_c, rate, 0.0, 294.0};
      const int steps = 4000;
      const double total = 0.6, dt = total / rate / steps;
      double worst = 0.0, worst_T = 0.0, last_eps_p = 0.0;
      mat3 tau;
      for (int k = 1; k <= steps; ++k) {
        tau = za.kirchhoff_stress(isochoric(total * k / steps), s, {dt, k * dt, s.temperature});
        const double plastic_rate = (s.equivalent_plastic_strain - last_eps_p) / dt;
        last_eps_p = s.equivalent_plastic_strain;
        if (s.equivalent_plastic_strain < 0.02) continue;  // past the elastic-plastic transition
        const double T = ode.at(s.equivalent_plastic_strain);
        worst = std::max(worst, std::abs(von_mises(tau) / za_curve(m.flow, s.equivalent_plastic_strain, plastic_rate, T) - 1.0));
        worst_T = std::max(worst_T, std::abs(s.temperature - T));
      }
      MESSAGE(m.label, ", rate ", rate, "/s: eps_p ", s.equivalent_plastic_strain, ", T ", s.temperature, " K, q ",
              von_mises(tau), " Pa; largest relative stress difference ", worst, ", temperature ", worst_T, " K");
      CHECK(s.equivalent_plastic_strain > 0.55);
      CHECK(s.temperature - 294.0 > 25.0);  // the heating matters
      CHECK(worst < 1e-4);
      CHECK(worst_T < 0.02);
      CHECK(std::abs(tau.trace()) <= 1e-9 * von_mises(tau));  // isochoric: no pressure
      // The temperature is beta W_p / (rho c_p) of the point's own plastic work.
      CHECK(s.temperature - 294.0 == doctest::Approx(0.9 * s.plastic_work / m.rho_c).epsilon(1e-12));
      CHECK((za.current_kirchhoff_stress(isochoric(total), s) - tau).norm() <= 1e-9 * tau.norm());
    }
  }
}

TEST_CASE("zerilli_armstrong: molten points carry pressure only; the Newton return is bounded; bad constants are errors") {
  const mat::zerilli_armstrong molten(copper, copper_flow, mat::zerilli_armstrong_heating{383.0, 0.9, 1356.0});
  auto s = molten.initial_state();
  mat3 F = diagonal(1.01, 0.98, 1.0);
  F(0, 1) = 0.05;
  const mat3 tau = molten.kirchhoff_stress(F, s, {1e-7, 0.0, s.temperature});
  CHECK(von_mises(tau) <= 1e-6 * std::abs(tau(0, 0)));
  CHECK(tau(0, 0) == doctest::Approx(copper.bulk_modulus() * std::log(1.01 * 0.98)).epsilon(1e-12));
  CHECK(s.temperature == 1356.0);
  CHECK(s.equivalent_plastic_strain > 0.0);

  // No melt temperature: none (infinity); a hot point still has a flow stress.
  h::zerilli_armstrong no_melt = copper_flow;
  no_melt.melt_temperature = std::numeric_limits<double>::infinity();
  CHECK(no_melt.flow_stress(0.1, {0.0, 2000.0}) > 65e6);

  // One Newton update is not enough from eps_p = 0 (infinite slope of eps_p^(1/2)).
  const mat::zerilli_armstrong hasty(copper, copper_flow, mat::zerilli_armstrong_heating{383.0, 0.9, 294.0}, 1e-12, 1);
  auto h1 = hasty.initial_state();
  const std::string message =
      rkpm::test::error_message([&] { hasty.kirchhoff_stress(isochoric(0.01), h1, {1e-6, 0.0, 294.0}); });
  CHECK(rkpm::test::contains(message, "zerilli_armstrong"));
  CHECK(rkpm::test::contains(message, "max_newton_iterations"));

  const auto rejects = [](h::zerilli_armstrong l, const std::string& words) {
    CAPTURE(words);
    CHECK(rkpm::test::contains(rkpm::test::error_message([&] { l.validate(); }), words));
  };
  auto bad = copper_flow;
  bad.C2 = -1.0;
  rejects(bad, "C2 = -1 is invalid");
  bad = copper_flow;
  bad.C0 = bad.C2 = 0.0;
  rejects(bad, "C0 + C2 = 0 is invalid");
  bad = copper_flow;
  bad.C4 = -1e-4;
  rejects(bad, "C4 = -0.0001 is invalid");
  bad = copper_flow;
  bad.reference_rate = 0.0;
  rejects(bad, "reference_rate = 0 is invalid");
  bad = iron_flow;
  bad.n = 0.0;
  rejects(bad, "n = 0 is invalid");
  bad = iron_flow;
  bad.C1 = NAN;
  rejects(bad, "C1 = nan is invalid");
  CHECK(rkpm::test::contains(rkpm::test::error_message([&] {
                               mat::zerilli_armstrong(copper, copper_flow, mat::zerilli_armstrong_heating{-1.0, 0.9, 294.0});
                             }),
                             "specific_heat"));
  CHECK(rkpm::test::contains(rkpm::test::error_message([&] {
                               mat::zerilli_armstrong(copper, copper_flow, mat::zerilli_armstrong_heating{383.0, 0.9, NAN});
                             }),
                             "initial_temperature"));
}

}  // namespace test_unit_material_zerilli_armstrong
