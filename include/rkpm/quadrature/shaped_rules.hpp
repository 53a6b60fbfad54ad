#pragma once
// The two other readings of the paper's two-point cell (docs/method.md section 3.4). The paper
// draws a cell split in two with one point per part and gives no coordinates; rkpm's `q2` is
// the diagonal Gauss pair (section 3.3). These rules place the points from the cell's physical
// corners (ShapedCellRule, concepts/quadrature.hpp), one point at the centroid of each part
// with the part's area as weight:
//   q2_split  the cell halved across its longer side: the segment joining the midpoints of the
//             two longer opposite sides cuts it into two quadrilaterals (a square cell is cut
//             across its first side, x0-x1)
//   q2_tri    the cell cut along its shorter diagonal into two triangles (x0-x2 on a tie; the
//             other diagonal when the cell is not convex and only that one cuts it inside)
// A centroid with the part's area integrates every linear function of X exactly over the part,
// so both rules are exact for linear integrands on any cell (q2 only on parallelograms), and
// with the weight 2 pi R_q the volume of revolution is exact (Pappus). The parts' areas add up
// to the cell's; a part of non-positive area is reported by the builder
// (discretization/quadrature_points.hpp).

#include <array>
#include <string_view>

#include <rkpm/concepts/quadrature.hpp>

namespace rkpm::quadrature {

namespace detail {

inline double cross(const vec2& a, const vec2& b) { return a[0] * b[1] - a[1] * b[0]; }

// Centroid and signed area of a polygon given counter-clockwise.
template <std::size_t N>
cell_point polygon_centroid(const std::array<vec2, N>& p) {
  double area2 = 0.0;
  vec2 moment = vec2::Zero();
  for (std::size_t k = 0; k < N; ++k) {
    const vec2& a = p[k];
    const vec2& b = p[(k + 1) % N];
    const double c = cross(a, b);
    area2 += c;
    moment += (a + b) * c;
  }
  // A degenerate part keeps its corners' mean, so the builder can name the cell.
  if (area2 == 0.0) {
    vec2 mean = vec2::Zero();
    for (const vec2& x : p) mean += x / static_cast<double>(N);
    return {mean, 0.0};
  }
  return {moment / (3.0 * area2), 0.5 * area2};
}

inline cell_point triangle(const vec2& a, const vec2& b, const vec2& c) {
  return {(a + b + c) / 3.0, 0.5 * cross(b - a, c - a)};
}

// Relative margin under which two lengths count as equal, so that a square cell is cut the
// same way whatever the rounding of its corners.
inline constexpr double tie = 1e-10;

}  // namespace detail

struct q2_split {
  static constexpr std::string_view name = "q2_split";
  static constexpr int points_per_cell = 2;
  static std::array<cell_point, 2> cell_points(const std::array<vec2, 4>& x) {
    const vec2 m01 = 0.5 * (x[0] + x[1]), m12 = 0.5 * (x[1] + x[2]);
    const vec2 m23 = 0.5 * (x[2] + x[3]), m30 = 0.5 * (x[3] + x[0]);
    // Lengths of the cell across its two directions: between the midpoints of opposite sides.
    const double along_01 = (m12 - m30).norm(), along_12 = (m23 - m01).norm();
    if (along_12 > (1.0 + detail::tie) * along_01)  // longer from side 0-1 to side 2-3
      return {detail::polygon_centroid<4>({x[0], x[1], m12, m30}), detail::polygon_centroid<4>({m30, m12, x[2], x[3]})};
    return {detail::polygon_centroid<4>({x[0], m01, m23, x[3]}), detail::polygon_centroid<4>({m01, x[1], x[2], m23})};
  }
};

struct q2_tri {
  static constexpr std::string_view name = "q2_tri";
  static constexpr int points_per_cell = 2;
  static std::array<cell_point, 2> cell_points(const std::array<vec2, 4>& x) {
    const std::array<cell_point, 2> d02{detail::triangle(x[0], x[1], x[2]), detail::triangle(x[0], x[2], x[3])};
    const std::array<cell_point, 2> d13{detail::triangle(x[0], x[1], x[3]), detail::triangle(x[1], x[2], x[3])};
    const bool inside02 = d02[0].area > 0.0 && d02[1].area > 0.0;
    const bool inside13 = d13[0].area > 0.0 && d13[1].area > 0.0;
    if (inside02 && inside13)
      return (x[3] - x[1]).norm() < (1.0 - detail::tie) * (x[2] - x[0]).norm() ? d13 : d02;
    return inside13 ? d13 : d02;
  }
};

}  // namespace rkpm::quadrature
