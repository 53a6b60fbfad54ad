#pragma once
// point_reference: what each quadrature point keeps of the configurations before its current
// reference once the solver has re-referenced its kernels (docs/method.md section 5.8):
//   F_r   the deformation gradient of the current reference relative to the initial one, so
//         that the material sees the total F = F_rel F_r (79) whatever the reference;
//   V_0/w the point's initial volume per unit of its current weight, so that quantities per
//         unit initial volume (the plastic work) are summed with their initial weights.
// Empty until the first re-reference: a Lagrangian run reads nothing of it and keeps its bits.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <rkpm/core/block_matrix.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/io/checkpoint.hpp>

namespace rkpm {

// The distortion of an in-plane F (81): its largest principal stretch or the inverse of its
// smallest, from the eigenvalues of C = F^T F.
inline double distortion(const mat2& F) {
  const mat2 C = F.transpose() * F;
  const double mean = 0.5 * C.trace(), radius = std::sqrt(std::max(0.0, mean * mean - C.determinant()));
  const double most = std::sqrt(mean + radius), least = std::sqrt(std::max(mean - radius, 0.0));
  return std::max(most, least > 0.0 ? 1.0 / least : std::numeric_limits<double>::infinity());
}

class point_reference {
 public:
  // Whether the points have been re-referenced at least once.
  bool active() const { return !F_.empty(); }
  // F = F_rel F_r (79).
  block_matrix total(index_t q, const block_matrix& relative) const { return relative * F_[q]; }
  // F_rel = F F_r^-1.
  block_matrix relative(index_t q, const block_matrix& total) const { return total * inverse(F_[q]); }
  // det F_r: the ratio of the current reference volume to the initial one.
  double volume_change(index_t q) const { return F_[q].determinant(); }
  // V_0 / w_q.
  double initial_volume_per_weight(index_t q) const { return initial_per_weight_[q]; }

  // The current configuration becomes the reference: `total(q)` the points' total F there, the
  // old and new weights those of the same material points in the old and new references.
  template <class TotalF>
  void advance(index_t points, const TotalF& total_F, const std::vector<double>& old_weight,
               const std::vector<double>& new_weight) {
    const bool first = !active();
    F_.resize(points);
    initial_per_weight_.resize(points, 1.0);
    for (index_t q = 0; q < points; ++q) {
      F_[q] = total_F(q);
      initial_per_weight_[q] = (first ? 1.0 : initial_per_weight_[q]) * old_weight[q] / new_weight[q];
    }
  }

  // Checkpoint (io/checkpoint.hpp): empty sections for a Lagrangian run. The count is the whole
  // model's points (`whole`); on a rank's part the arrays are its `points` (its layout maps them).
  void save(io::checkpoint_writer& w, index_t whole) const {
    w.value("points.reference_count", static_cast<std::uint64_t>(active() ? whole : 0));
    w.array("points.reference_F", F_);
    w.array("points.initial_volume_per_weight", initial_per_weight_);
  }
  void load(io::checkpoint_reader& r, index_t points) {
    std::uint64_t n = 0;
    r.value("points.reference_count", n);
    F_.resize(n > 0 ? points : 0);
    initial_per_weight_.resize(F_.size());
    r.array("points.reference_F", F_);
    r.array("points.initial_volume_per_weight", initial_per_weight_);
  }

 private:
  std::vector<block_matrix> F_;
  std::vector<double> initial_per_weight_;
};

}  // namespace rkpm
