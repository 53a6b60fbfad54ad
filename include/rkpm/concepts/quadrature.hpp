#pragma once
// Quadrature: a rule on the reference square [-1, 1]^2 of a background cell
// (docs/method.md section 3). `rule` lists (xi, eta, weight) per point.

#include <array>
#include <concepts>
#include <string_view>

namespace rkpm {

template <class Q>
concept Quadrature = requires {
  { Q::name } -> std::convertible_to<std::string_view>;
  { Q::points_per_cell } -> std::convertible_to<int>;
  { Q::rule[0][2] } -> std::convertible_to<double>;
} && (std::tuple_size_v<std::remove_cvref_t<decltype(Q::rule)>> == Q::points_per_cell);

}  // namespace rkpm
