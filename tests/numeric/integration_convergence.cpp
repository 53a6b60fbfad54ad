// Accuracy and convergence of every cell rule against two analytic solutions, beside the
// paper's q2 and q4 (docs/method.md sections 3.4-3.5):
//   axisymmetric uniform radial expansion (numeric/axisymmetric_expansion.cpp): u_r = V t r,
//     u_z = 0 is exact; error max_I |u_I - (V t r_I, 0)| / (V t R0) at 9 x 9, 17 x 17, 25 x 25;
//   free elastic bar, plane strain, nu = 0 (numeric/elastic_bar.cpp): the fundamental period
//     2 L / c; error |T_h / T - 1| at 11, 21, 41, 81 particles along the bar (x 3 across).
// The measured rates (observed orders, log of the error ratio over log of the spacing ratio)
// of all rules are printed. What holds, and is asserted: VCI removes most of q2's error in the expansion (13x)
// and leaves every rule at first order there; in the bar every rule is within 10% of q4 at
// second order.
// Issue 10's claim, q2+vci at least as accurate as q4 at every resolution in both problems,
// does not hold, and the last test case, marked should_fail, records that (it fails if the
// claim starts to hold, so that this note is revisited). Why (numeric/integration_statics.cpp):
//   expansion  the error is that of the essential conditions: u_r(R0) and u_z on the ends are
//              imposed on physical values by collocation (docs/method.md (50)), whose reactions
//              sum_J N_I(X_J) lambda_J cannot equal the consistent boundary resultants
//              integral N_I sigma n; the static problem with the same conditions reproduces the
//              dynamic errors to 2-3 digits, q9 errs more than q4 there (q4's integration error
//              partly cancels the conditions'), and with consistent tractions instead q2+vci
//              and q4+vci are exact to 1e-13 while q4 errs by 0.5%;
//   bar        the period error is the lumped mass's (rate 2, the same for every rule within
//              10%); with a consistent mass the stiffness's own frequency error is O(h^2) for
//              q2+vci (2-7 times q4's, which is O(h^3) for this smooth mode). Linear VCI makes
//              the rule consistent, not more accurate for smooth fields: in the static
//              manufactured problem q2+vci converges at second order but stays 4-17 times
//              above q4 up to 33 x 33.

#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <numbers>

#include "support/solver_fixtures.hpp"

namespace test_numeric_integration_convergence {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

namespace {

template <class Q, class G>
using cfg = config<kernel::cubic_spline, correction::linear, Q, G, material::elastic, contact::none>;

// ---- axisymmetric uniform expansion ---------------------------------------------------------
template <class Q>
double expansion_error(int n) {
  using Cfg = cfg<Q, geometry::axisymmetric>;
  const material::elastic_constants c{117e9, 0.35, 8930.0};
  const double R0 = 3.2e-3, Lz = 6.4e-3;
  const double strain = 2e-3, end_time = 20.0 * R0 / c.dilatational_wave_speed();
  const double V = strain / end_time;
  auto p = test::grid_problem<Cfg>(vec2(0, 0), vec2(R0, Lz), Eigen::Vector2i(n, n), c);
  p.initial_velocity = [V](const vec2& X) { return vec2(V * X[0], 0.0); };
  for (index_t I = 0; I < p.particles.size(); ++I) {
    const vec2& X = p.particles.position[I];
    if (X[0] == R0) p.constraints.push_back({I, 0, [V, R0](double) { return V * R0; }});
    if (X[1] == 0.0 || X[1] == Lz) p.constraints.push_back({I, 1, {}});
  }
  run_options o;
  o.end_time = end_time;
  auto s = make_solver<Cfg>(std::move(p), o);
  s.run();
  const double t = s.time(), outer = V * t * R0;
  const auto u = s.particle_displacements();
  double e = 0.0;
  for (index_t I = 0; I < s.model().particle_count(); ++I)
    e = std::max(e, (u[I] - vec2(V * t * s.model().particles.position[I][0], 0.0)).norm() / outer);
  CHECK(s.energy().balance_error() < 1e-4);
  return e;
}

// ---- free elastic bar -------------------------------------------------------------------------
const material::elastic_constants bar{100e9, 0.0, 8000.0};
const double L = 1.0, H = 0.1;

struct bar_result {
  double error = 0.0;  // |period / (2 L / c) - 1|
  double drift = 0.0;  // max |K + W_int - K0| / K0
};

template <class Q>
bar_result bar_period(int nx) {
  using Cfg = cfg<Q, geometry::plane_strain>;
  const double c = std::sqrt(bar.youngs_modulus / bar.density), T = 2.0 * L / c, V = 1e-4 * c;
  auto p = test::grid_problem<Cfg>(vec2(0, 0), vec2(L, H), Eigen::Vector2i(nx, 3), bar);
  p.initial_velocity = [V](const vec2& X) { return vec2(V * std::cos(std::numbers::pi * X[0] / L), 0.0); };
  run_options o;
  o.end_time = 5.0 * T;
  o.time_step_fraction = 0.5;
  auto s = make_solver<Cfg>(std::move(p), o);
  std::vector<index_t> end;
  for (index_t I = 0; I < s.model().particle_count(); ++I)
    if (s.model().particles.position[I][0] == 0.0) end.push_back(I);
  std::vector<double> t, u;
  bar_result r;
  const double K0 = s.energy().initial_kinetic;
  s.run(
      [&](const auto& solver) {
        double ux = 0.0;
        for (index_t I : end) ux += solver.model().at_particles.interpolate(I, solver.coefficients())[0];
        t.push_back(solver.time());
        u.push_back(ux / static_cast<double>(end.size()));
        const auto& e = solver.energy();
        r.drift = std::max(r.drift, std::abs(e.kinetic + e.internal - K0) / K0);
      },
      1);
  std::vector<double> crossing;
  for (std::size_t k = 2; k < u.size(); ++k)
    if ((u[k - 1] > 0.0) != (u[k] > 0.0)) crossing.push_back(t[k - 1] + (t[k] - t[k - 1]) * u[k - 1] / (u[k - 1] - u[k]));
  REQUIRE(crossing.size() >= 4);
  const double period = 2.0 * (crossing.back() - crossing.front()) / static_cast<double>(crossing.size() - 1);
  r.error = std::abs(period / T - 1.0);
  return r;
}

// ---- every rule ---------------------------------------------------------------------------------
const std::vector<int> expansion_n{9, 17, 25};
const std::vector<int> bar_n{11, 21, 41, 81};

// Observed order between resolutions k-1 and k (n particles per direction, spacing ~ 1/(n-1)).
double rate(const std::vector<double>& e, const std::vector<int>& n, std::size_t k) {
  return std::log(e[k - 1] / e[k]) / std::log(double(n[k] - 1) / double(n[k - 1] - 1));
}
std::string rates(const std::vector<double>& e, const std::vector<int>& n) {
  std::string s;
  for (std::size_t k = 1; k < e.size(); ++k) s += (k > 1 ? ", " : "") + fmt::format("{:.2f}", rate(e, n, k));
  return s;
}
std::string errors(const std::vector<double>& e) {
  std::string s;
  for (std::size_t k = 0; k < e.size(); ++k) s += (k ? ", " : "") + fmt::format("{:.3g}", e[k]);
  return s;
}

template <class Q>
std::vector<double> expansion_errors() {
  std::vector<double> e;
  for (int n : expansion_n) e.push_back(expansion_error<Q>(n));
  MESSAGE("expansion " << Q::name << ": errors at 9, 17, 25 = " << errors(e) << "; rates " << rates(e, expansion_n));
  return e;
}

template <class Q>
std::vector<double> bar_errors() {
  std::vector<double> e;
  double drift = 0.0;
  for (int n : bar_n) {
    const auto r = bar_period<Q>(n);
    e.push_back(r.error);
    drift = std::max(drift, r.drift);
  }
  MESSAGE("bar " << Q::name << ": period errors at 11, 21, 41, 81 = " << errors(e) << "; rates " << rates(e, bar_n)
                 << "; worst energy drift " << drift);
  CHECK(drift < 5e-3);
  return e;
}

}  // namespace

namespace {
// Errors of every rule, computed once for the test cases below.
struct all_errors {
  std::map<std::string, std::vector<double>> expansion, bar;
};

const all_errors& measured() {
  static const all_errors e = [] {
    test::run_serially();
    all_errors r;
    r.expansion["q4"] = expansion_errors<quadrature::q4>();
    r.expansion["q2"] = expansion_errors<quadrature::q2>();
    r.expansion["q2_split"] = expansion_errors<quadrature::q2_split>();
    r.expansion["q2_tri"] = expansion_errors<quadrature::q2_tri>();
    r.expansion["q2+vci"] = expansion_errors<quadrature::q2_vci>();
    r.expansion["q4+vci"] = expansion_errors<quadrature::q4_vci>();
    r.bar["q4"] = bar_errors<quadrature::q4>();
    r.bar["q2"] = bar_errors<quadrature::q2>();
    r.bar["q2_split"] = bar_errors<quadrature::q2_split>();
    r.bar["q2_tri"] = bar_errors<quadrature::q2_tri>();
    r.bar["q2+vci"] = bar_errors<quadrature::q2_vci>();
    r.bar["q4+vci"] = bar_errors<quadrature::q4_vci>();
    return r;
  }();
  return e;
}

}  // namespace

TEST_CASE("uniform radial expansion: VCI removes most of q2's error; every rule at first order") {
  const auto& e = measured().expansion;
  for (std::size_t k = 0; k < expansion_n.size(); ++k) {
    CAPTURE(expansion_n[k]);
    CHECK(e.at("q2+vci")[k] < e.at("q2")[k] / 8.0);
    CHECK(e.at("q4+vci")[k] < 1.25 * e.at("q4")[k]);
    CHECK(e.at("q2_split")[k] < e.at("q2")[k]);
    CHECK(e.at("q2_tri")[k] < e.at("q2")[k]);
  }
  for (const auto& [rule, errors] : e) {
    CAPTURE(rule);
    CHECK(rate(errors, expansion_n, 2) > 0.8);
    CHECK(rate(errors, expansion_n, 2) < 1.3);
  }
}

TEST_CASE("elastic bar period: every rule within 10% of q4, at second order") {
  const auto& e = measured().bar;
  for (const auto& [rule, errors] : e) {
    CAPTURE(rule);
    for (std::size_t k = 0; k < bar_n.size(); ++k) CHECK(std::abs(errors[k] / e.at("q4")[k] - 1.0) < 0.1);
    CHECK(rate(errors, bar_n, 3) > 1.8);
  }
}

// Expected to fail (see the header): the test cases above assert what holds instead.
TEST_CASE("issue 10's claim: q2+vci at least as accurate as q4 at every resolution" * doctest::should_fail()) {
  const auto& m = measured();
  for (std::size_t k = 0; k < expansion_n.size(); ++k) CHECK(m.expansion.at("q2+vci")[k] <= m.expansion.at("q4")[k]);
  for (std::size_t k = 0; k < bar_n.size(); ++k) CHECK(m.bar.at("q2+vci")[k] <= m.bar.at("q4")[k]);
}

// scni (docs/method.md section 3.6) beside the rules above, held to what they are: first order in
// the expansion, whose error the collocated conditions set (measured 0.00596, 0.00286, 0.00187;
// rates 1.06, 1.04), and second order in the bar's period, the lumped mass's (measured 0.0173,
// 0.00413, 0.00102, 0.000262; rates 2.07, 2.02, 1.95), there 11% to 15% above q4 (the others are
// within 10%). Its own second order in the static problems is in numeric/integration_statics.cpp.
TEST_CASE("scni: first order in the expansion, second in the bar's period, within 25% of q4 there") {
  test::run_serially();
  const auto expansion = expansion_errors<quadrature::scni<>>();
  const auto bar = bar_errors<quadrature::scni<>>();
  CHECK(rate(expansion, expansion_n, 2) > 0.8);
  CHECK(rate(expansion, expansion_n, 2) < 1.3);
  CHECK(rate(bar, bar_n, 3) > 1.8);
  const auto& q4 = measured().bar.at("q4");
  for (std::size_t k = 0; k < bar_n.size(); ++k) {
    CAPTURE(bar_n[k]);
    CHECK(std::abs(bar[k] / q4[k] - 1.0) < 0.25);
  }
}

}  // namespace test_numeric_integration_convergence
