// Checks of the approximation policies against their concepts (include/rkpm/concepts/): at
// compile time, the shipped kernels and corrections satisfy Kernel and Correction and types
// missing what the solver calls are rejected (mp-units style negative static_asserts); at run
// time, each shipped policy keeps what the concepts promise but cannot express (support,
// symmetry, unit integral, derivatives consistent with values, monomial count).

#include <doctest/doctest.h>

#include <cmath>
#include <string_view>

#include <Eigen/LU>

#include <rkpm/correction/polynomial_bases.hpp>
#include <rkpm/approximation/rk_shape_functions.hpp>
#include <rkpm/concepts/correction.hpp>
#include <rkpm/concepts/kernel.hpp>
#include <rkpm/kernel/cubic_spline.hpp>
#include <rkpm/kernel/quartic_spline.hpp>

namespace {

// ---- kernels ----
struct kernel_without_derivative {
  static constexpr std::string_view name = "broken";
  static double value(double) { return 0.0; }
  static double second_derivative(double) { return 0.0; }
};

struct kernel_without_name {
  static double value(double) { return 0.0; }
  static double derivative(double) { return 0.0; }
  static double second_derivative(double) { return 0.0; }
};

struct kernel_returning_float {
  static constexpr std::string_view name = "float";
  static float value(double) { return 0.0f; }
  static double derivative(double) { return 0.0; }
  static double second_derivative(double) { return 0.0; }
};

// ---- corrections ----
template <int Dim>
using basis_h = Eigen::Matrix<double, 1 + Dim, 1>;
template <int Dim>
using basis_dh = Eigen::Matrix<double, 1 + Dim, Dim>;

struct correction_without_evaluate {
  static constexpr std::string_view name = "no evaluate";
  static constexpr int order = 1;
  template <int Dim>
  static constexpr int size = 1 + Dim;
};

struct correction_without_order {
  static constexpr std::string_view name = "no order";
  template <int Dim>
  static constexpr int size = 1 + Dim;
  template <int Dim>
  static void evaluate(const rkpm::vec<Dim>&, basis_h<Dim>&, basis_dh<Dim>&) {}
};

// The complete shape of a correction, to show the two above fail for the missing member only.
struct correction_complete {
  static constexpr std::string_view name = "complete";
  static constexpr int order = 1;
  template <int Dim>
  static constexpr int size = 1 + Dim;
  template <int Dim>
  static void evaluate(const rkpm::vec<Dim>&, basis_h<Dim>&, basis_dh<Dim>&) {}
};

}  // namespace

static_assert(rkpm::Kernel<rkpm::kernel::cubic_spline>);
static_assert(rkpm::Kernel<rkpm::kernel::quartic_spline>);
static_assert(!rkpm::Kernel<kernel_without_derivative>);
static_assert(!rkpm::Kernel<kernel_without_name>);
static_assert(!rkpm::Kernel<kernel_returning_float>);
static_assert(!rkpm::Kernel<int>);

static_assert(rkpm::Correction<rkpm::correction::linear>);
static_assert(rkpm::Correction<rkpm::correction::quadratic>);
static_assert(rkpm::Correction<correction_complete>);
static_assert(!rkpm::Correction<correction_without_evaluate>);
static_assert(!rkpm::Correction<correction_without_order>);
static_assert(!rkpm::Correction<rkpm::kernel::cubic_spline>);
static_assert(!rkpm::Correction<double>);

// The shape-function class is constrained by both concepts.
template <class K, class C>
concept rk_instantiable = requires { typename rkpm::rk_shape_functions<K, C, 2>; };
static_assert(rk_instantiable<rkpm::kernel::cubic_spline, rkpm::correction::quadratic>);
static_assert(!rk_instantiable<kernel_without_derivative, rkpm::correction::linear>);
static_assert(!rk_instantiable<rkpm::kernel::quartic_spline, correction_without_order>);

static_assert(rkpm::rk_shape_functions<rkpm::kernel::cubic_spline, rkpm::correction::linear,
                                       2>::basis_size == 3);
static_assert(rkpm::rk_shape_functions<rkpm::kernel::cubic_spline, rkpm::correction::quadratic,
                                       2>::basis_size == 6);
static_assert(rkpm::rk_shape_functions<rkpm::kernel::cubic_spline, rkpm::correction::quadratic,
                                       1>::basis_size == 3);

// ---- what the concepts cannot state, checked at run time on every shipped policy ----------
// A Kernel is even, zero outside |z| < 1, positive inside, of unit integral, and its
// derivative and second_derivative are those of value.
template <rkpm::Kernel K>
void check_kernel_contract() {
  CAPTURE(K::name);
  CHECK(K::value(1.0) == 0.0);
  CHECK(K::value(-1.0) == 0.0);
  CHECK(K::value(1.5) == 0.0);
  CHECK(K::derivative(1.25) == 0.0);
  CHECK(K::second_derivative(-1.25) == 0.0);
  CHECK(K::value(0.999) > 0.0);
  CHECK(K::derivative(0.0) == 0.0);
  // Composite Simpson on 6000 intervals: exact to round-off for piecewise polynomials of
  // degree <= 3 with knots on the grid, ~1e-14 for the quartic.
  const int n = 6000;
  double integral = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double z = -1.0 + 2.0 * i / n;
    integral += (i == 0 || i == n ? 1.0 : i % 2 ? 4.0 : 2.0) * K::value(z);
  }
  integral *= 2.0 / n / 3.0;
  CHECK(integral == doctest::Approx(1.0).epsilon(1e-12));
  const double h = 1e-6;
  for (double z : {0.05, 0.3, 0.49, 0.51, 0.7, 0.95}) {
    CAPTURE(z);
    CHECK(K::value(-z) == K::value(z));
    CHECK(K::derivative(-z) == -K::derivative(z));
    CHECK(K::second_derivative(-z) == K::second_derivative(z));
    CHECK(K::derivative(z) == doctest::Approx((K::value(z + h) - K::value(z - h)) / (2 * h)).epsilon(1e-7));
    CHECK(K::second_derivative(z) ==
          doctest::Approx((K::derivative(z + h) - K::derivative(z - h)) / (2 * h)).epsilon(1e-6));
  }
}

// A Correction of order p in Dim dimensions has size C(p + Dim, Dim) monomials, H = [1, z, ...]
// linearly independent, and dH the derivative of H.
template <rkpm::Correction C, int Dim>
void check_correction_contract() {
  CAPTURE(C::name);
  CAPTURE(Dim);
  constexpr int m = C::template size<Dim>;
  using H = Eigen::Matrix<double, m, 1>;
  using DH = Eigen::Matrix<double, m, Dim>;
  int monomials = 1;  // C(order + Dim, Dim)
  for (int k = 1; k <= Dim; ++k) monomials = monomials * (C::order + k) / k;
  CHECK(m == monomials);
  rkpm::vec<Dim> z;
  for (int k = 0; k < Dim; ++k) z[k] = 0.3 - 0.45 * k;
  H h;
  DH dh;
  C::evaluate(z, h, dh);
  CHECK(h[0] == 1.0);
  for (int k = 0; k < Dim; ++k) CHECK(h[1 + k] == z[k]);
  const double step = 1e-6;
  for (int k = 0; k < Dim; ++k) {
    rkpm::vec<Dim> zp = z, zm = z;
    zp[k] += step;
    zm[k] -= step;
    H hp, hm;
    DH unused;
    C::evaluate(zp, hp, unused);
    C::evaluate(zm, hm, unused);
    CHECK(((hp - hm) / (2 * step) - dh.col(k)).norm() < 1e-8);
  }
  // Independent monomials: H at m generic points spans R^m.
  Eigen::Matrix<double, m, m> sample;
  for (int i = 0; i < m; ++i) {
    rkpm::vec<Dim> zi;
    for (int k = 0; k < Dim; ++k) zi[k] = std::sin(1.3 * std::pow(i + 1.0, k + 1) + 0.2 * k);  // on no conic
    H hi;
    C::evaluate(zi, hi, dh);
    sample.col(i) = hi;
  }
  CHECK(Eigen::FullPivLU<Eigen::Matrix<double, m, m>>(sample).rank() == m);
}

TEST_CASE("kernels keep the promises of Kernel that the type system cannot check") {
  check_kernel_contract<rkpm::kernel::cubic_spline>();
  check_kernel_contract<rkpm::kernel::quartic_spline>();
}

TEST_CASE("corrections keep the promises of Correction that the type system cannot check") {
  check_correction_contract<rkpm::correction::linear, 1>();
  check_correction_contract<rkpm::correction::linear, 2>();
  check_correction_contract<rkpm::correction::quadratic, 1>();
  check_correction_contract<rkpm::correction::quadratic, 2>();
}
