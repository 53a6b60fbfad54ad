// Rigid motions give zero stress: a translation and a 90 degree rotation u = (R - I) X, put on
// the coefficients (exactly representable: linear fields), leave every Cauchy stress and every
// internal force at round-off, for the elastic law and J2 plasticity (whose elastic predictor
// must see f b_e f^T = R R^T = I). Linear momentum: for any deformed state, in plane strain,
// sum_I f_int,I = sum_q P_q (sum_I grad N_I(X_q)) w_q = 0 because the RK functions are a
// partition of unity.

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "support/solver_fixtures.hpp"

namespace test_unit_solver_rigid_body {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

namespace {

const auto c = test::steel_like();
const vec2 lo(-0.3, 0.1), hi(0.7, 0.6);
const Eigen::Vector2i n(9, 6);
const double h = 0.1;

template <class Cfg>
void check_zero_stress(const std::function<vec2(const vec2&)>& u) {
  auto s = test::solver_at<Cfg>(test::grid_problem<Cfg>(lo, hi, n, c), u, test::tiny_step(h, c));
  double worst_stress = 0.0, worst_force = 0.0;
  for (index_t q = 0; q < s.model().point_count(); ++q)
    worst_stress = std::max(worst_stress, s.point_cauchy_stress(q).cwiseAbs().maxCoeff());
  for (const vec2& f : s.internal_force()) worst_force = std::max(worst_force, f.cwiseAbs().maxCoeff());
  // Scales: stress E, internal force E h (per metre of depth).
  CHECK(worst_stress / c.youngs_modulus < 1e-11);
  CHECK(worst_force / (c.youngs_modulus * h) < 1e-11);
  // The displacement really is the rigid motion (so the test cannot pass with u = 0).
  const auto x = s.particle_positions();
  double worst_position = 0.0;
  for (index_t I = 0; I < s.model().particle_count(); ++I)
    worst_position = std::max(worst_position, (x[I] - s.model().particles.position[I] - u(s.model().particles.position[I])).norm());
  CHECK(worst_position < 1e-12);
}

template <class Cfg>
void check_rigid() {
  SUBCASE("translation") { check_zero_stress<Cfg>([](const vec2&) { return vec2(3.5, -12.0); }); }
  SUBCASE("rotation by 90 degrees") {
    mat2 R;
    R << 0.0, -1.0, 1.0, 0.0;
    check_zero_stress<Cfg>([R](const vec2& X) -> vec2 { return (R - mat2::Identity()) * X + vec2(0.2, 0.1); });
  }
  SUBCASE("rotation by 137 degrees") {
    const double a = 137.0 * std::numbers::pi / 180.0;
    mat2 R;
    R << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
    check_zero_stress<Cfg>([R](const vec2& X) -> vec2 { return (R - mat2::Identity()) * X; });
  }
}

using elastic_cfg = config<kernel::cubic_spline, correction::linear, quadrature::q4, geometry::plane_strain,
                           material::elastic, contact::none>;
using j2_cfg = config<kernel::quartic_spline, correction::quadratic, quadrature::q2, geometry::plane_strain,
                      material::j2_plasticity<material::hardening::linear>, contact::none>;

}  // namespace

TEST_CASE("rigid motions, elastic") { check_rigid<elastic_cfg>(); }
TEST_CASE("rigid motions, J2") { check_rigid<j2_cfg>(); }

TEST_CASE("internal forces sum to zero for an arbitrary deformed state") {
  // A smooth, strongly nonlinear field with 10-20 % strains (J2 yields).
  const auto u = [](const vec2& X) -> vec2 {
    return vec2(0.08 * std::sin(4.0 * X[0] + 1.0) * std::cos(3.0 * X[1]) + 0.05 * X[1] * X[1],
                -0.06 * std::cos(5.0 * X[0] * X[1]) + 0.1 * X[0] * X[0] * X[1]);
  };
  auto check = [&]<class Cfg>() {
    auto s = test::solver_at<Cfg>(test::grid_problem<Cfg>(lo, hi, n, c), u, test::tiny_step(h, c));
    vec2 sum = vec2::Zero();
    double size = 0.0;
    for (const vec2& f : s.internal_force()) {
      sum += f;
      size += f.norm();
    }
    REQUIRE(size > 1e-3 * c.youngs_modulus * h);
    CHECK(sum.norm() / size < 1e-12);
    return s.point_states()[0].equivalent_plastic_strain;
  };
  check.operator()<elastic_cfg>();
  // The J2 run is plastic somewhere, so the check covers the return mapping too.
  auto s = test::solver_at<j2_cfg>(test::grid_problem<j2_cfg>(lo, hi, n, c), u, test::tiny_step(h, c));
  double eps_p = 0.0;
  for (const auto& st : s.point_states()) eps_p = std::max(eps_p, st.equivalent_plastic_strain);
  CHECK(eps_p > 0.0);
  check.operator()<j2_cfg>();
}

}  // namespace test_unit_solver_rigid_body
