#pragma once
// Plane strain: the section is a slice of unit thickness of a long body; F33 = 1.
// Forces and masses are per metre of depth.

#include <string_view>

#include <rkpm/core/types.hpp>

namespace rkpm::geometry {

struct plane_strain {
  static constexpr std::string_view name = "plane_strain";
  static constexpr bool is_axisymmetric = false;
  static double weight_factor(const vec2&) { return 1.0; }
  static double out_of_plane_stretch(const vec2&, const vec2&) { return 1.0; }
};

}  // namespace rkpm::geometry
