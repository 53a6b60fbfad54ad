#pragma once
// Geometry: how a 2D section stands for a 3D body (docs/method.md (16), (35), (37)).
//   weight_factor(X)          2 pi R in axisymmetric geometry, 1 in plane strain (per metre)
//   out_of_plane_stretch(u,X) F33: the hoop stretch 1 + u_r / R, or 1
//   is_axisymmetric            true when the hoop term enters the internal force and the
//                             symmetry axis r = 0 must be held on physical values

#include <concepts>
#include <string_view>

#include <rkpm/core/types.hpp>

namespace rkpm {

template <class G>
concept Geometry = requires(const vec2& X, const vec2& u) {
  { G::name } -> std::convertible_to<std::string_view>;
  { G::is_axisymmetric } -> std::convertible_to<bool>;
  { G::weight_factor(X) } -> std::same_as<double>;
  { G::out_of_plane_stretch(u, X) } -> std::same_as<double>;
};

}  // namespace rkpm
