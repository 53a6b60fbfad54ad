#pragma once
// segment_grid: a uniform grid over the segments of one rigid tool, in the tool's own frame
// (docs/method.md section 9.3: contact search with a grid, not all pairs). The tool only translates,
// so the grid is built once and queried at y = x - u(t). Each segment is listed in every cell
// that its bounding box, grown by the tool's reach, overlaps; so the one cell containing y
// lists every segment that could catch y (rigid_tool::catches), each once.

#include <algorithm>
#include <cmath>
#include <span>
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
    start_.assign(count_[0] * count_[1] + 1, 0);
    // Two passes: count, then fill (counting sort by cell).
    for (int pass = 0; pass < 2; ++pass) {
      std::vector<index_t> fill;
      if (pass == 1) {
        for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
        fill.assign(start_.begin(), start_.end() - 1);
        list_.resize(start_.back());
      }
      for (index_t k = 0; k < ns; ++k) {
        const vec2 a = P[k].cwiseMin(P[k + 1]).array() - reach;
        const vec2 b = P[k].cwiseMax(P[k + 1]).array() + reach;
        const index_t i0 = clamp_cell(a[0], 0), i1 = clamp_cell(b[0], 0);
        const index_t j0 = clamp_cell(a[1], 1), j1 = clamp_cell(b[1], 1);
        for (index_t j = j0; j <= j1; ++j)
          for (index_t i = i0; i <= i1; ++i) {
            const index_t c = j * count_[0] + i;
            if (pass == 0)
              ++start_[c + 1];
            else
              list_[fill[c]++] = k;
          }
      }
    }
  }

  // Segments that could catch y (tool frame); empty far from the tool. Does not allocate.
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
  index_t clamp_cell(double x, int d) const {
    return std::clamp<index_t>(static_cast<index_t>(std::floor((x - lo_[d]) / cell_)), 0, count_[d] - 1);
  }

  vec2 lo_ = vec2::Zero();
  double cell_ = 1.0;
  index_t count_[2] = {0, 0};
  std::vector<index_t> start_;
  std::vector<index_t> list_;
};

}  // namespace rkpm::contact
