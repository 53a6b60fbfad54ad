#pragma once
// particle_set<Dim>: the particles of an RK discretization in the reference configuration.
//   position  #particles list of X_I
//   volume    #particles list of dV_I (the quadrature weight of the particle in (P3))
//   support   #particles list of a_I, one support size per direction (docs/method.md section 2.3)

#include <cmath>
#include <vector>

#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>

namespace rkpm {

template <int Dim>
struct particle_set {
  std::vector<vec<Dim>> position;
  std::vector<double> volume;
  std::vector<vec<Dim>> support;

  index_t size() const { return static_cast<index_t>(position.size()); }

  // Throws rkpm::error naming the first inconsistent particle.
  void validate() const {
    if (volume.size() != position.size() || support.size() != position.size())
      fail("particle set: {} positions but {} volumes and {} supports; give one of each per particle",
           position.size(), volume.size(), support.size());
    if (position.empty()) fail("particle set is empty: give at least one particle");
    for (index_t i = 0; i < size(); ++i) {
      if (!position[i].allFinite()) fail("particle {}: position is not finite", i);
      if (!(volume[i] > 0.0) || !std::isfinite(volume[i]))
        fail("particle {}: volume {} must be positive and finite", i, volume[i]);
      for (int k = 0; k < Dim; ++k)
        if (!(support[i][k] > 0.0) || !std::isfinite(support[i][k]))
          fail("particle {}: support {} in direction {} must be positive and finite; "
               "set a = s * h with a support factor s > 0",
               i, support[i][k], k);
    }
  }
};

// A regular grid of counts[k] particles per direction on the box [lo, hi], with the support
// a_k = support_factor * h_k and the tributary volume of each particle (corner 1/4, edge 1/2,
// interior one cell), so that the volumes add up to the box.
template <int Dim>
particle_set<Dim> make_grid_particles(const vec<Dim>& lo, const vec<Dim>& hi,
                                      const Eigen::Matrix<int, Dim, 1>& counts,
                                      double support_factor) {
  vec<Dim> h;
  for (int k = 0; k < Dim; ++k) {
    if (counts[k] < 2) fail("grid particles: need at least 2 particles per direction, got {} in direction {}", counts[k], k);
    if (!(hi[k] > lo[k])) fail("grid particles: empty box in direction {}", k);
    h[k] = (hi[k] - lo[k]) / (counts[k] - 1);
  }
  if (!(support_factor > 0.0)) fail("grid particles: support factor {} must be positive", support_factor);
  particle_set<Dim> p;
  index_t total = 1;
  for (int k = 0; k < Dim; ++k) total *= counts[k];
  p.position.reserve(total);
  p.volume.reserve(total);
  p.support.reserve(total);
  for (index_t n = 0; n < total; ++n) {
    index_t rest = n;
    vec<Dim> x;
    double v = 1.0;
    for (int k = 0; k < Dim; ++k) {
      const index_t i = rest % counts[k];
      rest /= counts[k];
      x[k] = lo[k] + h[k] * static_cast<double>(i);
      v *= (i == 0 || i == counts[k] - 1) ? 0.5 * h[k] : h[k];
    }
    p.position.push_back(x);
    p.volume.push_back(v);
    p.support.push_back(support_factor * h);
  }
  return p;
}

}  // namespace rkpm
