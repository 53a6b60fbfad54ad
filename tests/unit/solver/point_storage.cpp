// What the solver keeps per quadrature point (solver/point_materials.hpp, core/block_matrix.hpp):
// F, tau and the J2 state's b_e and F_n as their five block entries. A block-structured tensor
// stored and read back is the same matrix bit for bit, so no result changes; the F that the
// stable-step re-estimates read from the J2 state (no copy of its own) is the deformation
// gradient of the current coefficients, recomputed here from the shape table; and the Cauchy
// stress read back is symmetric with the out-of-plane shear zero, as the materials make it.

#include <doctest/doctest.h>

#include <random>

#include "support/solver_fixtures.hpp"

namespace test_unit_solver_point_storage {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

namespace {

using axi_cfg = config<kernel::cubic_spline, correction::linear, quadrature::q2, geometry::axisymmetric,
                       material::j2_plasticity<material::hardening::linear>, contact::none>;

}  // namespace

TEST_CASE("block_matrix: a block-structured tensor round-trips bit for bit in 40 bytes") {
  static_assert(sizeof(block_matrix) == 40);
  static_assert(sizeof(material::j2_state) == 2 * 40 + 2 * 8);
  static_assert(bitwise_value<material::j2_state>);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int k = 0; k < 1000; ++k) {
    mat3 a = mat3::Zero();
    a(0, 0) = u(rng);
    a(0, 1) = u(rng) * 1e-300;  // subnormal-sized and ordinary entries alike
    a(1, 0) = u(rng);
    a(1, 1) = u(rng) * 1e200;
    a(2, 2) = u(rng);
    const mat3 back = block_matrix::of(a).full();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) CHECK(std::bit_cast<std::uint64_t>(back(i, j)) == std::bit_cast<std::uint64_t>(a(i, j)));
  }
  CHECK(block_matrix{}.full() == mat3::Identity());
}

TEST_CASE("the F read from the J2 state is the deformation gradient of the coefficients") {
  const Eigen::Vector2i n(5, 7);
  auto p = test::grid_problem<axi_cfg>(vec2(0.0, 0.0), vec2(2e-3, 3e-3), n);
  // A cylinder squeezed at its top face, swirled so that every entry of F moves.
  test::squeeze_from_top(p, 3e-3, 20.0, 1e-7);
  p.initial_velocity = [](const vec2& X) { return vec2(5.0 * X[1] / 3e-3, 3.0 * X[0] / 2e-3); };
  run_options o;
  o.end_time = 1.0;
  auto s = make_solver<axi_cfg>(std::move(p), o);
  for (int k = 0; k < 60; ++k) s.step();
  const auto F = test::deformation_gradients<axi_cfg::geometry_type>(s.model(), s.coefficients());
  double worst = 0.0, sheared = 0.0, plastic = 0.0;
  for (index_t q = 0; q < s.model().point_count(); ++q) {
    const mat3 stored = s.point_states()[q].previous_deformation.full();
    worst = std::max(worst, (stored - F[q]).cwiseAbs().maxCoeff());
    sheared = std::max(sheared, std::abs(F[q](0, 1)));
    plastic = std::max(plastic, s.point_states()[q].equivalent_plastic_strain);
    CHECK(s.point_det_F(q) == doctest::Approx(F[q].determinant()).epsilon(1e-13));
    const mat3 sigma = s.point_cauchy_stress(q);
    CHECK(sigma(0, 1) == sigma(1, 0));
    CHECK(sigma(0, 2) == 0.0);
    CHECK(sigma(2, 1) == 0.0);
  }
  CHECK(worst < 1e-14);  // the same sums in another order: rounding only
  CHECK(sheared > 1e-4);  // the test sees a deformed configuration
  MESSAGE("largest shear F12 ", sheared, ", largest plastic strain ", plastic);
}

}  // namespace test_unit_solver_point_storage
