#pragma once
// Essential conditions on physical values (docs/method.md (50)-(51), section 5.7). RK coefficients are not
// nodal values, so "u_r = 0 on the axis" means sum_J N_J(X_I) d_Jr = 0, not d_Ir = 0. Each
// constraint row r reads  sum_J Lambda_rJ v_Jk = g_r(t)  with Lambda_rJ = N_J(X_I).
// Imposed with Lagrange multipliers in the explicit update, this is the M-orthogonal
// projection
//   v <- v - M^-1 Lambda^T (Lambda M^-1 Lambda^T)^-1 (Lambda v - g),
// whose matrix is constant in the Lagrangian setting and factored once. It is sparse: two rows
// couple only when their particles share a neighbour (a band along the axis), so it is kept and
// factored sparse (Eigen's SimplicialLLT in the rows' order, which keeps the band): memory and
// work grow with the number of constraints, not its square (a dense factor of the 1,601 axis
// constraints of the Taylor bar at 10^6 particles would hold 1,601^2 doubles, 20 MB, and cost
// millions of flops of serial solve per step).

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <functional>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include <rkpm/core/error.hpp>
#include <rkpm/discretization/shape_table.hpp>
#include <rkpm/solver/energy.hpp>

namespace rkpm {

// Prescribes the physical velocity component `direction` at particle `particle`;
// an empty `velocity` holds it at rest (and so holds the displacement at its initial value).
struct velocity_constraint {
  index_t particle = 0;
  int direction = 0;
  std::function<double(double)> velocity;
};

// The projector's factorization of A = Lambda M^-1 Lambda^T. Natural ordering: the rows come in
// the order the caller gave, which for constraints along a line is the band order.
using constraint_factor = Eigen::SimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>>;

// A class template (of its factorization, always constraint_factor) only so that it can be
// compiled once: with RKPM_EXTERN_CONSTRAINTS (the project's programs, target rkpm_instances)
// Eigen's sparse assembly, factorization and solve are not instantiated again at the end of
// every file that includes the library (a fifth of what an empty file including
// <rkpm/rkpm.hpp> instantiates).
template <class Factor>
class basic_constraint_projector {
 public:
  // The relative weight eps of (51a): far below any independent row's pivot, far above round-off.
  static constexpr double dependent_rows_tolerance = 1e-10;

  basic_constraint_projector() = default;

  // `global_id`: each particle's index in the whole model when this is one rank's part of it
  // (discrete_model::particle_id; empty: the particles' own indices). The rows are then every
  // rank's copy of the whole model's rows, and the projector orders what it sums by those
  // indices, so that every rank computes the one-process projection, bit for bit.
  basic_constraint_projector(std::vector<velocity_constraint> constraints, const shape_table<2>& at_particles,
                             const std::vector<double>& mass, std::span<const stored_index> global_id = {});

  index_t size() const { return static_cast<index_t>(constraints_.size()); }
  const std::vector<velocity_constraint>& constraints() const { return constraints_; }
  // The particles whose coefficient velocities apply() can change, the columns of the rows, in
  // increasing order of their index in the whole model; every other velocity it leaves as it
  // is, bit for bit.
  const std::vector<index_t>& touched() const { return touched_; }

  // apply(t, v), returning the work of the velocity jump it made (docs/method.md (68)) with the
  // reference velocities v_ref, summed over the particles it can touch (zero elsewhere).
  double apply_with_work(double t, std::vector<vec2>& v, const std::vector<double>& mass,
                         const std::vector<vec2>& v_ref) {
    for (std::size_t k = 0; k < touched_.size(); ++k) v_start_[k] = v[touched_[k]];
    apply(t, v);
    double work = 0.0;
    for (std::size_t k = 0; k < touched_.size(); ++k) {
      const index_t I = touched_[k];
      work += impulse_work_at(mass[I], v[I], v_start_[k], v_ref[I]);
    }
    return work;
  }

  // Projects the coefficient velocities v onto the constraints at time t. No allocation.
  void apply(double t, std::vector<vec2>& v);

  // The same projection for a field of one component per particle (the temperature of
  // thermal/heat_conduction.hpp, with the heat capacities as the weights M given at
  // construction): x <- x - M^-1 Lambda^T (Lambda M^-1 Lambda^T)^-1 (Lambda x - target), so that
  // the physical values Lambda x equal `target` (#rows, in the rows' order). The rows' directions
  // must all be 0 (one system). No allocation.
  void project_values(std::span<double> x, std::span<const double> target);

 private:
  std::vector<velocity_constraint> constraints_;
  std::vector<index_t> offset_, column_, touched_;
  std::vector<vec2> v_start_;  // v at touched_ before the last apply_with_work
  std::vector<double> value_, value_over_mass_;
  // The factor, shared by copies of the projector (Eigen's factorizations cannot be copied or
  // moved; it is not changed after construction).
  std::shared_ptr<const Factor> llt_;
  Eigen::VectorXd rhs_, work_;
};

using constraint_projector = basic_constraint_projector<constraint_factor>;

template <class Factor>
basic_constraint_projector<Factor>::basic_constraint_projector(std::vector<velocity_constraint> constraints,
                                                             const shape_table<2>& at_particles,
                                                             const std::vector<double>& mass,
                                                             std::span<const stored_index> global_id)
    : constraints_(std::move(constraints)) {
  const index_t n = static_cast<index_t>(constraints_.size());
  if (n == 0) return;
  offset_.push_back(0);
  for (const auto& c : constraints_) {
    if (c.particle < 0 || c.particle >= at_particles.points())
      fail("velocity constraint on particle {}: there are {} particles", c.particle, at_particles.points());
    if (c.direction != 0 && c.direction != 1)
      fail("velocity constraint on particle {}: direction {} must be 0 or 1", c.particle, c.direction);
    for (index_t e = at_particles.offset[c.particle]; e < at_particles.offset[c.particle + 1]; ++e) {
      column_.push_back(at_particles.neighbor[e]);
      value_.push_back(at_particles.N[e]);
      value_over_mass_.push_back(at_particles.N[e] / mass[at_particles.neighbor[e]]);
    }
    offset_.push_back(static_cast<index_t>(column_.size()));
  }
  const auto key = [&](index_t I) -> index_t { return global_id.empty() ? I : global_id[I]; };
  touched_ = column_;
  std::ranges::sort(touched_, {}, key);
  touched_.erase(std::unique(touched_.begin(), touched_.end()), touched_.end());
  v_start_.resize(touched_.size());
  // A = Lambda M^-1 Lambda^T per direction (rows of different directions act on different
  // velocity components and do not couple): A_rs = sum_I Lambda_rI Lambda_sI / m_I, over the
  // touched particles in the order of their indices in the whole model (Lambda's columns).
  const auto position = [&](index_t I) {
    return static_cast<index_t>(std::ranges::lower_bound(touched_, key(I), {}, key) - touched_.begin());
  };
  const auto columns = static_cast<Eigen::Index>(touched_.size());
  Eigen::SparseMatrix<double> A(n, n);
  Eigen::VectorXd inverse_mass(columns);
  for (Eigen::Index k = 0; k < columns; ++k) inverse_mass[k] = 1.0 / mass[touched_[k]];
  for (int k = 0; k < 2; ++k) {
    std::vector<Eigen::Triplet<double>> lambda;
    for (index_t r = 0; r < n; ++r)
      if (constraints_[r].direction == k)
        for (index_t e = offset_[r]; e < offset_[r + 1]; ++e) lambda.emplace_back(r, position(column_[e]), value_[e]);
    Eigen::SparseMatrix<double> L(n, columns);
    L.setFromTriplets(lambda.begin(), lambda.end());
    A += Eigen::SparseMatrix<double>(L * inverse_mass.asDiagonal() * L.transpose());  // disjoint patterns
  }
  std::vector<std::pair<index_t, int>> given;
  for (const auto& c : constraints_) given.emplace_back(c.particle, c.direction);
  std::ranges::sort(given);
  if (const auto twice = std::ranges::adjacent_find(given); twice != given.end())
    fail("two velocity constraints prescribe direction {} of particle {}: give each once", twice->second, twice->first);
  auto llt = std::make_shared<Factor>(A);
  if (llt->info() != Eigen::Success) {
    // Rows dependent to round-off: particles packed closer than their supports resolve (a layer
    // squeezed against a tool, re-referenced: docs/method.md section 5.8) see almost the same
    // neighbours with almost the same values. Their conditions are then one condition, met
    // already by the others; the factor of A + eps diag(A) gives the minimum-norm projection
    // onto what the rows can tell apart (51a).
    Eigen::SparseMatrix<double> regularized = A;
    for (index_t r = 0; r < n; ++r) regularized.coeffRef(r, r) *= 1.0 + dependent_rows_tolerance;
    llt = std::make_shared<Factor>(regularized);
    if (llt->info() != Eigen::Success)
      fail("the {} velocity constraints cannot be factored: a row of the shape functions is empty or not finite", n);
  }
  llt_ = std::move(llt);
  rhs_ = Eigen::VectorXd::Zero(n);
  work_ = Eigen::VectorXd::Zero(n);
}

template <class Factor>
void basic_constraint_projector<Factor>::apply(double t, std::vector<vec2>& v) {
  const index_t n = size();
  if (n == 0) return;
  for (index_t r = 0; r < n; ++r) {
    const int k = constraints_[r].direction;
    double lv = 0.0;
    for (index_t e = offset_[r]; e < offset_[r + 1]; ++e) lv += value_[e] * v[column_[e]][k];
    rhs_[r] = lv - (constraints_[r].velocity ? constraints_[r].velocity(t) : 0.0);
  }
  work_ = llt_->solve(rhs_);
  for (index_t r = 0; r < n; ++r) {
    const int k = constraints_[r].direction;
    for (index_t e = offset_[r]; e < offset_[r + 1]; ++e)
      v[column_[e]][k] -= value_over_mass_[e] * work_[r];
  }
}

template <class Factor>
void basic_constraint_projector<Factor>::project_values(std::span<double> x, std::span<const double> target) {
  const index_t n = size();
  if (n == 0) return;
  for (index_t r = 0; r < n; ++r) {
    double lx = 0.0;
    for (index_t e = offset_[r]; e < offset_[r + 1]; ++e) lx += value_[e] * x[column_[e]];
    rhs_[r] = lx - target[r];
  }
  work_ = llt_->solve(rhs_);
  for (index_t r = 0; r < n; ++r)
    for (index_t e = offset_[r]; e < offset_[r + 1]; ++e) x[column_[e]] -= value_over_mass_[e] * work_[r];
}

// Compiled once by the project's programs (cmake/constraints.cpp, target rkpm_instances).
#ifdef RKPM_EXTERN_CONSTRAINTS
extern template class basic_constraint_projector<constraint_factor>;
#endif

}  // namespace rkpm
