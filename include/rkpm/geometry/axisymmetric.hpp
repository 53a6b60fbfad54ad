#pragma once
// Axisymmetric: coordinates (r, z) with the axis at r = 0. Weights and masses carry 2 pi R,
// so forces are totals over the ring (N); the hoop stretch is F33 = 1 + u_r / R at the
// point's reference radius R > 0 (Gauss points never lie on the axis). The symmetry axis
// u_r = 0 is held on physical values by the solver's constraints (docs/method.md section 5.7).

#include <numbers>
#include <string_view>

#include <rkpm/core/types.hpp>

namespace rkpm::geometry {

struct axisymmetric {
  static constexpr std::string_view name = "axisymmetric";
  static constexpr bool is_axisymmetric = true;
  static double weight_factor(const vec2& X) { return 2.0 * std::numbers::pi * X[0]; }
  static double out_of_plane_stretch(const vec2& u, const vec2& X) { return 1.0 + u[0] / X[0]; }
};

}  // namespace rkpm::geometry
