#pragma once
// dynamics<Geometry, Material, Contact>: the explicit large-deformation time integrator on
// the RK coefficients (design.md section 4). It reads only the precomputed discrete_model,
// so it does not depend on the kernel, correction or quadrature rule.
//
// One step (velocity form of the central-difference scheme, lumped mass):
//   v(n+1/2) = v(n) + dt/2 a(n);            d(n+1) = d(n) + dt v(n+1/2)      (prediction)
//   contact corrects v(n+1/2), d(n+1) on the predicted configuration (spec/paper.md (P4)-(P7))
//   constraints project v(n+1/2) onto the prescribed physical velocities; d(n+1) follows
//   F_q = I + sum_I d_I (x) grad_X N_I(X_q);  F33 from the geometry;  tau_q from the material
//   f_int,I = sum_q [P_q grad_X N_I(X_q) + e_r P33_q N_I(X_q) / R_q] w_q,  P = tau F^-T
//   a(n+1) = (f_ext - f_int) / m;  v(n+1) = v(n+1/2) + dt/2 a(n+1); constraints again.
// No heap allocation inside step(); loops run over quadrature points and then over particles
// (the scatter gathers from the transposed table), so no atomics are needed and the result
// does not depend on the thread count.

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <rkpm/concepts/contact.hpp>
#include <rkpm/concepts/geometry.hpp>
#include <rkpm/concepts/material.hpp>
#include <rkpm/contact/body_view.hpp>
#include <rkpm/solver/constraints.hpp>
#include <rkpm/solver/discrete_model.hpp>
#include <rkpm/solver/energy.hpp>
#include <rkpm/solver/problem.hpp>
#include <rkpm/solver/stable_time_step.hpp>

namespace rkpm {

template <Geometry G, Material M, Contact Ct>
class dynamics {
 public:
  using geometry_type = G;
  using material_type = M;
  using contact_type = Ct;
  using state_type = typename M::state_type;

  dynamics(discrete_model model, problem<M, Ct> prob, run_options options)
      : model_(std::move(model)),
        material_(std::move(prob.material)),
        contact_(std::move(prob.contact)),
        options_(options) {
    options_.validate();
    material_.constants().validate();
    const index_t n = model_.particle_count(), nq = model_.point_count();
    support_inverse_.setZero();
    for (const vec2& a : model_.particles.support) support_inverse_ += a;
    support_inverse_ = (support_inverse_ / static_cast<double>(n)).cwiseInverse();
    mass_.resize(n);
    for (index_t I = 0; I < n; ++I) mass_[I] = material_.density() * model_.lumped_volume[I];
    d_.assign(n, vec2::Zero());
    v_.assign(n, vec2::Zero());
    a_.assign(n, vec2::Zero());
    d_prev_ = v_before_ = v_half_prev_ = f_int_ = f_int_prev_ = d_;
    f_ext_.resize(n);
    for (index_t I = 0; I < n; ++I) f_ext_[I] = mass_[I] * prob.body_force;
    state_.assign(nq, material_.initial_state());
    tau_.assign(nq, mat3::Zero());
    F_.assign(nq, mat3::Identity());
    mode_.assign(n, vec2::Zero());
    start_.assign(n, vec2::Zero());
    power_iteration_start(start_);
    det_F_.assign(nq, 1.0);
    stress_w_.assign(nq, mat2::Zero());
    hoop_w_.assign(nq, 0.0);

    setup_constraints(std::move(prob.constraints));
    setup_contact(prob.slave_particles);
    if (prob.initial_velocity)
      for (index_t I = 0; I < n; ++I) v_[I] = prob.initial_velocity(model_.particles.position[I]);
    constraints_.apply(0.0, v_);
    std::copy(v_.begin(), v_.end(), v_half_prev_.begin());

    compute_internal_force();
    for (index_t I = 0; I < n; ++I) a_[I] = (f_ext_[I] - f_int_[I]) / mass_[I];

    mode_ = start_;
    reference_dt_ = 2.0 / std::sqrt(largest_frequency_squared<G>(model_, material_.constants(), F_, mass_, mode_,
                                                                 workspace_, 100));
    estimate_dt_ = reference_dt_;
    update_time_step();
    energy_.initial_kinetic = energy_.kinetic = kinetic_energy();
    energy_.record();
  }

  // The contact policy keeps pointers into this object's particle data: no copies or moves.
  dynamics(const dynamics&) = delete;
  dynamics& operator=(const dynamics&) = delete;

  // ---- stepping ----------------------------------------------------------------------
  void step() {
    const double dt = dt_;
    step_dt_ = dt;  // errors raised inside the step name the step being taken
    std::copy(d_.begin(), d_.end(), d_prev_.begin());
    const index_t n = model_.particle_count();
#pragma omp parallel for schedule(static)
    for (index_t I = 0; I < n; ++I) {
      v_[I] += 0.5 * dt * a_[I];
      d_[I] += dt * v_[I];
    }
    if (!contact_.tools().empty()) {
      std::copy(v_.begin(), v_.end(), v_before_.begin());
      last_contact_ = contact_.enforce(time_ + dt, dt, d_, v_);
      energy_.contact += impulse_work();
      max_penetration_ = std::max(max_penetration_, last_contact_.max_penetration);
    }
    if (constraints_.size() > 0) {
      std::copy(v_.begin(), v_.end(), v_before_.begin());
      constraints_.apply(time_ + 0.5 * dt, v_);
      energy_.constraint += impulse_work();
      for (index_t I = 0; I < n; ++I) d_[I] = d_prev_[I] + dt * v_[I];
    }
    std::copy(v_.begin(), v_.end(), v_half_prev_.begin());

    std::swap(f_int_, f_int_prev_);
    compute_internal_force();
    double internal = 0.0, external = 0.0;
    for (index_t I = 0; I < n; ++I) {
      const vec2 dd = d_[I] - d_prev_[I];
      internal += 0.5 * (f_int_prev_[I] + f_int_[I]).dot(dd);
      external += f_ext_[I].dot(dd);
    }
    energy_.internal += internal;
    energy_.external += external;

#pragma omp parallel for schedule(static)
    for (index_t I = 0; I < n; ++I) {
      a_[I] = (f_ext_[I] - f_int_[I]) / mass_[I];
      v_[I] += 0.5 * dt * a_[I];
    }
    if (constraints_.size() > 0) {
      std::copy(v_.begin(), v_.end(), v_before_.begin());
      constraints_.apply(time_ + dt, v_);
      energy_.constraint += impulse_work();
    }
    time_ += dt;
    ++steps_;
    step_dt_ = 0.0;
    dt_min_ = std::min(dt_min_, dt);
    dt_max_ = std::max(dt_max_, dt);
    energy_.kinetic = kinetic_energy();
    energy_.record();
    if (steps_ % options_.time_step_update_interval == 0) update_time_step();
  }

  // Steps to options.end_time, calling observe(*this) at the start, every `every` steps
  // (0: never in between) and at the end.
  template <class Observer>
  void run(Observer&& observe, index_t every = 0) {
    observe(*this);
    const double end = options_.end_time;
    while (time_ < end * (1.0 - 1e-12)) {
      if (time_ + dt_ > end) dt_ = end - time_;  // land on the end time exactly
      step();
      if (every > 0 && steps_ % every == 0 && time_ < end * (1.0 - 1e-12)) observe(*this);
    }
    observe(*this);
  }
  void run() {
    run([](const dynamics&) {});
  }

  // ---- results -----------------------------------------------------------------------
  double time() const { return time_; }
  index_t steps() const { return steps_; }
  double time_step() const { return dt_; }
  double min_time_step() const { return steps_ ? dt_min_ : dt_; }
  double max_time_step() const { return steps_ ? dt_max_ : dt_; }
  double reference_stable_step() const { return reference_dt_; }
  // Smallest support stretch (see support_stretch) over the quadrature points at the last
  // force evaluation; the stable step is reference_stable_step() times this.
  double min_stretch() const { return min_stretch_; }
  const energy_balance& energy() const { return energy_; }
  const run_options& options() const { return options_; }
  const discrete_model& model() const { return model_; }
  const M& material() const { return material_; }
  const Ct& contact() const { return contact_; }
  Ct& contact() { return contact_; }
  const contact::step_result& last_contact() const { return last_contact_; }
  double max_penetration() const { return max_penetration_; }
  const std::vector<double>& mass() const { return mass_; }
  const std::vector<vec2>& coefficients() const { return d_; }
  const std::vector<vec2>& coefficient_velocities() const { return v_; }
  const std::vector<vec2>& internal_force() const { return f_int_; }
  const std::vector<state_type>& point_states() const { return state_; }
  const std::vector<double>& point_det_F() const { return det_F_; }
  const constraint_projector& constraints() const { return constraints_; }
  const std::vector<index_t>& slave_particles() const { return slave_; }

  // Cauchy stress sigma = tau / J at quadrature point q.
  mat3 point_cauchy_stress(index_t q) const { return tau_[q] / det_F_[q]; }

  // Physical displacement u(X_I) = sum_J N_J(X_I) d_J at every particle.
  std::vector<vec2> particle_displacements() const { return physical(d_); }
  std::vector<vec2> particle_velocities() const { return physical(v_); }
  // Current positions x_I = X_I + u(X_I).
  std::vector<vec2> particle_positions() const {
    std::vector<vec2> x = physical(d_);
    for (index_t I = 0; I < model_.particle_count(); ++I) x[I] += model_.particles.position[I];
    return x;
  }
  // A quadrature-point quantity carried to the particles by the lumped L2 projection
  // value_I = sum_q N_I(X_q) w_q value_q / sum_q N_I(X_q) w_q.
  template <class Value, class PointValue>
  std::vector<Value> project_to_particles(PointValue&& at_point) const {
    const auto& tt = model_.particles_of_points;
    std::vector<Value> out(model_.particle_count());
    for (index_t I = 0; I < model_.particle_count(); ++I) {
      Value sum = at_point(index_t{0}) * 0.0;
      for (index_t s = tt.offset[I]; s < tt.offset[I + 1]; ++s)
        sum += model_.at_points.N[tt.entry[s]] * model_.points.weight[tt.point[s]] * at_point(tt.point[s]);
      out[I] = sum / model_.lumped_volume[I];
    }
    return out;
  }

  double kinetic_energy() const {
    double k = 0.0;
    for (index_t I = 0; I < model_.particle_count(); ++I) k += 0.5 * mass_[I] * v_[I].squaredNorm();
    return k;
  }

 private:
  std::vector<vec2> physical(const std::vector<vec2>& c) const {
    std::vector<vec2> out(model_.particle_count());
    for (index_t I = 0; I < model_.particle_count(); ++I) out[I] = model_.at_particles.interpolate(I, c);
    return out;
  }

  // Work of a velocity jump dv = v_ - v_before_ applied to the half-step velocity. The jump is
  // the impulse of a force f = m dv / dt acting at t(n); weighting it with the mean of the
  // half-step velocities around t(n), as the trapezoidal internal work does for f_int, keeps
  // the discrete energy balance exact to O(dt^2).
  double impulse_work() const {
    double w = 0.0;
    for (index_t I = 0; I < model_.particle_count(); ++I)
      w += 0.5 * mass_[I] * (v_[I] - v_before_[I]).dot(v_[I] + v_half_prev_[I]);
    return w;
  }

  void setup_constraints(std::vector<velocity_constraint> constraints) {
    if constexpr (G::is_axisymmetric) {
      double size = 0.0, rmin = std::numeric_limits<double>::infinity();
      for (const vec2& X : model_.particles.position) {
        size = std::max(size, X.cwiseAbs().maxCoeff());
        rmin = std::min(rmin, X[0]);
      }
      const double tol = options_.axis_tolerance * size;
      if (rmin < -tol)
        fail("axisymmetric body has a particle at r = {:.6g} < 0: give the half section r >= 0", rmin);
      for (index_t I = 0; I < model_.particle_count(); ++I)
        if (model_.particles.position[I][0] <= tol) constraints.push_back({I, 0, {}});
    }
    constraints_ = constraint_projector(std::move(constraints), model_.at_particles, mass_);
  }

  void setup_contact(std::vector<index_t> slaves) {
    if (slaves.empty() && !contact_.tools().empty()) {
      const auto& mesh = model_.mesh;
      const bool nodes_are_particles =
          static_cast<index_t>(mesh.node.size()) == model_.particle_count() &&
          std::equal(mesh.node.begin(), mesh.node.end(), model_.particles.position.begin(),
                     [](const vec2& a, const vec2& b) { return (a - b).norm() <= 1e-12 * (1.0 + a.norm()); });
      if (!nodes_are_particles)
        fail("contact needs slave particles: the mesh nodes are not the particles, so give "
             "problem.slave_particles (the boundary particles) explicitly");
      slaves = mesh.boundary_nodes();
    }
    slave_ = slaves;
    contact::body_view view;
    view.reference_position = &model_.particles.position;
    view.mass = &mass_;
    view.slave = std::move(slaves);
    auto& t = view.slave_table;
    t.offset.assign(1, 0);
    for (index_t J : view.slave) {
      if (J < 0 || J >= model_.particle_count()) fail("slave particle {} does not exist", J);
      const auto& src = model_.at_particles;
      for (index_t e = src.offset[J]; e < src.offset[J + 1]; ++e) {
        t.neighbor.push_back(src.neighbor[e]);
        t.N.push_back(src.N[e]);
        t.grad.push_back(src.grad[e]);
      }
      t.offset.push_back(static_cast<index_t>(t.neighbor.size()));
    }
    contact_.setup(view);
  }

  // Internal forces at the current coefficients d_, updating the material states. Records the
  // smallest principal stretch for the next time-step estimate.
  void compute_internal_force() {
    const auto& t = model_.at_points;
    const index_t nq = model_.point_count();
    index_t bad_point = -1;
    double min_stretch = std::numeric_limits<double>::infinity();
    double plastic = 0.0;
    std::string material_error;
#pragma omp parallel for schedule(static) reduction(min : min_stretch) reduction(+ : plastic)
    for (index_t q = 0; q < nq; ++q) {
      mat2 H = mat2::Zero();
      vec2 u = vec2::Zero();
      for (index_t e = t.offset[q]; e < t.offset[q + 1]; ++e) {
        H.noalias() += d_[t.neighbor[e]] * t.grad[e].transpose();
        u += t.N[e] * d_[t.neighbor[e]];
      }
      const vec2& X = model_.points.position[q];
      mat3 F = mat3::Identity();
      F.topLeftCorner<2, 2>() += H;
      F(2, 2) = G::out_of_plane_stretch(u, X);
      const double J = F.determinant();
      det_F_[q] = J;
      F_[q] = F;
      if (!(J > 0.0) || !std::isfinite(J)) {
#pragma omp critical(rkpm_bad_point)
        if (bad_point < 0 || q < bad_point) bad_point = q;
        continue;
      }
      try {
        tau_[q] = material_.kirchhoff_stress(F, state_[q]);
      } catch (const std::exception& ex) {
#pragma omp critical(rkpm_bad_point)
        {
          if (bad_point < 0 || q < bad_point) bad_point = q;
          material_error = ex.what();
        }
        continue;
      }
      plastic += state_[q].plastic_work * model_.points.weight[q];
      const mat2 Fi = F.topLeftCorner<2, 2>().inverse();
      // P = tau F^-T; the in-plane block and the out-of-plane (hoop) component.
      stress_w_[q] = tau_[q].topLeftCorner<2, 2>() * Fi.transpose() * model_.points.weight[q];
      hoop_w_[q] = G::is_axisymmetric ? tau_[q](2, 2) / F(2, 2) * model_.points.weight[q] / X[0] : 0.0;
      min_stretch = std::min({min_stretch, support_stretch(Fi), F(2, 2)});
    }
    if (bad_point >= 0) {
      const vec2& X = model_.points.position[bad_point];
      if (!material_error.empty())
        fail("step {}, t = {:.6g} s: the material update failed at quadrature point {} (X = {:.6g}, {:.6g}): {}",
             steps_ + (step_dt_ > 0.0), time_ + step_dt_, bad_point, X[0], X[1], material_error);
      fail("step {}, t = {:.6g} s: det F = {:.6g} at quadrature point {} (X = {:.6g}, {:.6g}): the body "
           "has inverted or the solution has blown up; reduce the time step fraction, refine the "
           "particles or check the boundary conditions. Output written so far is kept",
           steps_ + (step_dt_ > 0.0), time_ + step_dt_, det_F_[bad_point], bad_point, X[0], X[1]);
    }
    min_stretch_ = min_stretch;
    energy_.plastic = plastic;

    const auto& tt = model_.particles_of_points;
    const index_t n = model_.particle_count();
#pragma omp parallel for schedule(static)
    for (index_t I = 0; I < n; ++I) {
      vec2 f = vec2::Zero();
      for (index_t s = tt.offset[I]; s < tt.offset[I + 1]; ++s) {
        const index_t e = tt.entry[s], q = tt.point[s];
        f.noalias() += stress_w_[q] * t.grad[e];
        if constexpr (G::is_axisymmetric) f[0] += hoop_w_[q] * t.N[e];
      }
      f_int_[I] = f;
    }
  }

  // How much the support has narrowed, as the highest frequency sees it: current gradients
  // are grad_x N = F^-T grad_X N with |grad_X N| ~ 1/a_k per direction, so the largest
  // current gradient scale is the largest singular value of F^-T diag(1/a). Relative to the
  // reference (1/min a_k) this is 1 at F = I and follows the thinnest direction of the
  // deformed support, not merely the smallest stretch (the Taylor bar's supports are 4:1).
  double support_stretch(const mat2& F_inverse) const {
    const mat2 B = F_inverse.transpose() * support_inverse_.asDiagonal();
    const double s = B.squaredNorm(), det = B.determinant();
    const double largest = std::sqrt(0.5 * (s + std::sqrt(std::max(0.0, s * s - 4.0 * det * det))));
    return support_inverse_.maxCoeff() / largest;
  }

  // The stable step follows the current configuration: between power iterations it scales
  // with the narrowing of the supports (support_stretch); when that has drifted by 10%, or
  // every 500 steps, a short power iteration on the current elastic tangent (warm-started,
  // with the fixed start vector mixed back in so that a newly dominant mode is not missed)
  // measures it again. The stretch rule alone is safe but, with the Taylor bar's 4:1
  // supports crushed at the impact face, 3 to 4 times too pessimistic.
  void update_time_step() {
    const double drift = min_stretch_ / estimate_stretch_;
    if (steps_ > 0 && (drift < 0.9 || drift > 1.25 || steps_ - estimate_step_ >= 500)) {
      double norm = 0.0;
      for (const vec2& x : mode_) norm = std::max(norm, x.cwiseAbs().maxCoeff());
      for (std::size_t I = 0; I < mode_.size(); ++I) mode_[I] = mode_[I] / norm + 0.3 * start_[I];
      estimate_dt_ = 2.0 / std::sqrt(largest_frequency_squared<G>(model_, material_.constants(), F_, mass_, mode_,
                                                                  workspace_, 20));
      estimate_stretch_ = min_stretch_;
      estimate_step_ = steps_;
    }
    const double stable = estimate_dt_ * std::min(1.0, min_stretch_ / estimate_stretch_);
    if (options_.fixed_time_step > 0.0) {
      if (options_.fixed_time_step > stable)
        fail("the forced time step {:.4g} s exceeds the stable limit {:.4g} s (t = {:.6g} s, step {}): "
             "use a smaller time step or let rkpm choose it (fixed_time_step = 0)",
             options_.fixed_time_step, stable, time_, steps_);
      dt_ = options_.fixed_time_step;
    } else {
      dt_ = options_.time_step_fraction * stable;
    }
  }

  discrete_model model_;
  M material_;
  Ct contact_;
  run_options options_;
  std::vector<double> mass_;
  std::vector<vec2> d_, v_, a_, d_prev_, v_before_, v_half_prev_, f_int_, f_int_prev_, f_ext_;
  std::vector<state_type> state_;
  std::vector<mat3> tau_, F_;
  std::vector<vec2> mode_, start_;  // power-iteration vector and its fixed start
  stiffness_workspace workspace_{model_};
  double estimate_dt_ = 0.0, estimate_stretch_ = 1.0;
  index_t estimate_step_ = 0;
  std::vector<double> det_F_, hoop_w_;
  std::vector<mat2> stress_w_;
  std::vector<index_t> slave_;
  constraint_projector constraints_;
  energy_balance energy_;
  contact::step_result last_contact_;
  double max_penetration_ = 0.0;
  vec2 support_inverse_ = vec2::Ones();  // 1 / mean support per direction
  double step_dt_ = 0.0;  // the step being taken, 0 between steps
  double time_ = 0.0, dt_ = 0.0, reference_dt_ = 0.0, min_stretch_ = 1.0;
  double dt_min_ = std::numeric_limits<double>::infinity(), dt_max_ = 0.0;
  index_t steps_ = 0;
};

}  // namespace rkpm
