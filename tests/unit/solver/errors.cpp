// Bad input is reported clearly, naming the problem: bad elastic constants (the parameter is
// named), run options, a forced time step above the stable limit, particles that do not match
// the cells, and a body that inverts during the run (the message gives step, time and point).

#include <doctest/doctest.h>

#include <limits>

#include "support/solver_fixtures.hpp"

namespace test_unit_solver_errors {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

namespace {
using cfg = config<kernel::cubic_spline, correction::linear, quadrature::q4, geometry::plane_strain,
                   material::elastic, contact::none>;
using j2_cfg = cfg::with_material<material::j2_plasticity<material::hardening::linear>>;
const vec2 lo(0, 0), hi(1e-2, 5e-3);
const Eigen::Vector2i n(5, 3);

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const error& e) {
    return e.what();
  }
  return "(no error)";
}
}  // namespace

TEST_CASE("elastic constants name the bad parameter") {
  auto elastic = [](double E, double nu, double rho) {
    return message_of([=] { material::elastic m(material::elastic_constants{E, nu, rho}); });
  };
  CHECK(elastic(0.0, 0.3, 7800).find("youngs_modulus") != std::string::npos);
  CHECK(elastic(-1e9, 0.3, 7800).find("youngs_modulus") != std::string::npos);
  CHECK(elastic(200e9, 0.3, 0.0).find("density") != std::string::npos);
  CHECK(elastic(200e9, 0.3, -1.0).find("density") != std::string::npos);
  CHECK(elastic(200e9, 0.5, 7800).find("poisson_ratio") != std::string::npos);
  CHECK(elastic(200e9, -1.0, 7800).find("poisson_ratio") != std::string::npos);
  CHECK(elastic(200e9, 0.7, 7800).find("poisson_ratio") != std::string::npos);
  CHECK(elastic(200e9, std::numeric_limits<double>::quiet_NaN(), 7800).find("poisson_ratio") != std::string::npos);
  CHECK(elastic(200e9, 0.49, 7800) == "(no error)");
  CHECK(elastic(200e9, -0.99, 7800) == "(no error)");
  const auto j2 = message_of([] {
    material::j2_plasticity<material::hardening::linear> m({200e9, 0.6, 7800.0}, {400e6, 1e8});
  });
  CHECK(j2.find("poisson_ratio") != std::string::npos);
  // Through the fixture that builds a whole problem.
  CHECK(message_of([] { test::grid_problem<cfg>(lo, hi, n, {200e9, 0.3, 0.0}); }).find("density") != std::string::npos);
}

TEST_CASE("run options") {
  auto with = [](auto change) {
    return message_of([&] {
      run_options o;
      change(o);
      auto s = make_solver<cfg>(test::grid_problem<cfg>(lo, hi, n), o);
    });
  };
  CHECK(with([](run_options& o) { o.time_step_fraction = 1.5; }).find("time step fraction") != std::string::npos);
  CHECK(with([](run_options& o) { o.end_time = -1.0; }).find("end time") != std::string::npos);
  CHECK(with([](run_options& o) { o.time_step_update_interval = 0; }).find("update interval") != std::string::npos);
}

TEST_CASE("a forced time step above the stable limit") {
  run_options probe;
  auto s = make_solver<cfg>(test::grid_problem<cfg>(lo, hi, n), probe);
  const double stable = s.time_step() / probe.time_step_fraction;
  run_options o;
  o.fixed_time_step = 1.5 * stable;
  const auto m = message_of([&] { auto t = make_solver<cfg>(test::grid_problem<cfg>(lo, hi, n), o); });
  CHECK(m.find("exceeds the stable limit") != std::string::npos);
  CHECK(m.find("fixed_time_step") != std::string::npos);  // names the fix
  // Just below the limit is accepted and used as given.
  o.fixed_time_step = 0.9 * stable;
  auto t = make_solver<cfg>(test::grid_problem<cfg>(lo, hi, n), o);
  CHECK(t.time_step() == o.fixed_time_step);
}

TEST_CASE("particles inconsistent with the cells") {
  auto p = test::grid_problem<cfg>(lo, hi, n);
  p.mesh = make_grid_mesh(lo, vec2(2e-2, 5e-3), n);  // twice as long as the particle set
  const auto m = message_of([&] { auto s = make_solver<cfg>(std::move(p), run_options{}); });
  CHECK(m.find("cells") != std::string::npos);
  CHECK(m.find("particle") != std::string::npos);
}

TEST_CASE("the body inverts: the error gives step, time and point") {
  auto check = [&]<class C>(std::function<vec2(const vec2&)> v) {
    auto p = test::grid_problem<C>(lo, hi, n);
    p.initial_velocity = std::move(v);
    run_options o;
    o.end_time = 1.0;
    auto s = make_solver<C>(std::move(p), o);
    const auto m = message_of([&] {
      for (int k = 0; k < 5; ++k) s.step();
    });
    MESSAGE(m);
    CHECK(m.find("step ") != std::string::npos);
    CHECK(m.find("t = ") != std::string::npos);
    CHECK(m.find("quadrature point") != std::string::npos);
    CHECK(m.find("X = ") != std::string::npos);
    // Every point fails in these motions: the first one is named, whatever the thread count
    // (the force loop records each tile's first failure, solver/point_materials.hpp).
    CHECK(m.find("quadrature point 0 (") != std::string::npos);
  };
  // u_x = -k dt (x - x_c) with k dt >> 1 folds the block over itself: det F = 1 - k dt < 0.
  const double k = 1e4 * 5800.0 / 2.5e-3;
  check.operator()<cfg>([k](const vec2& X) { return vec2(-k * (X[0] - 5e-3), 0.0); });
  check.operator()<j2_cfg>([k](const vec2& X) { return vec2(-k * (X[0] - 5e-3), 0.0); });
  // A NaN velocity gives a NaN det F.
  check.operator()<cfg>([](const vec2&) { return vec2(std::numeric_limits<double>::quiet_NaN(), 0.0); });
#ifdef _OPENMP
  const int threads = omp_get_max_threads();
  omp_set_num_threads(2);
  check.operator()<j2_cfg>([k](const vec2& X) { return vec2(-k * (X[0] - 5e-3), 0.0); });
  omp_set_num_threads(threads);
#endif
}

}  // namespace test_unit_solver_errors
