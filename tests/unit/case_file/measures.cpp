// Runs from case files give the typed cases' numbers bit for bit:
//   - taylor_bar.json and the typed Taylor bar, each run for 5 us: the same measures at every
//     observation and the same particle positions at the end (two solver types: the case
//     file's material is j2_plasticity<case_file::hardening_law>);
//   - the wheel and block histories evaluated on one solver give exactly what the typed
//     cases' measure() gives on it (the arithmetic of each history kind; the block is run
//     axisymmetric, shifted to r >= 0, only to share the solver type of this program).
#include <doctest/doctest.h>

#include <bit>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/solver/make_solver.hpp>

#include "cases/block_forging.hpp"
#include "cases/taylor_bar.hpp"
#include "cases/wheel_forging.hpp"
#include "support/case_file_solver_instance.hpp"
#include "support/case_files.hpp"
#include "support/solver_fixtures.hpp"
#include "tools/runner/case_file/build_problem.hpp"
#include "tools/runner/case_file/measure.hpp"

namespace test_unit_case_file_measures {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

namespace {

using contact_t = contact::particle_to_segment<contact::enforcement::paper, contact::friction::coulomb>;
template <class Material>
using method = config<kernel::cubic_spline, correction::linear, quadrature::q2, geometry::axisymmetric, Material, contact_t>;
using typed_config = method<cases::taylor_bar::material_type>;
using file_config = method<runner::case_file::material_type>;

using measures = std::vector<std::pair<std::string, double>>;

// Equal as bit patterns (so -0 and 0, or two NaNs, are told apart or matched exactly).
void check_identical(const measures& a, const measures& b) {
  REQUIRE(a.size() == b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    CAPTURE(a[k].first);
    CAPTURE(a[k].second);
    CAPTURE(b[k].second);
    CHECK(a[k].first == b[k].first);
    CHECK(std::bit_cast<std::uint64_t>(a[k].second) == std::bit_cast<std::uint64_t>(b[k].second));
  }
}

// Runs a solver to end_time, recording measure(s, reactions) every 10 steps and at the end.
template <class Config, class Measure>
std::pair<std::vector<measures>, std::vector<vec2>> run(problem_for<Config> p, double end_time, Measure&& measure) {
  run_options o;
  o.end_time = end_time;
  auto s = make_solver<Config>(std::move(p), o);
  std::vector<measures> rows;
  s.run([&](const auto& s) { rows.push_back(measure(s, s.contact().reactions())); }, 10);
  return {rows, s.particle_positions()};
}

}  // namespace

TEST_CASE("taylor_bar.json runs as the typed Taylor bar, bit for bit") {
  test::run_serially();
  const double end = 5e-6;
  cases::taylor_bar::parameters params;
  const auto typed = run<typed_config>(cases::taylor_bar::build<contact_t>(params, 1), end, [&](const auto& s, const auto& f) {
    return cases::taylor_bar::measure(s, params, f);
  });
  const auto description = runner::case_file::load_case_file(test::paper_case_file("taylor_bar"));
  const auto problem = runner::case_file::build_problem<contact_t>(description, 1);
  const auto file = run<file_config>(problem, end, [&](const auto& s, const auto& f) {
    return runner::case_file::measure(s, description, f);
  });
  REQUIRE(typed.first.size() == file.first.size());
  CHECK(typed.first.size() > 10);
  for (std::size_t r = 0; r < typed.first.size(); ++r) check_identical(typed.first[r], file.first[r]);
  CHECK(typed.second == file.second);
  MESSAGE("radius ", typed.first.back()[0].second, " mm, height ", typed.first.back()[1].second, " mm after 5 us");
}

TEST_CASE("the wheel's histories are the typed wheel's measures") {
  test::run_serially();
  const cases::wheel_forging::parameters params;
  const auto description = runner::case_file::load_case_file(test::paper_case_file("wheel_forging"));
  bool forced = false;
  run<file_config>(runner::case_file::build_problem<contact_t>(description, 1), 4e-6, [&](const auto& s, const auto& f) {
    const std::vector<vec2> force(f.begin(), f.end());
    check_identical(cases::wheel_forging::measure(s, params, force), runner::case_file::measure(s, description, force));
    forced = forced || force[0].y() != 0.0;
    return measures{};
  });
  CHECK(forced);  // the punch force was compared while non-zero
}

TEST_CASE("the block's histories are the typed block's measures") {
  test::run_serially();
  const cases::block_forging::parameters params;
  const auto description = test::load_document(test::paper_case_document("block_forging"),
                                               {{"/geometry", "axisymmetric"},
                                                {"/bodies/0/shape/rectangle/lower_left_m", "[0, 0]"},
                                                {"/bodies/0/shape/rectangle/upper_right_m", "[0.5, 0.5]"}});
  bool forced = false;
  run<file_config>(runner::case_file::build_problem<contact_t>(description, 1), 2e-4, [&](const auto& s, const auto& f) {
    const std::vector<vec2> force(f.begin(), f.end());
    check_identical(cases::block_forging::measure(s, params, force), runner::case_file::measure(s, description, force));
    forced = forced || force[1].y() != 0.0;
    return measures{};
  });
  CHECK(forced);
}

}  // namespace test_unit_case_file_measures
