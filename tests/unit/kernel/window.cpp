// The tensor-product window Phi_a(x) = prod_k phi(x_k / a_k) / a_k with one support per
// direction (docs/method.md (6), section 2.3): product of the 1D profiles, unit
// integral over its rectangle for any supports, gradient against central differences, and
// the strict support test used by the neighbor search.

#include <doctest/doctest.h>

#include <cmath>

#include <rkpm/kernel/cubic_spline.hpp>
#include <rkpm/kernel/quartic_spline.hpp>
#include <rkpm/kernel/window.hpp>

namespace test_unit_kernel_window {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using rkpm::vec;
using rkpm::vec2;
using rkpm::kernel::cubic_spline;
using rkpm::kernel::quartic_spline;

TEST_CASE_TEMPLATE("window: product of scaled 1D profiles", K, cubic_spline, quartic_spline) {
  const vec2 a(0.32e-3, 1.296e-3);  // Taylor bar spacing times 2
  for (int i = 0; i < 50; ++i) {
    const vec2 dx(a[0] * (-1.2 + 2.4 * i / 49.0), a[1] * (0.9 - 1.9 * i / 49.0));
    const auto w = rkpm::kernel::window<K, 2>(dx, a);
    const double expect = K::value(dx[0] / a[0]) / a[0] * K::value(dx[1] / a[1]) / a[1];
    CHECK(w.value == doctest::Approx(expect).epsilon(1e-14));
  }
  // 1D: just the scaled profile.
  const auto w1 = rkpm::kernel::window<K, 1>(vec<1>(0.3), vec<1>(2.0));
  CHECK(w1.value == doctest::Approx(K::value(0.15) / 2.0).epsilon(1e-15));
  CHECK(w1.gradient[0] == doctest::Approx(K::derivative(0.15) / 4.0).epsilon(1e-15));
}

TEST_CASE_TEMPLATE("window: unit integral over the support rectangle", K, cubic_spline,
                   quartic_spline) {
  // Tensor 3-point Gauss on the 4 x 4 sub-rectangles split at the knots: exact.
  const vec2 a(0.7, 2.9);
  const double cuts[] = {-1.0, -0.5, 0.0, 0.5, 1.0};
  const double gx[] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
  const double gw[] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  double sum = 0.0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int p = 0; p < 3; ++p)
        for (int q = 0; q < 3; ++q) {
          const double mx = 0.5 * (cuts[i] + cuts[i + 1]), my = 0.5 * (cuts[j] + cuts[j + 1]);
          const vec2 dx(a[0] * (mx + 0.25 * gx[p]), a[1] * (my + 0.25 * gx[q]));
          const double jac = 0.25 * a[0] * 0.25 * a[1];
          sum += gw[p] * gw[q] * jac * rkpm::kernel::window<K, 2>(dx, a).value;
        }
  CHECK(sum == doctest::Approx(1.0).epsilon(1e-14));
}

TEST_CASE_TEMPLATE("window: gradient against central differences", K, cubic_spline,
                   quartic_spline) {
  const vec2 a(1.6e-4, 6.48e-4);
  for (int i = 0; i < 60; ++i) {
    const vec2 dx(a[0] * std::sin(0.7 * i) * 1.05, a[1] * std::cos(1.3 * i) * 1.05);
    const auto w = rkpm::kernel::window<K, 2>(dx, a);
    const double gscale = 4.0 / (a[0] * a[0] * a[1]) + 4.0 / (a[0] * a[1] * a[1]);
    for (int k = 0; k < 2; ++k) {
      const double h = 1e-6 * a[k];
      vec2 p = dx, m = dx;
      p[k] += h;
      m[k] -= h;
      const double fd = (rkpm::kernel::window<K, 2>(p, a).value -
                         rkpm::kernel::window<K, 2>(m, a).value) /
                        (2.0 * h);
      INFO("dx = " << dx.transpose() << ", k = " << k);
      CHECK(std::abs(fd - w.gradient[k]) < 1e-8 * gscale);
    }
  }
}

TEST_CASE("in_support: strict, per direction") {
  const vec2 a(1.0, 3.0);
  CHECK(rkpm::kernel::in_support<2>(vec2(0.0, 0.0), a));
  CHECK(rkpm::kernel::in_support<2>(vec2(0.999, -2.999), a));
  CHECK_FALSE(rkpm::kernel::in_support<2>(vec2(1.0, 0.0), a));
  CHECK_FALSE(rkpm::kernel::in_support<2>(vec2(0.0, -3.0), a));
  CHECK_FALSE(rkpm::kernel::in_support<2>(vec2(1.5, 0.0), a));  // inside in y only
  CHECK_FALSE(rkpm::kernel::in_support<2>(vec2(0.5, 3.5), a));  // inside in x only
  // Isotropic support 3 would contain this offset; the rectangle 1 x 3 does not.
  CHECK_FALSE(rkpm::kernel::in_support<2>(vec2(2.0, 0.0), a));
}

}  // namespace test_unit_kernel_window
