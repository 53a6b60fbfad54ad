// The correction bases H(z) (docs/method.md (7)): the complete monomials of degree 1 and 2 in
// 1D and 2D, in the documented order, with dH/dz checked against the monomials' closed-form
// derivatives and against central differences.

#include <doctest/doctest.h>

#include <cmath>

#include <rkpm/correction/polynomial_bases.hpp>

namespace test_unit_correction_polynomial_bases {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using rkpm::vec;
using rkpm::correction::linear;
using rkpm::correction::quadratic;

TEST_CASE("basis sizes") {
  static_assert(linear::size<1> == 2 && linear::size<2> == 3);
  static_assert(quadratic::size<1> == 3 && quadratic::size<2> == 6);
  static_assert(linear::order == 1 && quadratic::order == 2);
  CHECK(linear::name == "linear");
  CHECK(quadratic::name == "quadratic");
}

TEST_CASE("linear basis: [1, z1, z2] and its gradient") {
  const vec<2> z(0.3, -1.7);
  Eigen::Matrix<double, 3, 1> h;
  Eigen::Matrix<double, 3, 2> dh;
  h.setConstant(99.0);
  dh.setConstant(99.0);  // evaluate must overwrite everything
  linear::evaluate<2>(z, h, dh);
  CHECK(h[0] == 1.0);
  CHECK(h[1] == 0.3);
  CHECK(h[2] == -1.7);
  Eigen::Matrix<double, 3, 2> expect;
  expect << 0, 0, 1, 0, 0, 1;
  CHECK(dh == expect);
}

TEST_CASE("quadratic basis: [1, z1, z2, z1^2, z1 z2, z2^2] and its gradient") {
  const double a = 0.3, b = -1.7;
  Eigen::Matrix<double, 6, 1> h;
  Eigen::Matrix<double, 6, 2> dh;
  h.setConstant(99.0);
  dh.setConstant(99.0);
  quadratic::evaluate<2>(vec<2>(a, b), h, dh);
  Eigen::Matrix<double, 6, 1> he;
  he << 1, a, b, a * a, a * b, b * b;
  Eigen::Matrix<double, 6, 2> dhe;
  dhe << 0, 0, 1, 0, 0, 1, 2 * a, 0, b, a, 0, 2 * b;
  CHECK((h - he).norm() < 1e-15);
  CHECK((dh - dhe).norm() < 1e-15);
}

TEST_CASE("1D bases") {
  Eigen::Matrix<double, 2, 1> h1, dh1;
  linear::evaluate<1>(vec<1>(-0.4), h1, dh1);
  CHECK(h1[0] == 1.0);
  CHECK(h1[1] == -0.4);
  CHECK(dh1[0] == 0.0);
  CHECK(dh1[1] == 1.0);
  Eigen::Matrix<double, 3, 1> h2, dh2;
  quadratic::evaluate<1>(vec<1>(-0.4), h2, dh2);
  CHECK(h2[2] == doctest::Approx(0.16).epsilon(1e-15));
  CHECK(dh2[2] == doctest::Approx(-0.8).epsilon(1e-15));
}

TEST_CASE_TEMPLATE("basis gradient against central differences", C, linear, quadratic) {
  constexpr int n = C::template size<2>;
  Eigen::Matrix<double, n, 1> h, hp, hm;
  Eigen::Matrix<double, n, 2> dh, scratch;
  const double step = 1e-6;
  for (int i = 0; i < 20; ++i) {
    const vec<2> z(std::sin(1.1 * i), std::cos(0.37 * i) * 1.5);
    C::template evaluate<2>(z, h, dh);
    for (int k = 0; k < 2; ++k) {
      vec<2> zp = z, zm = z;
      zp[k] += step;
      zm[k] -= step;
      C::template evaluate<2>(zp, hp, scratch);
      C::template evaluate<2>(zm, hm, scratch);
      CHECK(((hp - hm) / (2.0 * step) - dh.col(k)).norm() < 1e-9);
    }
  }
}

}  // namespace test_unit_correction_polynomial_bases
