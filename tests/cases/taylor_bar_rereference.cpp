// The paper's Taylor bar (cases/taylor_bar.hpp) re-referenced (docs/method.md section 5.8)
// against the Lagrangian run of the same method: the kernels rebuilt whenever a point's principal
// stretch since the last rebuild exceeds the threshold, which fires at least three times; the
// final height and impact-face radius agree with the Lagrangian run's within 0.3% and 1%, mass is
// exact (the masses are the first model's), the energy ledger balances with its remap term, and
// the bar's momentum obeys Newton's law through every re-reference (the wall's impulse).
#include <doctest/doctest.h>

#include <cmath>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/solver/make_solver.hpp>

#include "cases/taylor_bar.hpp"

namespace test_cases_taylor_bar_rereference {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

namespace {

using tb = cases::taylor_bar;
using contact_t = contact::particle_to_segment<contact::enforcement::paper, contact::friction::coulomb>;
using cfg = config<kernel::cubic_spline, correction::linear, quadrature::q2, tb::geometry_type, tb::material_type,
                   contact_t>;

struct outcome {
  double height = 0.0, radius = 0.0, momentum_error = 0.0, balance_error = 0.0, remap = 0.0, kinetic0 = 0.0;
  index_t rereferences = 0;
  bool mass_kept = false;
};

outcome run(double end_time, rereference_policy when) {
  tb::parameters p;
  p.end_time_s = end_time;
  run_options o;
  o.end_time = end_time;
  o.rereference = when;
  auto s = make_solver<cfg>(tb::build<contact_t>(p, 1), o);
  const std::vector<double> mass = s.mass();
  const auto momentum_z = [&] {
    double P = 0.0;
    for (index_t I = 0; I < s.model().particle_count(); ++I) P += s.mass()[I] * s.coefficient_velocities()[I].y();
    return P;
  };
  const double P0 = momentum_z();
  s.run();
  outcome r;
  for (const auto& [name, value] : tb::measure(s, p, {})) {
    if (name == "height_mm") r.height = value;
    if (name == "radius_mm") r.radius = value;
  }
  double total_mass = 0.0;
  for (double m : mass) total_mass += m;
  r.momentum_error = std::abs(momentum_z() - P0 + s.tool_impulses()[0].y()) / (total_mass * p.velocity_m_s);
  r.balance_error = s.energy().balance_error();
  r.remap = s.energy().remap;
  r.kinetic0 = s.energy().initial_kinetic;
  r.rereferences = s.rereferences();
  r.mass_kept = s.mass() == mass;
  return r;
}

}  // namespace

TEST_CASE("Taylor bar: re-referenced by stretch, the Lagrangian run's height and radius") {
  const double end = 80e-6;
  const outcome lagrangian = run(end, {});
  const outcome rebuilt = run(end, {.max_stretch = 1.5, .every_steps = 0});
  CAPTURE(rebuilt.rereferences);
  CHECK(rebuilt.rereferences >= 3);
  CHECK(rebuilt.mass_kept);
  CHECK(rebuilt.height == doctest::Approx(lagrangian.height).epsilon(0.003));
  CHECK(rebuilt.radius == doctest::Approx(lagrangian.radius).epsilon(0.01));
  CHECK(rebuilt.momentum_error < 1e-9);
  CHECK(rebuilt.balance_error < 1e-2);
  CHECK(std::abs(rebuilt.remap) < 1e-2 * rebuilt.kinetic0);
}

}  // namespace test_cases_taylor_bar_rereference
