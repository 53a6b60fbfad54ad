#pragma once
// Test-function gradients of variationally consistent integration (VCI; docs/method.md section
// 3.5, (19c)-(19c'')), corrected so that the integration constraint (19a) holds for every
// particle and the internal forces still sum to zero at every point (linear momentum).
//
//   g_I(X_q) = grad N_I(X_q) + xi_I - <xi>_q,   <xi>_q = mean of xi_J over the n_q particles of point q
//
// One constant vector xi_I per particle, as in Chen, Hillman, Rueter (2013), minus its mean over
// each point's particles: without that mean the corrections of a point's particles do not cancel,
// sum_I g_I(X_q) != 0, and the force (37) of a non-uniform stress has a net resultant (a
// 40-step impact drifted by 2e-4 of its momentum). With it, (19a) for all I is the linear system
//
//   sum_J A_IJ xi_J = r_I,   A_IJ = sum_q w_q (delta_IJ - 1 / n_q)   (I, J both of point q)
//   r_I = b_I - sum_q [grad N_I + e_r N_I / R_q] w_q                                  (19c'')
//
// A is a weighted graph Laplacian: symmetric, positive semi-definite, zero on constants (which
// change no g_I). The system is compatible because sum_I r_I = 0 (the rule integrates constants
// exactly and sum_I b_I is the closed boundary's integral of n omega), so conjugate gradients
// with Jacobi scaling solve it, matrix-free over the shape table, starting from the per-particle
// solution of (19c).

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <rkpm/core/error.hpp>
#include <rkpm/discretization/integration_constraint.hpp>
#include <rkpm/discretization/quadrature_points.hpp>
#include <rkpm/discretization/shape_table.hpp>

namespace rkpm {

namespace detail {

// The operator of (19c''): y = A x, per component, over the points of the table.
class vci_operator {
 public:
  vci_operator(const quadrature_points& points, const shape_table<2>& at_points)
      : points_(points), table_(at_points) {}

  void apply(const std::vector<double>& x, std::vector<double>& y) const {
    std::fill(y.begin(), y.end(), 0.0);
    for (index_t q = 0; q < points_.size(); ++q) {
      const index_t begin = table_.offset[q], end = table_.offset[q + 1];
      if (begin == end) continue;
      double mean = 0.0;
      for (index_t e = begin; e < end; ++e) mean += x[table_.neighbor[e]];
      mean /= static_cast<double>(end - begin);
      for (index_t e = begin; e < end; ++e) y[table_.neighbor[e]] += points_.weight[q] * (x[table_.neighbor[e]] - mean);
    }
  }

  std::vector<double> diagonal(index_t particles) const {
    std::vector<double> d(particles, 0.0);
    for (index_t q = 0; q < points_.size(); ++q) {
      const index_t begin = table_.offset[q], end = table_.offset[q + 1];
      for (index_t e = begin; e < end; ++e)
        d[table_.neighbor[e]] += points_.weight[q] * (1.0 - 1.0 / static_cast<double>(end - begin));
    }
    return d;
  }

 private:
  const quadrature_points& points_;
  const shape_table<2>& table_;
};

inline double max_abs(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

// Preconditioned conjugate gradients for A x = r from the start x; stops when every particle's
// residual is below `target` (round-off of the sums that make up r: a nearly consistent rule
// has a small r made of large terms, and the residual cannot go below their round-off).
inline void solve_vci_system(const vci_operator& A, const std::vector<double>& diagonal, const std::vector<double>& r,
                             std::vector<double>& x, double target) {
  const std::size_t n = r.size();
  std::vector<double> res(n), z(n), p(n), Ap(n);
  A.apply(x, Ap);
  for (std::size_t I = 0; I < n; ++I) res[I] = r[I] - Ap[I];
  auto precondition = [&] {
    for (std::size_t I = 0; I < n; ++I) z[I] = diagonal[I] > 0.0 ? res[I] / diagonal[I] : 0.0;
  };
  precondition();
  p = z;
  double rz = 0.0;
  for (std::size_t I = 0; I < n; ++I) rz += res[I] * z[I];
  const std::size_t limit = 10 * n + 100;
  for (std::size_t it = 0; it < limit; ++it) {
    if (max_abs(res) <= target) return;
    A.apply(p, Ap);
    double pAp = 0.0;
    for (std::size_t I = 0; I < n; ++I) pAp += p[I] * Ap[I];
    if (!(pAp > 0.0)) break;
    const double alpha = rz / pAp;
    for (std::size_t I = 0; I < n; ++I) {
      x[I] += alpha * p[I];
      res[I] -= alpha * Ap[I];
    }
    precondition();
    double rz_next = 0.0;
    for (std::size_t I = 0; I < n; ++I) rz_next += res[I] * z[I];
    const double beta = rz_next / rz;
    rz = rz_next;
    for (std::size_t I = 0; I < n; ++I) p[I] = z[I] + beta * p[I];
  }
  if (max_abs(res) > target)
    fail("variationally consistent integration: the correction system (docs/method.md (19c'')) did not converge "
         "(largest residual {:.3g}, asked {:.3g}); the particles' supports may not overlap "
         "enough: enlarge the support or refine the background cells",
         max_abs(res), target);
}

}  // namespace detail

// VCI test gradients (#entries of at_points) for the boundary integrals b_I of
// integration_constraint.hpp.
inline std::vector<vec2> vci_test_gradients(const quadrature_points& points, const shape_table<2>& at_points,
                                            const std::vector<vec2>& boundary_integral, bool axisymmetric) {
  const auto n = static_cast<index_t>(boundary_integral.size());
  std::vector<vec2> sum(n, vec2::Zero());
  std::vector<double> magnitude(n, 0.0), support_weight(n, 0.0);
  detail::domain_sums(points, at_points, at_points.grad, axisymmetric, sum, magnitude);
  for (index_t q = 0; q < points.size(); ++q)
    for (index_t e = at_points.offset[q]; e < at_points.offset[q + 1]; ++e)
      support_weight[at_points.neighbor[e]] += points.weight[q];

  double largest_term = 0.0;  // of the constraint's sums, max_I (sum_q |terms| + |b_I|)
  for (index_t I = 0; I < n; ++I)
    largest_term = std::max(largest_term, magnitude[I] + boundary_integral[I].cwiseAbs().maxCoeff());
  const detail::vci_operator A(points, at_points);
  const std::vector<double> diagonal = A.diagonal(n);
  std::array<std::vector<double>, 2> xi;
  for (int d = 0; d < 2; ++d) {
    std::vector<double> r(n, 0.0);
    xi[d].assign(n, 0.0);
    for (index_t I = 0; I < n; ++I) {
      r[I] = boundary_integral[I][d] - sum[I][d];
      if (support_weight[I] > 0.0) xi[d][I] = r[I] / support_weight[I];  // (19c), the start
      else if (r[I] != 0.0)
        fail("variationally consistent integration: particle {} is covered by no quadrature point but touches "
             "the boundary; refine the background cells or enlarge the support",
             I);
    }
    detail::solve_vci_system(A, diagonal, r, xi[d], 1e-14 * largest_term);
  }

  std::vector<vec2> g(at_points.grad);
  for (index_t q = 0; q < points.size(); ++q) {
    const index_t begin = at_points.offset[q], end = at_points.offset[q + 1];
    vec2 mean = vec2::Zero();
    for (index_t e = begin; e < end; ++e) mean += vec2(xi[0][at_points.neighbor[e]], xi[1][at_points.neighbor[e]]);
    mean /= static_cast<double>(std::max<index_t>(end - begin, 1));
    for (index_t e = begin; e < end; ++e)
      g[e] += vec2(xi[0][at_points.neighbor[e]], xi[1][at_points.neighbor[e]]) - mean;
  }
  return g;
}

}  // namespace rkpm
