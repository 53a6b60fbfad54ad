#pragma once
// crack_set: cracks as line segments in the reference configuration of a model, and the
// visibility criterion that keeps the kernels from reaching across them (docs/method.md
// section 3.7): particle I is no neighbour of a point x when the segment from x to X_I crosses
// a crack, (112). A crack is a surface, not a band: the shape functions on each side are
// corrected with that side's particles alone, so each side reproduces the linear (or quadratic)
// fields by itself, and the displacement may jump across the crack.
//   segment   the cracks' segments, end points in the model's reference configuration
//   blocks    whether the sight line from x to y crosses one of them
//   faces     where the cracks are surfaces of the material, when they were cut through cells
//             (solver/crack_growth.hpp's cracks_on): each segment's chord inside its cell, whose
//             two sides are the crack's faces (contact between them: discretization/crack_face_rows.hpp)
// A crack whose end only touches a sight line, or that lies along it, does not block it:
// a crack is extended a little past the cells it cuts, so that the segments of a crack path
// overlap (solver/crack_growth.hpp).

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>

namespace rkpm {

class crack_set {
 public:
  using segment_type = std::array<vec2, 2>;
  // A crack through background cell `cell`, from chord[0] to chord[1] where it crosses the cell's sides.
  struct face_type {
    index_t cell = 0;
    segment_type chord;
  };

  crack_set() = default;
  explicit crack_set(std::vector<segment_type> segments) : segment_(std::move(segments)) { index(); }
  // Segments that cut cells, with their faces (one per segment, or none).
  crack_set(std::vector<segment_type> segments, std::vector<face_type> faces)
      : segment_(std::move(segments)), face_(std::move(faces)) {
    if (!face_.empty() && face_.size() != segment_.size())
      fail("crack set: {} faces for {} segments; give one per segment or none", face_.size(), segment_.size());
    index();
  }

  bool empty() const { return segment_.empty(); }
  index_t size() const { return static_cast<index_t>(segment_.size()); }
  const std::vector<segment_type>& segments() const { return segment_; }
  const std::vector<face_type>& faces() const { return face_; }

  // A segment with no face (a crack given by hand is drawn in the cells, not cut through them).
  void add(const vec2& a, const vec2& b) {
    if (!face_.empty()) fail("crack set: a segment without a face added to segments with faces");
    segment_.push_back({a, b});
    index();
  }

  // Whether the open segment x-y and a crack segment cross at a point inside both (112).
  bool blocks(const vec2& x, const vec2& y) const {
    if (segment_.empty()) return false;
    const vec2 lo = x.cwiseMin(y), hi = x.cwiseMax(y);
    const auto [i0, j0] = bin(lo);
    const auto [i1, j1] = bin(hi);
    for (index_t j = j0; j <= j1; ++j)
      for (index_t i = i0; i <= i1; ++i) {
        const index_t b = j * bins_[0] + i;
        for (index_t k = start_[b]; k < start_[b + 1]; ++k)
          if (crosses(x, y, segment_[member_[k]][0], segment_[member_[k]][1])) return true;
      }
    return false;
  }

  // Whether the sight line p-q crosses crack segment a-b: the crack's ends strictly on the two
  // sides of the sight line, and p and q on two sides of the crack's line, where a point on the
  // crack's line counts as on its left (a particle or point that a crack runs through belongs
  // to one side, not to both: a crack at 45 degrees through a square grid's cells meets
  // particles and points exactly).
  static bool crosses(const vec2& p, const vec2& q, const vec2& a, const vec2& b) {
    const auto side = [](const vec2& o, const vec2& d, const vec2& r) {
      return d[0] * (r[1] - o[1]) - d[1] * (r[0] - o[0]);
    };
    const vec2 pq = q - p, ab = b - a;
    const double s1 = side(p, pq, a), s2 = side(p, pq, b);
    if (!((s1 > 0.0 && s2 < 0.0) || (s1 < 0.0 && s2 > 0.0))) return false;
    return (side(a, ab, p) >= 0.0) != (side(a, ab, q) >= 0.0);
  }

 private:
  // A grid over the segments' bounding box, bins as large as the longest segment, each segment
  // listed in the bins its box overlaps (clamped queries outside the box see the edge bins).
  void index() {
    if (segment_.empty()) return;
    lo_ = segment_[0][0];
    vec2 hi = lo_;
    double longest = 0.0;
    for (const auto& [a, b] : segment_) {
      if (!a.allFinite() || !b.allFinite()) fail("crack segment with a non-finite end point");
      lo_ = lo_.cwiseMin(a).cwiseMin(b);
      hi = hi.cwiseMax(a).cwiseMax(b);
      longest = std::max(longest, (b - a).cwiseAbs().maxCoeff());
    }
    width_ = std::max(longest, 1e-12 * std::max(1.0, (hi - lo_).maxCoeff()));
    for (int k = 0; k < 2; ++k)
      bins_[k] = std::min<index_t>(static_cast<index_t>((hi[k] - lo_[k]) / width_) + 1, 256);
    width_ = std::max(width_, std::max((hi[0] - lo_[0]) / bins_[0], (hi[1] - lo_[1]) / bins_[1]) * (1.0 + 1e-12));
    start_.assign(bins_[0] * bins_[1] + 1, 0);
    const auto each_bin = [&](index_t s, auto&& visit) {
      const auto [i0, j0] = bin(segment_[s][0].cwiseMin(segment_[s][1]));
      const auto [i1, j1] = bin(segment_[s][0].cwiseMax(segment_[s][1]));
      for (index_t j = j0; j <= j1; ++j)
        for (index_t i = i0; i <= i1; ++i) visit(j * bins_[0] + i);
    };
    for (index_t s = 0; s < size(); ++s) each_bin(s, [&](index_t b) { ++start_[b + 1]; });
    for (std::size_t b = 1; b < start_.size(); ++b) start_[b] += start_[b - 1];
    member_.resize(start_.back());
    std::vector<index_t> fill(start_.begin(), start_.end() - 1);
    for (index_t s = 0; s < size(); ++s) each_bin(s, [&](index_t b) { member_[fill[b]++] = s; });
  }
  std::array<index_t, 2> bin(const vec2& x) const {
    std::array<index_t, 2> ij{};
    for (int k = 0; k < 2; ++k)
      ij[k] = static_cast<index_t>(std::clamp(std::floor((x[k] - lo_[k]) / width_), 0.0, double(bins_[k] - 1)));
    return ij;
  }

  std::vector<segment_type> segment_;
  std::vector<face_type> face_;
  vec2 lo_ = vec2::Zero();
  double width_ = 1.0;
  std::array<index_t, 2> bins_{1, 1};
  std::vector<index_t> start_, member_;
};

}  // namespace rkpm
