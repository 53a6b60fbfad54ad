// Several bodies in one case file (tools/runner/case_file/README.md, "bodies" and
// "contact": {"pairs": ...}), run through build_problem and measure as the runner does:
//   - two elastic bars of different impedance (beryllium at +V, steel at -V, plane strain,
//     Poisson ratio 0: 1D bars) touching at t = 0: total momentum is kept to round-off, the
//     beryllium bar leaves after its round trip 2 L / c at 2 v_i - V with v_i = (Z_Be V - Z_st V) /
//     (Z_Be + Z_st) (1D wave theory), each body's mass is its own density times its area, and
//     the histories look at the body they name (at t = 0 the probe at the shared face point reads
//     +V on one body and -V on the other; the extents are the bars' own);
//   - "contact": {"self": true} (every body against every body, itself included) runs as the
//     file's pair (steel, beryllium) with two passes, bit for bit;
//   - bad input: a pair naming an unknown body, "self" with pairs or two_pass or not a boolean,
//     overlapping bodies, two bodies of one name, a wrong constant in the second body: one line
//     each, with the pointer.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/solver/make_solver.hpp>

#include "support/body_momentum.hpp"
#include "support/case_files.hpp"
#include "tools/runner/case_file/build_problem.hpp"
#include "tools/runner/case_file/measure.hpp"

namespace test_unit_case_file_bodies {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;
using test::case_json;
using test::contains;
using test::reports;

namespace {

using contact_t = test::plane_file_contact;
using file_config = test::plane_file_config;

constexpr double V = 1.0, L = 10e-3, H = 1.5e-3;
constexpr double E_be = 287e9, rho_be = 1850.0, E_st = 200e9, rho_st = 7800.0;

case_json bar(const std::string& name, double x0, double E, double rho, double v) {
  return {{"name", name},
          {"shape", {{"rectangle", {{"lower_left_m", {x0, 0.0}}, {"upper_right_m", {x0 + L, H}}, {"particles", {41, 7}}}}}},
          {"material", {{"law", "elastic"}, {"youngs_modulus_Pa", E}, {"poisson_ratio", 0.0}, {"density_kg_m3", rho}}},
          {"initial_velocity_m_s", {v, 0.0}}};
}

// Beryllium on [-L, 0] at +V, steel on [0, L] at -V, each slave against the other.
case_json two_bars(double end_time) {
  return {{"name", "two_bars"},
          {"geometry", "plane_strain"},
          {"method", {{"contact", "effective_mass"}}},
          {"end_time_s", end_time},
          {"bodies", {bar("beryllium", -L, E_be, rho_be, V), bar("steel", 0.0, E_st, rho_st, -V)}},
          {"contact", {{"pairs", {{{"slave", "steel"}, {"master", "beryllium"}}}}, {"two_pass", true}}},
          {"histories",
           {{{"name", "be_face_velocity"},
             {"probe", {{"body", "beryllium"}, {"point_m", {0.0, 0.0}}, {"quantity", "velocity"}, {"component", "x"}}}},
            {{"name", "steel_face_velocity"},
             {"probe", {{"body", "steel"}, {"point_m", {0.0, 0.0}}, {"quantity", "velocity"}, {"component", "x"}}}},
            {{"name", "be_min_x"}, {"extent", {{"body", "beryllium"}, {"of", "min_x"}}}},
            {{"name", "steel_right_x"}, {"extent", {{"body", "steel"}, {"of", "max_x"}, {"on_edge", "right"}}}}}}};
}

double measured(const std::vector<std::pair<std::string, double>>& m, const std::string& name) {
  for (const auto& [key, value] : m)
    if (key == name) return value;
  FAIL("no measure " << name);
  return 0.0;
}

}  // namespace

TEST_CASE("two bars in one case file: momentum, the speed after from wave theory, histories per body") {
  const double c_be = std::sqrt(E_be / rho_be), Z_be = rho_be * c_be, Z_st = rho_st * std::sqrt(E_st / rho_st);
  const double v_i = (Z_be * V - Z_st * V) / (Z_be + Z_st), round_trip = 2.0 * L / c_be;
  const auto description = test::load_document(two_bars(1.6 * round_trip));
  run_options o;
  o.end_time = description.end_time;
  auto s = make_solver<file_config>(runner::case_file::build_problem<contact_t>(description, 1), o);
  REQUIRE(s.bodies() == 2);
  auto momentum = [&](int body) { return test::body_momentum_x(s, body); };  // body -1: both
  const double m_be = momentum(0).second, m_st = momentum(1).second, P0 = momentum(-1).first;
  CHECK(std::abs(m_be - rho_be * L * H) < 1e-9 * m_be);
  CHECK(std::abs(m_st - rho_st * L * H) < 1e-9 * m_st);

  const auto at_start = runner::case_file::measure(s, description, {});
  CHECK(measured(at_start, "be_face_velocity") == doctest::Approx(V));
  CHECK(measured(at_start, "steel_face_velocity") == doctest::Approx(-V));
  CHECK(measured(at_start, "be_min_x") == doctest::Approx(-L));
  CHECK(measured(at_start, "steel_right_x") == doctest::Approx(L));

  double momentum_error = 0.0;
  while (s.time() < o.end_time * (1.0 - 1e-12)) {
    s.step();
    momentum_error = std::max(momentum_error, std::abs(momentum(-1).first - P0) / (m_be * V));
  }
  const double after_be = momentum(0).first / m_be, after_st = momentum(1).first / m_st;
  const double expected_be = 2.0 * v_i - V, expected_st = (P0 - m_be * expected_be) / m_st;
  const auto at_end = runner::case_file::measure(s, description, {});
  MESSAGE("after " << s.time() * 1e6 << " us: beryllium " << after_be << " m/s (wave theory " << expected_be
                   << "), steel " << after_st << " m/s (" << expected_st << "); momentum error " << momentum_error
                   << "; beryllium's left end moved " << (measured(at_end, "be_min_x") + L) * 1e6 << " um");
  CHECK(momentum_error < 1e-12);
  CHECK(std::abs(after_be - expected_be) < 0.03 * std::abs(expected_be));
  CHECK(std::abs(after_st - expected_st) < 0.03 * std::abs(expected_st));
  // The beryllium's free left end moves at +V until the unloading wave reaches it (L / c), then
  // at 2 v_i - V: after t, it has moved V L / c + (2 v_i - V)(t - L / c).
  const double t = s.time(), moved = V * L / c_be + expected_be * (t - L / c_be);
  CHECK(std::abs(measured(at_end, "be_min_x") + L - moved) < 0.05 * std::abs(moved));
}

TEST_CASE("\"self\": true runs as the file's pair (steel, beryllium) with two passes") {
  auto run = [](case_json doc) {
    const auto description = test::load_document(doc);
    run_options o;
    o.end_time = 0.5e-6;
    auto s = make_solver<file_config>(runner::case_file::build_problem<contact_t>(description, 1), o);
    while (s.time() < o.end_time * (1.0 - 1e-12)) s.step();
    return std::tuple{s.coefficients(), s.coefficient_velocities(), s.contact().all_body_pairs(),
                      s.contact().body_pairs().size()};
  };
  case_json all = two_bars(1e-6), declared = two_bars(1e-6);
  all["contact"] = {{"self", true}};
  const auto [d_all, v_all, mode_all, pairs_all] = run(all);
  const auto [d_declared, v_declared, mode_declared, pairs_declared] = run(declared);
  CHECK(mode_all);
  CHECK(!mode_declared);
  CHECK(pairs_all == 4);  // (0, 0), (1, 0), (0, 1), (1, 1)
  CHECK(pairs_declared == 2);
  CHECK(d_all == d_declared);  // Eigen's == on each entry: bit for bit, but for -0 and +0
  CHECK(v_all == v_declared);
}

TEST_CASE("bad input: unknown body in a pair, \"self\" with pairs, overlap, a name twice, a bad constant") {
  case_json doc = two_bars(1e-6);
  doc["contact"]["pairs"][0]["master"] = "berylium";
  CHECK(reports(test::load_error(doc), "/contact/pairs/0/master", "no body 'berylium'; did you mean 'beryllium'?"));

  doc = two_bars(1e-6);
  doc["contact"]["self"] = true;
  CHECK(reports(test::load_error(doc), "/contact/pairs", "\"self\": true already puts every body against every body"));

  doc = two_bars(1e-6);
  doc["contact"] = {{"self", true}, {"two_pass", true}};
  CHECK(reports(test::load_error(doc), "/contact/two_pass", "already takes every pair both ways"));

  doc = two_bars(1e-6);
  doc["contact"] = {{"self", "yes"}};
  CHECK(reports(test::load_error(doc), "/contact/self", "expected true or false"));

  // A body with itself is self-contact now, not an error.
  doc = two_bars(1e-6);
  doc["contact"]["pairs"][0]["master"] = "steel";
  CHECK(test::load_error(doc).empty());

  doc = two_bars(1e-6);
  doc["bodies"][1]["name"] = "beryllium";
  CHECK(reports(test::load_error(doc), "/bodies/1/name", "a second body named 'beryllium'"));

  doc = two_bars(1e-6);
  doc["bodies"][1]["material"]["youngs_modulus_Pa"] = -200e9;
  CHECK(reports(test::load_error(doc), "/bodies/1/material/youngs_modulus_Pa", "must be positive"));

  doc = two_bars(1e-6);
  doc["contact"].erase("pairs");
  CHECK(reports(test::load_error(doc), "/contact/two_pass", "no \"pairs\" of bodies in contact"));

  // Overlap is found on the cells when the problem is built; touching (above) is allowed.
  doc = two_bars(1e-6);
  doc["bodies"][1]["shape"]["rectangle"]["lower_left_m"] = {-0.5e-3, 0.0};
  const auto overlapping = test::load_document(doc);
  const std::string e =
      test::error_message([&] { runner::case_file::build_problem<contact_t>(overlapping, 1); });
  MESSAGE(e);
  CHECK(reports(e, "/bodies/1/shape", "body 'steel' overlaps body 'beryllium' at t = 0"));
  CHECK(std::count(e.begin(), e.end(), '\n') == 0);
}

}  // namespace test_unit_case_file_bodies
