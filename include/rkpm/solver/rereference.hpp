#pragma once
// Re-referencing the kernels (docs/method.md section 5.8): what the solver needs to rebuild its
// model in the current configuration and carry its fields over.
//   rereference_policy     when: by the distortion of the kernels since the last reference (81),
//                          every N steps, or never (the default: a Lagrangian run)
//   deformed_particles     the particles at their current positions, with supports that follow
//                          the deformation (82) and volumes from the deformed cells; the cells'
//                          corners move with the particles (the mesh nodes are the particles)
//   carried_points         the quadrature points as the same material points at their current
//                          positions, each weight times J_rel
//   refuse_across_axis     in a section, no particle or point carried across the axis

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>


#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/discretization/background_mesh.hpp>
#include <rkpm/discretization/particle_set.hpp>
#include <rkpm/discretization/quadrature_points.hpp>
#include <rkpm/discretization/shape_table.hpp>

namespace rkpm {

struct rereference_policy {
  // Re-reference when a point's principal stretch since the last reference, or its inverse,
  // exceeds this (> 1); 0: not by distortion.
  double max_stretch = 0.0;
  // Re-reference every this many steps (1: the updated-Lagrangian limit); 0: not by count.
  index_t every_steps = 0;
  // On several processes, after a re-reference: the particles are partitioned again when the
  // most loaded process's work (parallel::load_imbalance) exceeds this multiple of the mean
  // (>= 1; infinity keeps the set-up's partition). The results are the same bits either way.
  double rebalance_above = 1.1;

  bool enabled() const { return max_stretch > 0.0 || every_steps > 0; }
  void validate() const {
    if (!(max_stretch == 0.0 || max_stretch > 1.0) || !std::isfinite(max_stretch))
      fail("rereference: max_stretch {} must exceed 1 (a principal stretch since the last reference), or be 0 "
           "to re-reference by step count only",
           max_stretch);
    if (every_steps < 0) fail("rereference: every_steps {} must be positive, or 0 to re-reference by stretch only",
                              every_steps);
    if (!(rebalance_above >= 1.0))
      fail("rereference: rebalance_above {} must be at least 1 (the largest process's load over the mean), or "
           "infinity to keep the partition",
           rebalance_above);
  }
};

// The left stretch V = sqrt(F F^T) of an in-plane F (F = V R): for a 2x2 B = F F^T,
// sqrt(B) = (B + sqrt(det B) I) / sqrt(tr B + 2 sqrt(det B)).
inline mat2 left_stretch(const mat2& F) {
  const mat2 B = F * F.transpose();
  const double root_det = std::sqrt(std::max(B.determinant(), 0.0));
  return (B + root_det * mat2::Identity()) / std::sqrt(B.trace() + 2.0 * root_det);
}

// The particles moved to x (the current positions), each support a_I stretched by the
// deformation since the last reference, F_I (the in-plane block at the particle), without its
// rotation: the box that holds the support stretched by V_I, a'_k = sum_j |V_kj| a_j (82), so
// that a particle keeps the neighbours it had, and a spinning body keeps its supports. (A body
// turned by a large angle keeps axis-aligned supports: an anisotropic support does not turn
// with it.) Volumes: a quarter of each deformed cell at each of its corners (of its area's
// magnitude when the cells may be tangled: `tangled`, the points carried, not made on them).
inline std::pair<particle_set<2>, background_mesh> deformed_particles(const particle_set<2>& particles,
                                                                      const background_mesh& mesh,
                                                                      const std::vector<vec2>& x,
                                                                      const std::vector<mat2>& F, bool tangled) {
  particle_set<2> next;
  next.position = x;
  next.support.resize(particles.size());
  // (A particle that no point reaches, a free one cut off by cracks, has no F: its support stays.)
  for (index_t I = 0; I < particles.size(); ++I)
    next.support[I] = F[I].allFinite() && F[I].determinant() > 0.0
                          ? vec2(left_stretch(F[I]).cwiseAbs() * particles.support[I])
                          : particles.support[I];
  background_mesh cells{x, mesh.cell, tangled};
  next.volume.assign(particles.size(), 0.0);
  for (index_t c = 0; c < cells.cells(); ++c) {
    const double area = tangled ? std::abs(cells.cell_area(c)) : cells.cell_area(c);
    if (!tangled && !(area > 0.0))
      fail("re-referencing: cell {} has area {:.3g} in the current configuration (a cell turned inside out); "
           "re-reference earlier (a smaller max_stretch) or refine the particles",
           c, area);
    for (const stored_index n : cells.cell[c]) next.volume[n] += 0.25 * area;
  }
  for (index_t I = 0; I < particles.size(); ++I)
    if (!(next.volume[I] > 0.0)) next.volume[I] = particles.volume[I];  // cells around it all flat
  return {std::move(next), std::move(cells)};
}

// In a section the body stays on its side of the axis: a particle or a point carried to r < 0
// (a point to r <= 0; the axis particles are held at r = 0, to round-off of 1e-9 of the body's
// size) would have a hoop stretch of no meaning and no particles beyond it to build its kernel
// on. Refused by name: the layer by the axis has folded across it.
inline void refuse_across_axis(const std::vector<vec2>& x, const std::vector<vec2>& X, bool points, double time) {
  double size = 0.0;
  for (const vec2& p : X) size = std::max(size, p.cwiseAbs().maxCoeff());
  const double round_off = 1e-9 * size;
  for (std::size_t k = 0; k < x.size(); ++k)
    if (points ? !(x[k][0] > 0.0) : !(x[k][0] >= -round_off))
      fail("t = {:.6g} s: re-referencing: {} {} (at r = {:.4g} m, z = {:.4g} m at the last reference) has been carried "
           "across the axis, to r = {:.3g} m: the material by the axis has folded over it; re-reference earlier (a "
           "smaller max_stretch) or refine the particles",
           time, points ? "quadrature point" : "particle", k, X[k][0], X[k][1], x[k][0]);
}

// The points of `points` (rows `at_points`, coefficients d) carried to the current configuration:
// the same material points at x_q = X_q + sum_I N_I(X_q) d_I, each weight times relative_J(q),
// the volume it stands for now, so that nothing is interpolated; in a section (`axisymmetric`)
// none across the axis.
template <class RelativeJ>
quadrature_points carried_points(const quadrature_points& points, const shape_table<2>& at_points,
                                 const std::vector<vec2>& d, RelativeJ&& relative_J, bool axisymmetric, double time) {
  quadrature_points carried;
  carried.position.resize(points.position.size());
  carried.weight.resize(points.position.size());
  carried.cell = points.cell;
  for (index_t q = 0; q < points.size(); ++q) {
    carried.position[q] = points.position[q] + at_points.interpolate(q, d);
    carried.weight[q] = points.weight[q] * relative_J(q);
  }
  if (axisymmetric) refuse_across_axis(carried.position, points.position, true, time);
  return carried;
}

}  // namespace rkpm
