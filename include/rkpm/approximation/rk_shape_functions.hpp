#pragma once
// RK shape functions and their gradients at one point (docs/method.md (8)-(14),
// section 2):
//   N_I(x) = H(0)^T M(x)^-1 H(z_I) Phi_a(x - x_I) dV_I,   z_I = (x - x_I) / s
//   M(x)   = sum_I H(z_I) H(z_I)^T Phi_a(x - x_I) dV_I
// with the basis scaled by s (the mean support of the neighbors), and the gradient from
// d(M^-1) = -M^-1 dM M^-1. Reproduction makes N independent of s; s only keeps M well
// conditioned. A singular or badly conditioned M is an error that names the point.

#include <Eigen/Dense>
#include <limits>
#include <vector>

#include <rkpm/concepts/correction.hpp>
#include <rkpm/concepts/kernel.hpp>
#include <rkpm/core/error.hpp>
#include <rkpm/discretization/particle_set.hpp>
#include <rkpm/kernel/window.hpp>

namespace rkpm {

// Largest accepted condition number of the scaled moment matrix. A well-posed point has
// 1e1..1e4; beyond this the correction is dominated by round-off.
inline constexpr double default_max_moment_condition = 1e10;

template <Kernel K, Correction C, int Dim>
class rk_shape_functions {
 public:
  static constexpr int basis_size = C::template size<Dim>;
  using basis_vector = Eigen::Matrix<double, basis_size, 1>;
  using basis_gradient = Eigen::Matrix<double, basis_size, Dim>;
  using moment_matrix = Eigen::Matrix<double, basis_size, basis_size>;

  rk_shape_functions() = default;
  explicit rk_shape_functions(double max_condition) : max_condition_(max_condition) {}

  // Values N (#neighbors) and gradients grad (#neighbors, each a Dim-vector) at x for the
  // given neighbors of x. Throws rkpm::error if the moment matrix cannot be inverted reliably.
  // (Defined below the class, not inline, so that a program can compile it once: see
  // discretization/shape_table_instances.hpp.)
  void evaluate(const vec<Dim>& x, const particle_set<Dim>& particles, const std::vector<index_t>& neighbors,
                std::vector<double>& N, std::vector<vec<Dim>>& grad) const {
    evaluate_or_refuse(x, particles, neighbors, N, grad, true);
  }
  // The same, but false (N and grad empty) where evaluate() throws: a point cut off by cracks
  // from the particles it would need (discretization/crack_set.hpp).
  bool try_evaluate(const vec<Dim>& x, const particle_set<Dim>& particles, const std::vector<index_t>& neighbors,
                    std::vector<double>& N, std::vector<vec<Dim>>& grad) const {
    return evaluate_or_refuse(x, particles, neighbors, N, grad, false);
  }

  double max_condition() const { return max_condition_; }

 private:
  bool evaluate_or_refuse(const vec<Dim>& x, const particle_set<Dim>& particles, const std::vector<index_t>& neighbors,
                          std::vector<double>& N, std::vector<vec<Dim>>& grad, bool throwing) const;
  bool check_conditioning(const vec<Dim>& x, const moment_matrix& M, std::size_t n, bool throwing) const;
  static std::string format_point(const vec<Dim>& x) {
    std::string s;
    for (int k = 0; k < Dim; ++k) s += fmt::format("{}{:.6g}", k ? ", " : "", x[k]);
    return s;
  }

  double max_condition_ = default_max_moment_condition;
};

template <Kernel K, Correction C, int Dim>
bool rk_shape_functions<K, C, Dim>::evaluate_or_refuse(const vec<Dim>& x, const particle_set<Dim>& particles,
                                                       const std::vector<index_t>& neighbors, std::vector<double>& N,
                                                       std::vector<vec<Dim>>& grad, bool throwing) const {
  const std::size_t n = neighbors.size();
  N.resize(n);
  grad.resize(n);
  if (n == 0 && !throwing) return false;
  if (n == 0)
    fail("RK shape functions at point ({}): no particle support covers it; "
         "the point lies outside the particle cloud or the supports are too small",
         format_point(x));

  vec<Dim> scale = vec<Dim>::Zero();
  for (index_t I : neighbors) scale += particles.support[I];
  scale /= static_cast<double>(n);

  moment_matrix M = moment_matrix::Zero();
  moment_matrix dM[Dim];
  for (int k = 0; k < Dim; ++k) dM[k].setZero();
  basis_vector h;
  basis_gradient dh;
  for (index_t I : neighbors) {
    const vec<Dim> dx = x - particles.position[I];
    const auto w = kernel::window<K, Dim>(dx, particles.support[I]);
    const double phi = w.value * particles.volume[I];
    C::template evaluate<Dim>(vec<Dim>(dx.cwiseQuotient(scale)), h, dh);
    const moment_matrix hh = h * h.transpose();
    M += hh * phi;
    for (int k = 0; k < Dim; ++k) {
      const basis_vector dhk = dh.col(k) / scale[k];
      dM[k] += (dhk * h.transpose() + h * dhk.transpose()) * phi +
               hh * (w.gradient[k] * particles.volume[I]);
    }
  }

  if (!check_conditioning(x, M, n, throwing)) {
    N.clear();
    grad.clear();
    return false;
  }
  const Eigen::LDLT<moment_matrix> solver(M);
  basis_vector h0 = basis_vector::Zero();
  h0[0] = 1.0;
  const basis_vector b = solver.solve(h0);  // b = M^-1 H(0)
  basis_vector db[Dim];
  for (int k = 0; k < Dim; ++k) db[k] = -solver.solve(basis_vector(dM[k] * b));

  for (std::size_t j = 0; j < n; ++j) {
    const index_t I = neighbors[j];
    const vec<Dim> dx = x - particles.position[I];
    const auto w = kernel::window<K, Dim>(dx, particles.support[I]);
    C::template evaluate<Dim>(vec<Dim>(dx.cwiseQuotient(scale)), h, dh);
    const double bh = b.dot(h);
    N[j] = bh * w.value * particles.volume[I];
    for (int k = 0; k < Dim; ++k) {
      const double dbh = db[k].dot(h) + b.dot(dh.col(k)) / scale[k];
      grad[j][k] = (dbh * w.value + bh * w.gradient[k]) * particles.volume[I];
    }
  }
  return true;
}

template <Kernel K, Correction C, int Dim>
bool rk_shape_functions<K, C, Dim>::check_conditioning(const vec<Dim>& x, const moment_matrix& M, std::size_t n,
                                                       bool throwing) const {
  const Eigen::SelfAdjointEigenSolver<moment_matrix> eig(M, Eigen::EigenvaluesOnly);
  const double lo = eig.eigenvalues().minCoeff();
  const double hi = eig.eigenvalues().maxCoeff();
  const double cond = lo > 0.0 ? hi / lo : std::numeric_limits<double>::infinity();
  if (cond <= max_condition_) return true;
  if (throwing)
    fail("RK moment matrix at point ({}) is singular or badly conditioned: {} neighbors, "
         "condition estimate {:.3g} (limit {:.1g}); the {} basis needs at least {} neighbors "
         "spread in every direction: enlarge the support factor or refine the particles",
         format_point(x), n, cond, max_condition_, C::name, basis_size);
  return false;
}

}  // namespace rkpm
