#pragma once
// neighbor_search<Dim>: cell lists over the particles' reference positions. Cells are as large
// as the largest support in each direction, so the particles whose support covers a point x
// lie in the 3^Dim cells around x. Set-up is O(N) (counting sort); a query returns every
// particle with |x_k - X_Ik| < a_Ik in all directions, in ascending order, with no cap; with
// cracks (2D), only the particles whose sight line from x crosses none of them (docs/method.md
// (112)). A search over some of the particles (one body's, search_rows.hpp's body_searches)
// finds only those, by their indices in the whole set.

#include <algorithm>
#include <vector>

#include <rkpm/core/error.hpp>
#include <rkpm/discretization/crack_set.hpp>
#include <rkpm/discretization/particle_set.hpp>
#include <rkpm/kernel/window.hpp>

namespace rkpm {

template <int Dim>
class neighbor_search {
 public:
  // `cracks`: kept by pointer (null or empty: none), as the particles are.
  explicit neighbor_search(const particle_set<Dim>& particles, const crack_set* cracks = nullptr)
      : neighbor_search(particles, cracks, nullptr, particles.size()) {}

  // Only the particles `only` (indices into `particles`, at least one) are found.
  neighbor_search(const particle_set<Dim>& particles, const crack_set* cracks, const std::vector<index_t>& only)
      : neighbor_search(particles, cracks, only.data(), static_cast<index_t>(only.size())) {}

  // Appends to `out` (after clearing it) the particles whose support contains x.
  void query(const vec<Dim>& x, std::vector<index_t>& out) const {
    out.clear();
    Eigen::Matrix<index_t, Dim, 1> c = cell_index(x);
    Eigen::Matrix<index_t, Dim, 1> first, last;
    for (int k = 0; k < Dim; ++k) {
      first[k] = std::max<index_t>(c[k] - 1, 0);
      last[k] = std::min<index_t>(c[k] + 1, count_[k] - 1);
      if (first[k] > last[k]) return;  // x far outside the particle cloud
    }
    Eigen::Matrix<index_t, Dim, 1> cur = first;
    while (true) {
      const index_t f = flat(cur);
      for (index_t s = start_[f]; s < start_[f + 1]; ++s) {
        const index_t i = sorted_[s];
        if (kernel::in_support<Dim>(x - particles_->position[i], particles_->support[i]) && visible(x, i))
          out.push_back(i);
      }
      int k = 0;
      while (k < Dim && cur[k] == last[k]) {
        cur[k] = first[k];
        ++k;
      }
      if (k == Dim) break;
      ++cur[k];
    }
    std::sort(out.begin(), out.end());
  }

  std::vector<index_t> query(const vec<Dim>& x) const {
    std::vector<index_t> out;
    query(x, out);
    return out;
  }

  const particle_set<Dim>& particles() const { return *particles_; }
  const crack_set* cracks() const { return cracks_; }

 private:
  // The particles only[0 .. count) (null: all of them, 0 .. count).
  neighbor_search(const particle_set<Dim>& particles, const crack_set* cracks, const index_t* only, index_t count)
      : particles_(&particles), cracks_(cracks && !cracks->empty() ? cracks : nullptr) {
    if (Dim != 2 && cracks_) fail("cracks are segments in the plane: a {}-D particle set has none", Dim);
    particles.validate();
    if (count == 0) fail("a neighbour search over none of the particles: give it at least one");
    const auto id = [&](index_t k) { return only ? only[k] : k; };
    for (index_t k = 0; k < count; ++k)
      if (id(k) < 0 || id(k) >= particles.size())
        fail("a neighbour search over particle {} of {}: give indices of the particle set", id(k), particles.size());
    lo_ = particles.position[id(0)];
    vec<Dim> hi = lo_;
    cell_ = vec<Dim>::Zero();
    for (index_t k = 0; k < count; ++k) {
      lo_ = lo_.cwiseMin(particles.position[id(k)]);
      hi = hi.cwiseMax(particles.position[id(k)]);
      cell_ = cell_.cwiseMax(particles.support[id(k)]);
    }
    index_t total = 1;
    for (int k = 0; k < Dim; ++k) {
      count_[k] = static_cast<index_t>(std::floor((hi[k] - lo_[k]) / cell_[k])) + 1;
      total *= count_[k];
    }
    // Counting sort of the particles by cell: start_[c] .. start_[c+1] in sorted_.
    start_.assign(total + 1, 0);
    std::vector<index_t> cell_of(count);
    for (index_t k = 0; k < count; ++k) {
      cell_of[k] = flat(cell_index(particles.position[id(k)]));
      ++start_[cell_of[k] + 1];
    }
    for (index_t c = 0; c < total; ++c) start_[c + 1] += start_[c];
    sorted_.resize(count);
    std::vector<index_t> fill(start_.begin(), start_.end() - 1);
    for (index_t k = 0; k < count; ++k) sorted_[fill[cell_of[k]]++] = id(k);
  }

  bool visible(const vec<Dim>& x, index_t i) const {
    if constexpr (Dim == 2) return !cracks_ || !cracks_->blocks(x, particles_->position[i]);
    else return true;
  }
  Eigen::Matrix<index_t, Dim, 1> cell_index(const vec<Dim>& x) const {
    Eigen::Matrix<index_t, Dim, 1> c;
    for (int k = 0; k < Dim; ++k) {
      const double t = std::floor((x[k] - lo_[k]) / cell_[k]);
      // Clamp far-away points just outside the grid so the 3^Dim stencil logic stays valid.
      c[k] = static_cast<index_t>(std::clamp(t, -2.0, static_cast<double>(count_[k] + 1)));
    }
    return c;
  }
  index_t flat(const Eigen::Matrix<index_t, Dim, 1>& c) const {
    index_t f = 0;
    for (int k = Dim - 1; k >= 0; --k) f = f * count_[k] + c[k];
    return f;
  }

  const particle_set<Dim>* particles_;
  const crack_set* cracks_;
  vec<Dim> lo_, cell_;
  Eigen::Matrix<index_t, Dim, 1> count_;
  std::vector<index_t> start_;
  std::vector<index_t> sorted_;
};

}  // namespace rkpm
