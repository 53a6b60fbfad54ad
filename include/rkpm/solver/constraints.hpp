#pragma once
// Essential conditions on physical values (docs/method.md (50)-(51), section 5.7). RK coefficients are not
// nodal values, so "u_r = 0 on the axis" means sum_J N_J(X_I) d_Jr = 0, not d_Ir = 0. Each
// constraint row r reads  sum_J Lambda_rJ v_Jk = g_r(t)  with Lambda_rJ = N_J(X_I).
// Imposed with Lagrange multipliers in the explicit update, this is the M-orthogonal
// projection
//   v <- v - M^-1 Lambda^T (Lambda M^-1 Lambda^T)^-1 (Lambda v - g),
// whose small dense matrix is constant in the Lagrangian setting and factored once.

#include <Eigen/Cholesky>
#include <algorithm>
#include <functional>
#include <optional>
#include <vector>

#include <rkpm/core/error.hpp>
#include <rkpm/discretization/shape_table.hpp>

namespace rkpm {

// Prescribes the physical velocity component `direction` at particle `particle`;
// an empty `velocity` holds it at rest (and so holds the displacement at its initial value).
struct velocity_constraint {
  index_t particle = 0;
  int direction = 0;
  std::function<double(double)> velocity;
};

class constraint_projector {
 public:
  constraint_projector() = default;

  constraint_projector(std::vector<velocity_constraint> constraints, const shape_table<2>& at_particles,
                       const std::vector<double>& mass)
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
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
    std::vector<double> row(mass.size(), 0.0);
    for (index_t r = 0; r < n; ++r) {
      for (index_t e = offset_[r]; e < offset_[r + 1]; ++e) row[column_[e]] = value_[e] / mass[column_[e]];
      for (index_t s = 0; s < n; ++s) {
        if (constraints_[s].direction != constraints_[r].direction) continue;
        double a = 0.0;
        for (index_t e = offset_[s]; e < offset_[s + 1]; ++e) a += value_[e] * row[column_[e]];
        A(r, s) = a;
      }
      for (index_t e = offset_[r]; e < offset_[r + 1]; ++e) row[column_[e]] = 0.0;
    }
    touched_ = column_;
    std::sort(touched_.begin(), touched_.end());
    touched_.erase(std::unique(touched_.begin(), touched_.end()), touched_.end());
    llt_.emplace(A);
    if (llt_->info() != Eigen::Success)
      fail("the {} velocity constraints are linearly dependent (a particle or direction given twice?)", n);
    work_ = Eigen::VectorXd::Zero(n);
  }

  index_t size() const { return static_cast<index_t>(constraints_.size()); }
  const std::vector<velocity_constraint>& constraints() const { return constraints_; }
  // The particles whose coefficient velocities apply() can change (in increasing order): the
  // columns of the rows; every other velocity it leaves as it is, bit for bit.
  const std::vector<index_t>& touched() const { return touched_; }

  // Projects the coefficient velocities v onto the constraints at time t. No allocation.
  void apply(double t, std::vector<vec2>& v) {
    const index_t n = size();
    if (n == 0) return;
    for (index_t r = 0; r < n; ++r) {
      const int k = constraints_[r].direction;
      double lv = 0.0;
      for (index_t e = offset_[r]; e < offset_[r + 1]; ++e) lv += value_[e] * v[column_[e]][k];
      work_[r] = lv - (constraints_[r].velocity ? constraints_[r].velocity(t) : 0.0);
    }
    llt_->solveInPlace(work_);
    for (index_t r = 0; r < n; ++r) {
      const int k = constraints_[r].direction;
      for (index_t e = offset_[r]; e < offset_[r + 1]; ++e)
        v[column_[e]][k] -= value_over_mass_[e] * work_[r];
    }
  }

 private:
  std::vector<velocity_constraint> constraints_;
  std::vector<index_t> offset_, column_, touched_;
  std::vector<double> value_, value_over_mass_;
  // Engaged only once factored: a default-constructed Eigen::LLT leaves its ComputationInfo
  // uninitialized, so copying or moving an empty projector (as the solver's constructor does)
  // would read it (undefined behaviour, found by the sanitizer build).
  std::optional<Eigen::LLT<Eigen::MatrixXd>> llt_;
  Eigen::VectorXd work_;
};

}  // namespace rkpm
