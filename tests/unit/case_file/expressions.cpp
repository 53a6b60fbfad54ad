// Fields given as expressions in case files (tools/runner/case_file/expressions.hpp and the
// README's "Expressions"):
//   - expressions that are numbers ("-1.7", "-v" with a constant v) and a body force that names
//     x but does not vary run bit for bit as the numbers: particle positions after 30 steps of a
//     small block forging, the tool moving as a velocity_expression of constants;
//   - an elastic disc set spinning by ["-w * y", "w * x"]: each particle's velocity at t = 0 is
//     the rotation's, the angular momentum sum m (x v_y - y v_x) starts at w sum m |X|^2 and is
//     kept to round-off (the central difference keeps it exactly for torque-free internal
//     forces), and the disc turns by about w t;
//   - a tool ramped to speed, -v min(1, t / T), and one at A sin(omega t): velocity and
//     displacement against the closed forms, also as the solver moves the tool, and the
//     displacement a function of t alone (a restart moves the tool as the uninterrupted run);
//   - a body force -k t on a free block: every particle's velocity is -k t^2 / 2 (the
//     trapezoidal rule of the central difference is exact for a force linear in t);
//   - each mistake: one line with its pointer and the fix.
#include <doctest/doctest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/solver/make_solver.hpp>

#include "support/case_files.hpp"
#include "tools/runner/case_file/build_problem.hpp"
#include "tools/runner/case_file/make_tools.hpp"
#include "tools/runner/case_file/measure.hpp"

namespace test_unit_case_file_expressions {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;
using test::case_json;
using test::contains;
using test::load_error;
using test::reports;

namespace {

using contact_t = test::plane_file_contact;
using file_config = test::plane_file_config;

std::size_t lines(const std::string& message) {
  return message.empty() ? 0 : 1 + std::count(message.begin(), message.end(), '\n');
}

// The paper's block forging, 9 x 9 particles, with a velocity and a body force of its own.
case_json small_block() {
  case_json doc = test::paper_case_document("block_forging");
  doc["bodies"][0]["shape"]["rectangle"]["particles"] = {9, 9};
  doc["bodies"][0]["initial_velocity_m_s"] = {0.3, -1.7};
  doc["bodies"][0]["body_force_m_s2"] = {0.0, -9.81e3};
  return doc;
}

// Particle positions after `steps` steps of the case.
std::vector<vec2> positions_after(const case_json& doc, int steps) {
  const auto c = test::load_document(doc);
  run_options o;
  o.end_time = c.end_time;
  auto s = make_solver<file_config>(runner::case_file::build_problem<contact_t>(c, 1), o);
  for (int k = 0; k < steps; ++k) s.step();
  return s.particle_positions();
}

bool identical(const std::vector<vec2>& a, const std::vector<vec2>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t I = 0; I < a.size(); ++I)
    for (int k = 0; k < 2; ++k)
      if (std::bit_cast<std::uint64_t>(a[I][k]) != std::bit_cast<std::uint64_t>(b[I][k])) return false;
  return true;
}

// A disc of radius R about the origin (a 32-gon, counter-clockwise), elastic steel.
case_json spinning_disc(double R, double w, double end_time) {
  case_json vertices = case_json::array();
  for (int k = 0; k < 32; ++k) {
    const double a = 2.0 * M_PI * k / 32.0;
    vertices.push_back({R * std::cos(a), R * std::sin(a)});
  }
  return {{"name", "disc"},
          {"geometry", "plane_strain"},
          {"constants", {{"w", w}}},
          {"end_time_s", end_time},
          {"bodies",
           {{{"name", "disc"},
             {"shape", {{"polygon", {{"vertices_m", vertices}, {"spacing_m", R / 8.0}}}}},
             {"material", {{"law", "elastic"}, {"youngs_modulus_Pa", 200e9}, {"poisson_ratio", 0.3},
                           {"density_kg_m3", 7800}}},
             {"initial_velocity_m_s", {"-w * y", "w * x"}}}}}};
}

// A block under a tool moving by `velocity` (expressions of t), with a tool_displacement history.
case_json block_under(const case_json& velocity) {
  case_json doc = small_block();
  doc["constants"] = {{"v", 10.0}, {"T", 1e-4}};
  doc["tools"][1]["motion"] = {{"type", "velocity_expression"}, {"velocity_m_s", velocity}};
  doc["histories"] = {{{"name", "top_y"}, {"tool_displacement", {{"tool", "top_tool"}, {"component", "y"}}}}};
  return doc;
}

}  // namespace

TEST_CASE("expressions that are numbers, and a body force of x that does not vary, run bit for bit as numbers") {
  const case_json numbers = small_block();
  case_json written = small_block();
  written["constants"] = {{"v", 10.0}};
  written["bodies"][0]["initial_velocity_m_s"] = {"0.3", "-1.7"};
  written["bodies"][0]["body_force_m_s2"] = {"0 * x", "-9.81e3 + 0 * x * t"};  // a field: evaluated per particle
  written["tools"][0]["motion"] = {{"type", "constant_velocity"}, {"velocity_m_s", {"0", "v"}}};
  written["tools"][1]["motion"] = {{"type", "velocity_expression"}, {"velocity_m_s", {0, "-v"}}};

  const auto c = test::load_document(written);
  CHECK(c.bodies[0].initial_velocity.value == vec2(0.3, -1.7));  // muparser reads numbers as JSON does
  CHECK(!c.bodies[0].initial_velocity.varies());
  CHECK(c.bodies[0].body_force.varies());
  CHECK(!c.tools[1].motion.velocity_expression.varies());
  const auto p = runner::case_file::build_problem<contact_t>(c, 1);
  REQUIRE(bool(p.body_force_field));  // the library's field path, not body_force
  CHECK(p.body_force_field(vec2(0.1, 0.2), 3e-3) == vec2(0.0, -9.81e3));

  const auto a = positions_after(numbers, 30), b = positions_after(written, 30);
  CHECK(identical(a, b));
  // The comparison can fail: a velocity off by 1e-7 of itself moves the particles.
  case_json nudged = written;
  nudged["bodies"][0]["initial_velocity_m_s"][1] = "-1.7000002";
  CHECK(!identical(a, positions_after(nudged, 30)));
}

TEST_CASE("a disc spinning at [-w y, w x]: the rotation's velocity at every particle, angular momentum kept") {
  const double R = 10e-3, w = 2e4;  // rim speed 200 m/s
  const auto c = test::load_document(spinning_disc(R, w, 1.0));
  run_options o;
  o.end_time = c.end_time;
  auto s = make_solver<file_config>(runner::case_file::build_problem<contact_t>(c, 1), o);
  const auto& X = s.model().particles.position;
  const auto n = s.model().particle_count();
  REQUIRE(n > 100);

  // At t = 0 the coefficients are the expression at X_I, and the physical velocity, a linear
  // field, is reproduced at every particle.
  const auto v_particles = s.particle_velocities();
  double worst = 0.0;
  for (index_t I = 0; I < n; ++I) {
    const vec2 rotation(-w * X[I].y(), w * X[I].x());
    CHECK(s.coefficient_velocities()[I] == rotation);
    worst = std::max(worst, (v_particles[I] - rotation).norm());
  }
  CHECK(worst < 1e-11 * w * R);

  // L = sum m_I (x_I v_I,y - y_I v_I,x) with x_I = X_I + d_I: w sum m |X|^2 at t = 0.
  const auto angular_momentum = [&] {
    double L = 0.0;
    for (index_t I = 0; I < n; ++I) {
      const vec2 x = X[I] + s.coefficients()[I], v = s.coefficient_velocities()[I];
      L += s.mass()[I] * (x.x() * v.y() - x.y() * v.x());
    }
    return L;
  };
  double inertia = 0.0;
  for (index_t I = 0; I < n; ++I) inertia += s.mass()[I] * X[I].squaredNorm();
  const double L0 = angular_momentum();
  CHECK(std::abs(L0 - w * inertia) < 1e-13 * w * inertia);

  // The particle starting at (R, 0) (the polygon's vertex) turns by about w t.
  index_t rim = 0;
  for (index_t I = 0; I < n; ++I)
    if ((X[I] - vec2(R, 0.0)).norm() < (X[rim] - vec2(R, 0.0)).norm()) rim = I;
  REQUIRE((X[rim] - vec2(R, 0.0)).norm() < 1e-12);
  double drift = 0.0;
  for (int k = 0; k < 300; ++k) {
    s.step();
    drift = std::max(drift, std::abs(angular_momentum() - L0));
  }
  const vec2 at = s.particle_positions()[rim];
  const double turned = std::atan2(at.y(), at.x());
  MESSAGE("after " << s.steps() << " steps (" << s.time() * 1e6 << " us): turned " << turned << " rad (w t = "
                   << w * s.time() << "), radius " << at.norm() / R << " R, angular momentum drift " << drift / L0);
  CHECK(drift < 1e-12 * L0);
  CHECK(std::abs(turned - w * s.time()) < 0.02 * w * s.time());
  CHECK(w * s.time() > 0.3);  // a real turn, not a few micro-radians
}

TEST_CASE("a tool ramped to speed, and one oscillating, follow the closed forms") {
  const double v = 10.0, T = 1e-4;
  const runner::case_file::constant_table constants{{"v", v}, {"T", T}, {"A", 3.0}, {"f", 2e4}};
  const auto motion = [&](const std::array<std::string, 2>& velocity) {
    runner::case_file::tool_motion_description m;
    m.type = "velocity_expression";
    m.velocity_expression = {vec2::Zero(), velocity, "/tools/0/motion/velocity_m_s"};
    return runner::case_file::make_motion(m, constants, "case.json");
  };
  // v(t) = -v min(1, t / T): u = -v t^2 / (2 T) until T, then -v (t - T / 2).
  const auto ramp = motion({"", "-v * min(1, t / T)"});
  const auto u_ramp = [&](double t) { return t <= T ? -v * t * t / (2.0 * T) : -v * (t - 0.5 * T); };
  for (double t : {0.0, 1e-9, 0.3 * T, T, 1.0000001 * T, 2.5 * T, 40.0 * T}) {
    CAPTURE(t);
    CHECK(ramp.velocity(t) == vec2(0.0, -v * std::min(1.0, t / T)));
    CHECK(ramp.displacement(t).x() == 0.0);
    CHECK(std::abs(ramp.displacement(t).y() - u_ramp(t)) <= 1e-13 * v * t);
  }
  // A function of t alone: the same bits whatever was asked before.
  const auto fresh = motion({"", "-v * min(1, t / T)"});
  CHECK(std::bit_cast<std::uint64_t>(fresh.displacement(2.5 * T).y()) ==
        std::bit_cast<std::uint64_t>(ramp.displacement(2.5 * T).y()));
  // v(t) = A sin(2 pi f t) in x: u = A (1 - cos(2 pi f t)) / (2 pi f), over many periods.
  const auto wave = motion({"A * sin(2 * 3.141592653589793 * f * t)", ""});
  const double omega = 2.0 * M_PI * 2e4;
  for (double t : {1e-6, 1.3e-5, 2.5e-4, 1.01e-3}) {
    CAPTURE(t);
    CHECK(std::abs(wave.displacement(t).x() - 3.0 * (1.0 - std::cos(omega * t)) / omega) < 1e-12 * 3.0 / omega);
  }

  // The same ramp as the solver moves the top tool of a block: the history and the tool.
  const auto c = test::load_document(block_under({"0", "-v * min(1, t / T)"}));
  run_options o;
  o.end_time = 2.0 * T;
  auto s = make_solver<file_config>(runner::case_file::build_problem<contact_t>(c, 1), o);
  for (double stop : {0.5 * T, 1.5 * T, 2.0 * T}) {
    while (s.time() < stop * (1.0 - 1e-12)) s.step();
    CAPTURE(s.time());
    const auto m = runner::case_file::measure(s, c, {});
    REQUIRE(m.size() == 1);
    CHECK(std::abs(m[0].second - u_ramp(s.time())) <= 1e-13 * v * s.time());
    CHECK(s.contact().tools()[1].velocity(s.time()).y() == -v * std::min(1.0, s.time() / T));
  }
}

TEST_CASE("a body force ramped in time, b = -k t, on a free block: v = -k t^2 / 2 at every particle") {
  // No tool, no stress: every particle accelerates as b(t). The step's velocity update is the
  // trapezoidal rule on b(t(n)), b(t(n+1)) (docs/method.md 5.4), exact for b linear in t.
  const double k = 2e7;  // m/s^3
  case_json doc = small_block();
  doc["tools"] = case_json::array();
  doc["histories"] = case_json::array();
  doc["constants"] = {{"k", k}};
  doc["bodies"][0]["initial_velocity_m_s"] = {0, 0};
  doc["bodies"][0]["body_force_m_s2"] = {"0", "-k * t"};
  const auto c = test::load_document(doc);
  run_options o;
  o.end_time = c.end_time;
  auto s = make_solver<file_config>(runner::case_file::build_problem<contact_t>(c, 1), o);
  for (int step = 0; step < 40; ++step) s.step();
  const double t = s.time(), expected = -0.5 * k * t * t;
  double worst = 0.0;
  for (const vec2& v : s.particle_velocities()) worst = std::max(worst, (v - vec2(0.0, expected)).norm());
  MESSAGE("t = " << t * 1e6 << " us: v = " << expected << " m/s, largest difference " << worst << " m/s");
  CHECK(std::abs(expected) > 1.0);
  CHECK(worst < 1e-12 * std::abs(expected));
}

TEST_CASE("expression mistakes: one line each, with the pointer and the fix") {
  const auto error_of = [](const case_json& doc) { return load_error(doc); };
  const auto build_error = [](const case_json& doc) {
    return test::error_message([&] {
      runner::case_file::build_problem<contact_t>(test::load_document(doc), 1);
    });
  };
  case_json doc = small_block();
  doc["bodies"][0]["initial_velocity_m_s"] = {"0", "2 +* x"};
  std::string e = error_of(doc);
  CHECK(reports(e, "/bodies/0/initial_velocity_m_s/1",
                "the expression \"2 +* x\" does not parse: Unexpected operator \"*\" found at position 3 (after \"2 +\")"));
  CHECK(lines(e) == 1);

  doc = small_block();
  doc["constants"] = {{"w", 100}};
  doc["bodies"][0]["initial_velocity_m_s"] = {"-w * z", "w * x"};
  e = error_of(doc);
  CHECK(reports(e, "/bodies/0/initial_velocity_m_s/0",
                "names 'z', neither a variable here nor a constant; the names allowed here are the variables x, y and "
                "the constants w"));
  CHECK(lines(e) == 1);

  doc = small_block();
  doc["bodies"][0]["body_force_m_s2"] = {"0", "-9.81 * r"};
  CHECK(reports(error_of(doc), "/bodies/0/body_force_m_s2/1", "the variables x, y, t (the file gives no \"constants\")"));

  doc = small_block();
  doc["tools"][1]["motion"] = {{"type", "velocity_expression"}, {"velocity_m_s", {"0", "-10 * x"}}};
  e = error_of(doc);
  CHECK(reports(e, "/tools/1/motion/velocity_m_s/1", "names 'x'"));
  CHECK(reports(e, "/tools/1/motion/velocity_m_s/1", "the variables t"));

  doc = small_block();
  doc["tools"][1]["motion"] = {{"type", "constant_velocity"}, {"velocity_m_s", {"0", "-10 * t"}}};
  CHECK(reports(error_of(doc), "/tools/1/motion/velocity_m_s/1", "no name is allowed here"));

  doc = small_block();
  doc["tools"][1]["motion"] = {{"type", "velocity_expression"}, {"velocity_m_s", {"0", "-1e-3 / t"}}};
  e = error_of(doc);
  CHECK(reports(e, "/tools/1/motion/velocity_m_s/1", "the expression \"-1e-3 / t\" gives -inf at t = 0 s; make it finite"));
  CHECK(lines(e) == 1);

  doc = small_block();
  doc["constants"] = {{"w", "fast"}, {"x", 2}, {"2w", 1}, {"sin", 1}};
  e = error_of(doc);
  CHECK(reports(e, "/constants/w", "expected a number, got a string \"fast\""));
  CHECK(reports(e, "/constants/x", "the constant 'x' has the name of a variable (x, y, t); rename it"));
  CHECK(reports(e, "/constants/2w", "'2w' cannot name a constant"));
  CHECK(reports(e, "/constants/sin", "muparser's own functions"));
  CHECK(lines(e) == 4);

  doc = small_block();
  doc["bodies"][0]["initial_velocity_m_s"] = {"0"};
  CHECK(reports(error_of(doc), "/bodies/0/initial_velocity_m_s",
                "expected [x, y]: two numbers, or expressions (strings) of x, y, got 1 components"));
  doc["bodies"][0]["initial_velocity_m_s"] = {0, true};
  CHECK(reports(error_of(doc), "/bodies/0/initial_velocity_m_s/1", "expected a number or an expression"));
  doc["bodies"][0]["initial_velocity_m_s"] = {"sqrt(-1)", 0};
  CHECK(reports(error_of(doc), "/bodies/0/initial_velocity_m_s/0", "gives -nan; give a finite value"));

  // Values that are not finite at a particle are found when the body is built.
  doc = small_block();  // the block spans x in [-0.25, 0.25], y in [0, 0.5]
  doc["bodies"][0]["initial_velocity_m_s"] = {"0", "1 / x"};
  e = build_error(doc);
  CHECK(reports(e, "/bodies/0/initial_velocity_m_s/1",
                "the expression \"1 / x\" gives inf at the reference point (0, 0) m; make it finite over the body"));
  CHECK(lines(e) == 1);
  doc = small_block();
  doc["bodies"][0]["body_force_m_s2"] = {"sqrt(0.1 - y)", "0"};
  e = build_error(doc);
  CHECK(reports(e, "/bodies/0/body_force_m_s2/0", "gives -nan at the reference point (-0.25, 0.125) m at t = 0 s"));

  // ... and those that turn up later in the run stop it with the same line.
  doc = small_block();
  doc["bodies"][0]["body_force_m_s2"] = {"0", "sqrt(1e-6 - t) + 0 * x"};
  const auto p = runner::case_file::build_problem<contact_t>(test::load_document(doc), 1);
  CHECK(contains(test::error_message([&] { p.body_force_field(vec2(0.1, 0.2), 2e-6); }),
                 "case.json: /bodies/0/body_force_m_s2/1: the expression \"sqrt(1e-6 - t) + 0 * x\" gives -nan at the "
                 "reference point (0.1, 0.2) m at t = 2e-06 s"));
  doc = block_under({"0", "sqrt(1e-6 - t)"});
  const auto tools = runner::case_file::make_tools(test::load_document(doc));
  CHECK(contains(test::error_message([&] { tools[1].displacement(2e-6); }),
                 "case.json: /tools/1/motion/velocity_m_s/1: the expression \"sqrt(1e-6 - t)\" gives -nan at t ="));
}

}  // namespace test_unit_case_file_expressions
