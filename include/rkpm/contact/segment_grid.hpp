#pragma once
// segment_grid: a uniform grid over segments (docs/method.md section 9.3: contact search with a
// grid, not all pairs). Each segment is listed in every cell that its bounding box, grown by a
// reach, overlaps, in increasing segment order; so the one cell containing a point y lists,
// each once and in order, every segment within the reach of y.
//   - A rigid tool (segment_grid(tool)), in the tool's own frame: the tool only translates, so
//     the grid is built once and queried at y = x - u(t); the reach is the tool's, so the
//     candidates hold every segment that could catch y (rigid_tool::catches).
//   - Moving segments (rebuild(), the deformable masters of body_contact.hpp): built again on
//     every detection, within the buffers reserve() sized.

#include <algorithm>
#include <cmath>
#include <span>
#include <utility>
#include <vector>

#include <rkpm/contact/rigid_tool.hpp>

namespace rkpm::contact {

class segment_grid {
 public:
  segment_grid() = default;

  explicit segment_grid(const rigid_tool& tool) {
    const auto& P = tool.reference_vertices();
    const index_t ns = tool.segments();
    const double reach = tool.reach();
    lo_ = P[0];
    vec2 hi = P[0];
    double total = 0.0;
    for (const vec2& p : P) {
      lo_ = lo_.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    for (index_t k = 0; k < ns; ++k) total += tool.length(k);
    lo_.array() -= reach;
    hi.array() += reach;
    // Cells about as large as a segment (or the reach, if larger) keep the lists short.
    // (never more than 4000 per direction, so that count_ * cell_ always spans the box).
    cell_ = std::max({reach, total / static_cast<double>(ns), (hi - lo_).maxCoeff() / 4000.0});
    for (int d = 0; d < 2; ++d)
      count_[d] = std::clamp<index_t>(static_cast<index_t>(std::ceil((hi[d] - lo_[d]) / cell_)), 1, 4001);
    fill(ns, [&](index_t k) { return std::pair<vec2, vec2>(P[k], P[k + 1]); }, reach);
  }

  // Buffers for rebuild() over `segments` segments, so that rebuilding does not allocate: at most
  // about 4 x segments cells, each segment in at most 4 of them.
  void reserve(index_t segments) {
    max_count_ = std::max<index_t>(1, static_cast<index_t>(std::ceil(2.0 * std::sqrt(static_cast<double>(segments)))));
    start_.reserve(max_count_ * max_count_ + 1);
    cursor_.reserve(max_count_ * max_count_);
    list_.reserve(4 * segments);
  }

  // The grid over `segments` segments whose end points are ends(k) (a pair of vec2) in the
  // current configuration. Square cells at least as large as the longest segment plus twice
  // the reach, so that a segment's grown box spans at most two cells per direction (segments of
  // about one length, as a body's surface has; one long segment makes few large cells).
  template <class Ends>
  void rebuild(index_t segments, Ends&& ends, double reach) {
    if (segments == 0) {
      start_.clear();
      return;
    }
    const auto [a0, b0] = ends(0);
    lo_ = a0.cwiseMin(b0);
    vec2 hi = a0.cwiseMax(b0);
    double longest = 0.0;
    for (index_t k = 0; k < segments; ++k) {
      const auto [a, b] = ends(k);
      lo_ = lo_.cwiseMin(a.cwiseMin(b));
      hi = hi.cwiseMax(a.cwiseMax(b));
      longest = std::max(longest, (b - a).norm());
    }
    lo_.array() -= reach;
    hi.array() += reach;
    const index_t most = std::max<index_t>(max_count_, 1);
    cell_ = std::max({longest + 2.0 * reach, (hi - lo_).maxCoeff() / static_cast<double>(most)});
    for (int d = 0; d < 2; ++d)
      count_[d] = std::clamp<index_t>(static_cast<index_t>(std::ceil((hi[d] - lo_[d]) / cell_)), 1, most);
    fill(segments, ends, reach);
  }

  // The segments within the reach of y (for a tool: that could catch y, in the tool frame), in
  // increasing order; empty far from every segment. Does not allocate.
  std::span<const index_t> candidates(const vec2& y) const {
    if (start_.empty()) return {};
    const double fi = std::floor((y[0] - lo_[0]) / cell_);
    const double fj = std::floor((y[1] - lo_[1]) / cell_);
    if (!(fi >= 0.0 && fj >= 0.0 && fi < static_cast<double>(count_[0]) && fj < static_cast<double>(count_[1])))
      return {};
    const index_t c = static_cast<index_t>(fj) * count_[0] + static_cast<index_t>(fi);
    return {list_.data() + start_[c], static_cast<std::size_t>(start_[c + 1] - start_[c])};
  }

  index_t cells() const { return count_[0] * count_[1]; }

 private:
  // Lists each segment in the cells its box grown by `reach` overlaps (counting sort by cell).
  template <class Ends>
  void fill(index_t segments, Ends&& ends, double reach) {
    start_.assign(count_[0] * count_[1] + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {
      if (pass == 1) {
        for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
        cursor_.assign(start_.begin(), start_.end() - 1);
        list_.resize(start_.back());
      }
      for (index_t k = 0; k < segments; ++k) {
        const auto [p, q] = ends(k);
        const vec2 a = p.cwiseMin(q).array() - reach;
        const vec2 b = p.cwiseMax(q).array() + reach;
        const index_t i0 = clamp_cell(a[0], 0), i1 = clamp_cell(b[0], 0);
        const index_t j0 = clamp_cell(a[1], 1), j1 = clamp_cell(b[1], 1);
        for (index_t j = j0; j <= j1; ++j)
          for (index_t i = i0; i <= i1; ++i) {
            const index_t c = j * count_[0] + i;
            if (pass == 0)
              ++start_[c + 1];
            else
              list_[cursor_[c]++] = k;
          }
      }
    }
  }

  index_t clamp_cell(double x, int d) const {
    return std::clamp<index_t>(static_cast<index_t>(std::floor((x - lo_[d]) / cell_)), 0, count_[d] - 1);
  }

  vec2 lo_ = vec2::Zero();
  double cell_ = 1.0;
  index_t count_[2] = {0, 0};
  index_t max_count_ = 0;         // cells per direction at most, for rebuild()
  std::vector<index_t> start_;    // #cells + 1: where each cell's list starts in list_
  std::vector<index_t> cursor_;   // #cells: fill()'s scratch
  std::vector<index_t> list_;
};

}  // namespace rkpm::contact
