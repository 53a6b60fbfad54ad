#pragma once
// Plane polygon tests behind the checks of a case file: signed area, simplicity, strict
// inside-ness and whether a tool segment passes through a body. "Strictly" means farther than
// a tolerance from the boundary, so that a tool may touch the body (lie along an edge, meet a
// corner), as the paper's cases start, but not start inside it.

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include <rkpm/core/types.hpp>

namespace rkpm::runner::case_file {

inline double cross(const vec2& a, const vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// Positive when counter-clockwise.
inline double signed_area(const std::vector<vec2>& v) {
  double a = 0.0;
  for (std::size_t k = 0; k < v.size(); ++k) a += cross(v[k], v[(k + 1) % v.size()]);
  return 0.5 * a;
}

// Largest coordinate extent, the length scale of the tolerances.
inline double extent(const std::vector<vec2>& v) {
  vec2 lo = v.front(), hi = v.front();
  for (const vec2& p : v) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).maxCoeff();
}

// Are all the points on the line through the first and the farthest from it?
inline bool on_one_line(const std::vector<vec2>& v) {
  std::size_t far = 0;
  for (std::size_t k = 1; k < v.size(); ++k)
    if ((v[k] - v[0]).squaredNorm() > (v[far] - v[0]).squaredNorm()) far = k;
  const vec2 e = v[far] - v[0];
  const double tol = 1e-12 * extent(v) * e.norm();
  return std::all_of(v.begin(), v.end(), [&](const vec2& p) { return std::abs(cross(e, p - v[0])) <= tol; });
}

inline double distance_to_segment(const vec2& p, const vec2& a, const vec2& b) {
  const vec2 e = b - a;
  const double L2 = e.squaredNorm();
  const double s = L2 > 0.0 ? std::clamp((p - a).dot(e) / L2, 0.0, 1.0) : 0.0;
  return (p - (a + s * e)).norm();
}

// Do the closed segments ab and cd share a point (within tol)?
inline bool segments_meet(const vec2& a, const vec2& b, const vec2& c, const vec2& d, double tol) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  return distance_to_segment(c, a, b) <= tol || distance_to_segment(d, a, b) <= tol ||
         distance_to_segment(a, c, d) <= tol || distance_to_segment(b, c, d) <= tol;
}

// The first pair of edges (k, l) of a closed polygon that meet although they are not
// neighbours (or, for neighbours, fold back onto each other); none for a simple polygon.
inline std::optional<std::pair<std::size_t, std::size_t>> crossing_edges(const std::vector<vec2>& v) {
  const std::size_t n = v.size();
  const double tol = 1e-12 * extent(v);
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t l = k + 1; l < n; ++l) {
      const vec2 &a = v[k], &b = v[(k + 1) % n], &c = v[l], &d = v[(l + 1) % n];
      const bool neighbours = l == k + 1 || (k == 0 && l == n - 1);
      if (!neighbours) {
        if (segments_meet(a, b, c, d, tol)) return std::pair{k, l};
      } else {
        // Neighbours share one vertex; they overlap when the far vertex of one lies on the other.
        const vec2 shared = l == k + 1 ? b : a;
        const vec2 p = l == k + 1 ? a : b, q = l == k + 1 ? d : c;
        if (distance_to_segment(p, shared, q) <= tol || distance_to_segment(q, shared, p) <= tol) return std::pair{k, l};
      }
    }
  return std::nullopt;
}

// Inside a closed polygon and farther than tol from its boundary.
inline bool strictly_inside(const vec2& p, const std::vector<vec2>& v, double tol) {
  bool inside = false;
  const std::size_t n = v.size();
  for (std::size_t k = 0, j = n - 1; k < n; j = k++) {
    if (distance_to_segment(p, v[j], v[k]) <= tol) return false;
    if ((v[k].y() > p.y()) != (v[j].y() > p.y()) &&
        p.x() < (v[j].x() - v[k].x()) * (p.y() - v[k].y()) / (v[j].y() - v[k].y()) + v[k].x())
      inside = !inside;
  }
  return inside;
}

using segment_list = std::vector<std::pair<vec2, vec2>>;

// The edges of a closed polygon.
inline segment_list polygon_edges(const std::vector<vec2>& v) {
  segment_list out;
  for (std::size_t k = 0; k < v.size(); ++k) out.emplace_back(v[k], v[(k + 1) % v.size()]);
  return out;
}

// A point of the segment ab strictly inside a region, if there is one: `boundary` is the
// region's boundary, inside(p) says whether a point off it is inside. Between two consecutive
// places where ab meets the boundary, ab is all inside or all outside, so testing the middle of
// each such piece decides.
template <class Inside>
std::optional<vec2> point_inside_along(const vec2& a, const vec2& b, const segment_list& boundary, double tol,
                                       Inside&& inside) {
  std::vector<double> s{0.0, 1.0};
  const vec2 e = b - a;
  const double L2 = e.squaredNorm();
  for (const auto& [c, d] : boundary) {
    const double den = cross(e, d - c);
    if (den != 0.0) {
      const double t = cross(c - a, d - c) / den;  // along ab
      const double u = cross(c - a, e) / den;      // along cd
      if (t > 0.0 && t < 1.0 && u >= -1e-12 && u <= 1 + 1e-12) s.push_back(t);
    }
    if (L2 > 0.0)  // boundary vertices on ab (also the ends of collinear overlaps)
      for (const vec2& p : {c, d})
        if (distance_to_segment(p, a, b) <= tol) s.push_back(std::clamp((p - a).dot(e) / L2, 0.0, 1.0));
  }
  std::sort(s.begin(), s.end());
  for (std::size_t k = 0; k + 1 < s.size(); ++k) {
    const vec2 mid = a + 0.5 * (s[k] + s[k + 1]) * e;
    if (s[k + 1] > s[k] && inside(mid)) return mid;
  }
  return std::nullopt;
}

// The boundary of a region covered by counter-clockwise cells: the cell edges that belong to
// one cell only.
template <class Mesh>
segment_list mesh_boundary(const Mesh& mesh) {
  std::map<std::pair<std::ptrdiff_t, std::ptrdiff_t>, int> count;
  for (const auto& c : mesh.cell)
    for (std::size_t k = 0; k < c.size(); ++k) {
      auto key = std::minmax(c[k], c[(k + 1) % c.size()]);
      ++count[{key.first, key.second}];
    }
  segment_list out;
  for (const auto& [edge, n] : count)
    if (n == 1) out.emplace_back(mesh.node[edge.first], mesh.node[edge.second]);
  return out;
}

// Inside (or on) one of the cells and farther than tol from the region's boundary.
template <class Mesh>
bool strictly_inside_mesh(const vec2& p, const Mesh& mesh, const segment_list& boundary, double tol) {
  for (const auto& [c, d] : boundary)
    if (distance_to_segment(p, c, d) <= tol) return false;
  for (const auto& cell : mesh.cell) {
    std::vector<vec2> corners;
    for (auto n : cell) corners.push_back(mesh.node[n]);
    if (strictly_inside(p, corners, 0.0)) return true;
    for (std::size_t k = 0; k < corners.size(); ++k)
      if (distance_to_segment(p, corners[k], corners[(k + 1) % corners.size()]) <= tol) return true;
  }
  return false;
}

}  // namespace rkpm::runner::case_file
