#pragma once
// Quartic spline profile on [-1, 1] (the one used by Belytschko's EFG and many RKPM codes):
// C2 at |z| = 1, no interior knots, scaled to unit integral.
//   phi(z) = 5/4 * (1 - 6 z^2 + 8 |z|^3 - 3 z^4)   for |z| <= 1

#include <cmath>
#include <string_view>

namespace rkpm::kernel {

struct quartic_spline {
  static constexpr std::string_view name = "quartic";

  static double value(double z) {
    const double s = std::abs(z);
    if (s >= 1.0) return 0.0;
    return 1.25 * (1.0 - 6.0 * s * s + 8.0 * s * s * s - 3.0 * s * s * s * s);
  }
  static double derivative(double z) {
    const double s = std::abs(z);
    if (s >= 1.0) return 0.0;
    const double sign = z < 0.0 ? -1.0 : 1.0;
    return sign * 1.25 * (-12.0 * s + 24.0 * s * s - 12.0 * s * s * s);
  }
  static double second_derivative(double z) {
    const double s = std::abs(z);
    if (s >= 1.0) return 0.0;
    return 1.25 * (-12.0 + 48.0 * s - 36.0 * s * s);
  }
};

}  // namespace rkpm::kernel
