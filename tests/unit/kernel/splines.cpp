// The 1D window profiles (docs/method.md (4), (5)): compact support on [-1, 1], even, unit
// integral, C1 (in fact C2) across their knots, and derivatives that agree with finite
// differences. Reference numbers are the closed forms in the header comments, evaluated here
// independently.

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include <rkpm/kernel/cubic_spline.hpp>
#include <rkpm/kernel/quartic_spline.hpp>

namespace test_unit_kernel_splines {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

namespace {

using rkpm::kernel::cubic_spline;
using rkpm::kernel::quartic_spline;

// The knots where the piecewise polynomial changes, in [0, 1] (1 is the support edge).
template <class K>
std::array<double, 2> knots();
template <>
std::array<double, 2> knots<cubic_spline>() { return {0.5, 1.0}; }
template <>
std::array<double, 2> knots<quartic_spline>() { return {1.0, 1.0}; }

// 3-point Gauss-Legendre on [a, b]: exact for polynomials up to degree 5, so exact for each
// polynomial piece of either profile when the interval does not straddle a knot.
template <class F>
double gauss3(F f, double a, double b) {
  const double m = 0.5 * (a + b), r = 0.5 * (b - a);
  const double x = std::sqrt(0.6);
  return r * (5.0 / 9.0 * f(m - r * x) + 8.0 / 9.0 * f(m) + 5.0 / 9.0 * f(m + r * x));
}

// Integral over [-1, 1] on pieces split at +-1/2 and 0 (covers both profiles' knots).
template <class F>
double integral(F f) {
  const double cuts[] = {-1.0, -0.5, 0.0, 0.5, 1.0};
  double s = 0.0;
  for (int i = 0; i < 4; ++i) s += gauss3(f, cuts[i], cuts[i + 1]);
  return s;
}

}  // namespace

TEST_CASE("cubic spline: closed-form values") {
  // 4/3 (1 - 6 z^2 + 6 |z|^3) on |z| <= 1/2, 8/3 (1 - |z|)^3 on 1/2 < |z| < 1.
  CHECK(cubic_spline::value(0.0) == doctest::Approx(4.0 / 3.0).epsilon(1e-15));
  CHECK(cubic_spline::value(0.5) == doctest::Approx(1.0 / 3.0).epsilon(1e-15));
  CHECK(cubic_spline::value(0.25) ==
        doctest::Approx(4.0 / 3.0 * (1.0 - 6.0 / 16.0 + 6.0 / 64.0)).epsilon(1e-15));
  CHECK(cubic_spline::value(-0.75) == doctest::Approx(8.0 / 3.0 / 64.0).epsilon(1e-15));
  CHECK(cubic_spline::derivative(0.5) == doctest::Approx(-2.0).epsilon(1e-15));
  CHECK(cubic_spline::second_derivative(0.0) == doctest::Approx(-16.0).epsilon(1e-15));
}

TEST_CASE("quartic spline: closed-form values") {
  // 5/4 (1 - 6 z^2 + 8 |z|^3 - 3 z^4) = 5/4 (1 - |z|)^3 (1 + 3 |z|).
  CHECK(quartic_spline::value(0.0) == doctest::Approx(1.25).epsilon(1e-15));
  for (double z : {0.1, 0.37, 0.5, 0.9, -0.6}) {
    const double s = std::abs(z);
    CHECK(quartic_spline::value(z) ==
          doctest::Approx(1.25 * std::pow(1.0 - s, 3) * (1.0 + 3.0 * s)).epsilon(1e-13));
  }
  CHECK(quartic_spline::second_derivative(0.0) == doctest::Approx(-15.0).epsilon(1e-15));
}

TEST_CASE_TEMPLATE("kernel profile: compact support on [-1, 1]", K, cubic_spline,
                   quartic_spline) {
  for (double z : {1.0, -1.0, 1.0 + 1e-12, -1.0 - 1e-12, 1.5, -3.0, 1e300}) {
    CHECK(K::value(z) == 0.0);
    CHECK(K::derivative(z) == 0.0);
    CHECK(K::second_derivative(z) == 0.0);
  }
  // Strictly positive inside, so every particle whose support covers x contributes to M.
  for (int i = 0; i < 200; ++i) {
    const double z = -0.995 + 1.99 * i / 199.0;
    CHECK(K::value(z) > 0.0);
  }
}

TEST_CASE_TEMPLATE("kernel profile: even value, odd derivative, even second derivative", K,
                   cubic_spline, quartic_spline) {
  for (int i = 0; i <= 120; ++i) {
    const double z = 1.2 * i / 120.0;
    CHECK(K::value(-z) == K::value(z));
    CHECK(K::derivative(-z) == -K::derivative(z));
    CHECK(K::second_derivative(-z) == K::second_derivative(z));
  }
  CHECK(K::derivative(0.0) == 0.0);
}

TEST_CASE_TEMPLATE("kernel profile: unit integral, zero first moment", K, cubic_spline,
                   quartic_spline) {
  CHECK(integral([](double z) { return K::value(z); }) == doctest::Approx(1.0).epsilon(1e-14));
  CHECK(std::abs(integral([](double z) { return z * K::value(z); })) < 1e-15);
  // The derivative integrates to phi(1) - phi(-1) = 0.
  CHECK(std::abs(integral([](double z) { return K::derivative(z); })) < 1e-14);
}

TEST_CASE_TEMPLATE("kernel profile: value and first derivative continuous at the knots", K,
                   cubic_spline, quartic_spline) {
  // A jump J at a knot would show as |f(k + d) - f(k - d)| ~ J; a continuous f gives O(d).
  const double d = 1e-9;
  for (double k : knots<K>()) {
    for (double sign : {1.0, -1.0}) {
      const double z = sign * k;
      CHECK(std::abs(K::value(z + d) - K::value(z - d)) < 1e-7);
      CHECK(std::abs(K::derivative(z + d) - K::derivative(z - d)) < 1e-6);
      // Both profiles are C2 as well.
      CHECK(std::abs(K::second_derivative(z + d) - K::second_derivative(z - d)) < 1e-6);
    }
  }
  // At the support edge the profile and its slope meet the zero outside (the expanded
  // quartic loses ~1e-15 to cancellation there, far below anything that matters).
  CHECK(std::abs(K::value(1.0 - 1e-6)) < 1e-14);
  CHECK(std::abs(K::derivative(1.0 - 1e-6)) < 1e-10);
}

TEST_CASE_TEMPLATE("kernel profile: derivatives against central differences", K, cubic_spline,
                   quartic_spline) {
  const double h = 1e-6;
  for (int i = 0; i <= 400; ++i) {
    const double z = -1.1 + 2.2 * i / 400.0;
    const double fd1 = (K::value(z + h) - K::value(z - h)) / (2.0 * h);
    const double fd2 = (K::derivative(z + h) - K::derivative(z - h)) / (2.0 * h);
    INFO("z = " << z);
    // Round-off of the difference quotient ~ 1e-16 * |phi| / h ~ 1e-10.
    CHECK(std::abs(fd1 - K::derivative(z)) < 1e-8);
    // phi'' has kinks at |z| = 0, 1/2, 1, where the central difference of phi' is only
    // first-order accurate; compare it away from them.
    const double s = std::abs(z);
    if (std::min({s, std::abs(s - 0.5), std::abs(s - 1.0)}) > 10.0 * h)
      CHECK(std::abs(fd2 - K::second_derivative(z)) < 1e-7);
  }
}

}  // namespace test_unit_kernel_splines
