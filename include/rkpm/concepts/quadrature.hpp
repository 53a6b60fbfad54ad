#pragma once
// Quadrature: how the integration points of a background cell are placed and weighted
// (docs/method.md section 3). Every rule has a `name` and a `points_per_cell`; it is one of
//   ReferenceCellRule  `rule` lists (xi, eta, weight) on the reference square [-1, 1]^2,
//                      mapped by the bilinear map of the cell (docs/method.md (15)-(16));
//                      q1, q2, q4, q9
//   ShapedCellRule     `cell_points(corners)` places the points from the cell's four physical
//                      corners (counter-clockwise), each with the area it stands for, because
//                      where they go depends on the cell's shape (its longer side, a diagonal);
//                      q2_split, q2_tri
//   CorrectedRule      a cell rule (`cell_rule`) whose test-function gradients are corrected
//                      once the shape functions are known (`corrects_test_gradients`): the
//                      points are the cell rule's; vci<Rule>
//   NodalRule          no rule per cell: one smoothing cell per mesh node, on which the builder
//                      smooths the gradients (`smooths_gradients`), with a `stabilization` in
//                      [0, 1] and `edge_points` per boundary segment; scni<Beta>
// A type that would be both a reference and a shaped rule, or a nodal and a cell rule, is
// rejected: the builder would not know which points to take.

#include <array>
#include <concepts>
#include <string_view>
#include <type_traits>

#include <rkpm/core/types.hpp>

namespace rkpm {

// A point placed by a ShapedCellRule: its position and the plane area it stands for (the
// builder multiplies by the geometry's weight factor, 2 pi R in axisymmetry).
struct cell_point {
  vec2 position;
  double area;
};

namespace detail {
template <class Q>
concept named_rule = requires {
  { Q::name } -> std::convertible_to<std::string_view>;
  { Q::points_per_cell } -> std::convertible_to<int>;
};
}  // namespace detail

template <class Q>
concept ReferenceCellRule = detail::named_rule<Q> && requires {
  { Q::rule[0][2] } -> std::convertible_to<double>;
} && (std::tuple_size_v<std::remove_cvref_t<decltype(Q::rule)>> == Q::points_per_cell);

template <class Q>
concept ShapedCellRule = detail::named_rule<Q> && requires(const std::array<vec2, 4>& corners) {
  { Q::cell_points(corners) } -> std::same_as<std::array<cell_point, Q::points_per_cell>>;
};

template <class Q>
concept CellRule = (ReferenceCellRule<Q> || ShapedCellRule<Q>) && !(ReferenceCellRule<Q> && ShapedCellRule<Q>);

template <class Q>
concept CorrectedRule = detail::named_rule<Q> && requires {
  typename Q::cell_rule;
  { Q::corrects_test_gradients } -> std::convertible_to<bool>;
} && CellRule<typename Q::cell_rule> && !CellRule<Q> && bool(Q::corrects_test_gradients) &&
                        (Q::points_per_cell == Q::cell_rule::points_per_cell);

template <class Q>
concept NodalRule = requires {
  { Q::name } -> std::convertible_to<std::string_view>;
  { Q::smooths_gradients } -> std::convertible_to<bool>;
  { Q::stabilization } -> std::convertible_to<double>;
  { Q::edge_points } -> std::convertible_to<int>;
} && bool(Q::smooths_gradients) && (Q::stabilization >= 0.0 && Q::stabilization <= 1.0) &&
                    !CellRule<Q> && !CorrectedRule<Q> && !requires { Q::points_per_cell; };

template <class Q>
concept Quadrature = CellRule<Q> || CorrectedRule<Q> || NodalRule<Q>;

// The rule that places the points of Q: Q itself, or the cell rule a corrected rule wraps
// (a nodal rule places its points itself: discretization/smoothing_cells.hpp).
template <Quadrature Q>
struct cell_rule_of {
  using type = Q;
};
template <CorrectedRule Q>
struct cell_rule_of<Q> {
  using type = typename Q::cell_rule;
};
template <Quadrature Q>
using cell_rule_of_t = typename cell_rule_of<Q>::type;

}  // namespace rkpm
