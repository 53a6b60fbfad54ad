#pragma once
// Cubic B-spline profile on [-1, 1]: C2, knots at |z| = 1/2, unit integral.
//   phi(z) = 4/3 * (1 - 6 z^2 + 6 |z|^3)   for |z| <= 1/2
//          = 8/3 * (1 - |z|)^3             for 1/2 < |z| <= 1

#include <cmath>
#include <string_view>

namespace rkpm::kernel {

struct cubic_spline {
  static constexpr std::string_view name = "cubic";

  static double value(double z) {
    const double s = std::abs(z);
    if (s <= 0.5) return 4.0 / 3.0 - 8.0 * s * s + 8.0 * s * s * s;
    if (s < 1.0) return 8.0 / 3.0 * (1.0 - s) * (1.0 - s) * (1.0 - s);
    return 0.0;
  }
  static double derivative(double z) {
    const double s = std::abs(z);
    const double sign = z < 0.0 ? -1.0 : 1.0;
    if (s <= 0.5) return sign * (-16.0 * s + 24.0 * s * s);
    if (s < 1.0) return sign * (-8.0 * (1.0 - s) * (1.0 - s));
    return 0.0;
  }
  static double second_derivative(double z) {
    const double s = std::abs(z);
    if (s <= 0.5) return -16.0 + 48.0 * s;
    if (s < 1.0) return 16.0 * (1.0 - s);
    return 0.0;
  }
};

}  // namespace rkpm::kernel
