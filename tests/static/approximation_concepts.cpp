// Compile-time checks of the approximation policies (include/rkpm/concepts/): the shipped
// kernels and corrections satisfy Kernel and Correction, and types missing what the solver
// calls are rejected (mp-units style negative static_asserts).

#include <doctest/doctest.h>

#include <string_view>

#include <rkpm/approximation/basis.hpp>
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

TEST_CASE("approximation concepts are checked at compile time") { CHECK(true); }
