#pragma once
// Re-referencing the kernels (docs/method.md section 5.8): what the solver needs to rebuild its
// model in the current configuration and carry its fields over.
//   rereference_policy     when: by the distortion of the kernels since the last reference (81),
//                          every N steps, or never (the default: a Lagrangian run)
//   deformed_particles     the particles at their current positions, with supports that follow
//                          the deformation (82) and volumes from the deformed cells; the cells'
//                          corners move with the particles (the mesh nodes are the particles)
//   solve_coefficients     the coefficients c with sum_J N_J(X_I) c_J = u_I at every particle:
//                          RK shape functions do not interpolate (83)

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/discretization/background_mesh.hpp>
#include <rkpm/discretization/particle_set.hpp>
#include <rkpm/discretization/shape_table.hpp>

namespace rkpm {

struct rereference_policy {
  // Re-reference when a point's principal stretch since the last reference, or its inverse,
  // exceeds this (> 1); 0: not by distortion.
  double max_stretch = 0.0;
  // Re-reference every this many steps (1: the updated-Lagrangian limit); 0: not by count.
  index_t every_steps = 0;

  bool enabled() const { return max_stretch > 0.0 || every_steps > 0; }
  void validate() const {
    if (!(max_stretch == 0.0 || max_stretch > 1.0) || !std::isfinite(max_stretch))
      fail("rereference: max_stretch {} must exceed 1 (a principal stretch since the last reference), or be 0 "
           "to re-reference by step count only",
           max_stretch);
    if (every_steps < 0) fail("rereference: every_steps {} must be positive, or 0 to re-reference by stretch only",
                              every_steps);
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
// with it.) Volumes: a quarter of each deformed cell at each of its corners.
inline std::pair<particle_set<2>, background_mesh> deformed_particles(const particle_set<2>& particles,
                                                                      const background_mesh& mesh,
                                                                      const std::vector<vec2>& x,
                                                                      const std::vector<mat2>& F) {
  particle_set<2> next;
  next.position = x;
  next.support.resize(particles.size());
  for (index_t I = 0; I < particles.size(); ++I)
    next.support[I] = left_stretch(F[I]).cwiseAbs() * particles.support[I];
  background_mesh cells{x, mesh.cell};
  next.volume.assign(particles.size(), 0.0);
  for (index_t c = 0; c < cells.cells(); ++c) {
    const double area = cells.cell_area(c);
    if (!(area > 0.0))
      fail("re-referencing: cell {} has area {:.3g} in the current configuration (a cell turned inside out); "
           "re-reference earlier (a smaller max_stretch) or refine the particles",
           c, area);
    for (const stored_index n : cells.cell[c]) next.volume[n] += 0.25 * area;
  }
  return {std::move(next), std::move(cells)};
}

// c with sum_J N_J(X_I) c_J = u_I at every particle I (83): BiCGSTAB with an incomplete LU
// preconditioner on the rows of `at_particles`, to a residual of 1e-14 of |u|; a sparse LU if
// that does not converge. The same bits on any thread count (a row is summed by one thread).
inline std::vector<vec2> solve_coefficients(const shape_table<2>& at_particles, const std::vector<vec2>& u) {
  using sparse = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  const auto n = static_cast<Eigen::Index>(u.size());
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(at_particles.neighbor.size());
  for (index_t I = 0; I < static_cast<index_t>(n); ++I)
    for (index_t e = at_particles.offset[I]; e < at_particles.offset[I + 1]; ++e)
      entries.emplace_back(I, at_particles.neighbor[e], at_particles.N[e]);
  sparse A(n, n);
  A.setFromTriplets(entries.begin(), entries.end());
  Eigen::MatrixX2d rhs(n, 2);
  for (Eigen::Index I = 0; I < n; ++I) rhs.row(I) = u[static_cast<std::size_t>(I)].transpose();
  Eigen::MatrixX2d c(n, 2);
  Eigen::BiCGSTAB<sparse, Eigen::IncompleteLUT<double>> iterative;
  iterative.setTolerance(1e-14);
  iterative.setMaxIterations(1000);
  iterative.compute(A);
  bool solved = iterative.info() == Eigen::Success;
  for (int k = 0; solved && k < 2; ++k) {
    if (rhs.col(k).squaredNorm() == 0.0) {
      c.col(k).setZero();
      continue;
    }
    c.col(k) = iterative.solve(rhs.col(k));
    solved = iterative.info() == Eigen::Success;
  }
  if (!solved) {
    Eigen::SparseLU<Eigen::SparseMatrix<double>> direct(A);
    if (direct.info() != Eigen::Success)
      fail("re-referencing: the shape functions at the particles form a singular matrix, so the fields cannot "
           "be carried to the new reference; re-reference earlier (a smaller max_stretch) or enlarge the supports");
    c = direct.solve(rhs);
  }
  std::vector<vec2> out(u.size());
  for (Eigen::Index I = 0; I < n; ++I) out[static_cast<std::size_t>(I)] = c.row(I).transpose();
  return out;
}

}  // namespace rkpm
