#pragma once
// explicit_solver<Geometry, Material, Contact>: the explicit large-deformation time integrator
// on the RK coefficients (docs/method.md section 5). It reads only the precomputed
// discrete_model, so it does not depend on the kernel, correction or quadrature rule: build
// one with make_solver<Config> (solver/make_solver.hpp).
//
// One step (velocity form of the central-difference scheme, lumped mass, docs/method.md (41)-(44)):
//   v(n+1/2) = v(n) + dt/2 a(n);            d(n+1) = d(n) + dt v(n+1/2)      (prediction)
//   contact corrects v(n+1/2), d(n+1) on the predicted configuration (section 6)
//   constraints project v(n+1/2) onto the prescribed physical velocities; d(n+1) follows
//   f_int(n+1) from the material at every quadrature point (solver/point_materials.hpp)
//   a(n+1) = (f_ext - f_int) / m;  v(n+1) = v(n+1/2) + dt/2 a(n+1); constraints again.
// No heap allocation inside step(); the result does not depend on the thread count.

#include <algorithm>
#include <cmath>
#include <limits>
#include <ranges>
#include <utility>
#include <vector>

#include <rkpm/concepts/contact.hpp>
#include <rkpm/concepts/geometry.hpp>
#include <rkpm/concepts/material.hpp>
#include <rkpm/core/block_sums.hpp>
#include <rkpm/io/checkpoint.hpp>
#include <rkpm/solver/body_materials.hpp>
#include <rkpm/solver/body_setup.hpp>
#include <rkpm/solver/constraints.hpp>
#include <rkpm/solver/discrete_model.hpp>
#include <rkpm/solver/energy.hpp>
#include <rkpm/solver/fields.hpp>
#include <rkpm/solver/point_materials.hpp>
#include <rkpm/solver/problem.hpp>
#include <rkpm/solver/time_step_controller.hpp>

namespace rkpm {

template <Geometry G, Material M, Contact Ct>
class explicit_solver {
 public:
  using geometry_type = G;
  using material_type = M;
  using contact_type = Ct;
  using state_type = typename M::state_type;

  explicit_solver(discrete_model model, problem<M, Ct> prob, run_options options)
      : model_(std::move(model)),
        materials_(model_, std::move(prob.material), std::move(prob.body_materials)),
        contact_(std::move(prob.contact)),
        options_(options) {
    options_.validate();
    const index_t n = model_.particle_count();
    mass_ = materials_.lumped_masses(model_);
    d_.assign(n, vec2::Zero());
    v_ = a_ = v_half_prev_ = f_int_ = d_;
    body_force_ = prob.body_force;
    sums_ = block_sums<2>(n);
    points_ = point_materials<G, M>(model_, materials_);

    add_axis_constraints<G>(model_, options_.axis_tolerance, prob.constraints);
    constraints_ = constraint_projector(std::move(prob.constraints), model_.at_particles, mass_);
    d_start_.resize(constraints_.touched().size());
    const contact_slaves slaves = select_slaves(model_, std::move(prob.slave_particles), has_contact(contact_));
    slave_ = slaves.particle;
    contact_.setup(body(), slaves);
    if (prob.initial_particle_velocity)
      for (index_t I = 0; I < n; ++I) v_[I] = prob.initial_particle_velocity(I, model_.particles.position[I]);
    else if (prob.initial_velocity)
      for (index_t I = 0; I < n; ++I) v_[I] = prob.initial_velocity(model_.particles.position[I]);
    constraints_.apply(0.0, v_);
    v_half_prev_ = v_;

    compute_internal_force();
    for (index_t I = 0; I < n; ++I) a_[I] = (external_force(I) - f_int_[I]) / mass_[I];
    dt_ = clock_.start(model_, materials_.moduli(), mass_, points_.deformation_gradients(), options_);
    check_step_budget();
    energy_.initial_kinetic = energy_.kinetic = kinetic_energy();
    energy_.record();
  }

  // ---- stepping ----------------------------------------------------------------------
  void step() {
    const double dt = dt_;
    step_dt_ = dt;  // errors raised inside the step name the step being taken
    const index_t n = model_.particle_count();
    const std::vector<index_t>& constrained = constraints_.touched();
    for (std::size_t k = 0; k < constrained.size(); ++k) d_start_[k] = d_[constrained[k]];
    // a(n) is spent once v(n+1/2) is predicted, until a(n+1) below: with contact it holds the
    // velocities before the contact corrections, for their work.
    std::vector<vec2>& v_before = a_;
    const bool with_contact = has_contact(contact_);
#pragma omp parallel for schedule(static)
    for (index_t I = 0; I < n; ++I) {
      v_[I] += 0.5 * dt * a_[I];
      d_[I] += dt * v_[I];
      if (with_contact) v_before[I] = v_[I];
    }
    if (with_contact) {
      last_contact_ = contact_.enforce(body(), time_ + dt, dt, d_, v_);
      energy_.contact += sums_([&](index_t I, block_sums<2>::sums& s) {
        s[0] += impulse_work_at(mass_[I], v_[I], v_before[I], v_half_prev_[I]);
      })[0];
      max_penetration_ = std::max(max_penetration_, last_contact_.max_penetration);
    }
    if (constraints_.size() > 0) {
      energy_.constraint += constraints_.apply_with_work(time_ + 0.5 * dt, v_, mass_, v_half_prev_);
      for (std::size_t k = 0; k < constrained.size(); ++k) d_[constrained[k]] = d_start_[k] + dt * v_[constrained[k]];
    }
    // v(n+1/2) is final: keep it, and book the work of f_int(n) and f_ext over d(n+1) - d(n) =
    // dt v(n+1/2) (the trapezoidal rule's first half; the second follows f_int(n+1)).
    const auto [work_before, external] = sums_([&](index_t I, block_sums<2>::sums& s) {
      v_half_prev_[I] = v_[I];
      const vec2 dd = dt * v_[I];
      s[0] += 0.5 * f_int_[I].dot(dd);
      s[1] += external_force(I).dot(dd);
    });

    compute_internal_force();

    // The kinetic energy here unless the constraints change v(n+1) afterwards.
    const bool constrained_end = constraints_.size() > 0;
    const auto [work_after, kinetic] = sums_([&](index_t I, block_sums<2>::sums& s) {
      s[0] += 0.5 * f_int_[I].dot(dt * v_[I]);
      a_[I] = (external_force(I) - f_int_[I]) / mass_[I];
      v_[I] += 0.5 * dt * a_[I];
      if (!constrained_end) s[1] += 0.5 * mass_[I] * v_[I].squaredNorm();
    });
    energy_.internal += work_before + work_after;
    energy_.external += external;
    energy_.kinetic = kinetic;
    if (constrained_end) {
      energy_.constraint += constraints_.apply_with_work(time_ + dt, v_, mass_, v_half_prev_);
      energy_.kinetic = kinetic_energy();
    }
    time_ += dt;
    ++steps_;
    step_dt_ = 0.0;
    dt_min_ = std::min(dt_min_, dt);
    dt_max_ = std::max(dt_max_, dt);
    energy_.record();
    if (steps_ % options_.time_step_update_interval == 0)
      dt_ = clock_.update(model_, materials_.moduli(), mass_, points_.deformation_gradients(),
                          points_.min_stretch(), options_, time_, steps_);
  }

  // Steps to options.end_time, calling observe(*this) at the start, every `every` steps
  // (0: never in between) and at the end. Stops with an error past options.max_steps.
  template <class Observer>
  void run(Observer&& observe, index_t every = 0) {
    observe(*this);
    const double end = options_.end_time;
    while (time_ < end * (1.0 - 1e-12)) {
      // Land on the end time exactly, in two equal steps rather than a full one and a sliver
      // (a sliver's contact impulse over a tiny step would read as a force spike).
      if (time_ + dt_ >= end) dt_ = end - time_;
      else if (time_ + 2.0 * dt_ > end) dt_ = 0.5 * (end - time_);
      if (steps_ >= options_.max_steps)
        fail("t = {:.6g} s of {:.6g} s after {} steps, the limit max_steps: the stable step has shrunk to "
             "{:.3g} s (a body crushed or inverting?); raise max_steps if the run is meant to be this long",
             time_, end, steps_, dt_);
      step();
      if (every > 0 && steps_ % every == 0 && time_ < end * (1.0 - 1e-12)) observe(*this);
    }
    observe(*this);
  }
  void run() { run([](const explicit_solver&) {}); }
  // Checkpoint sections (io/checkpoint.hpp; solver/checkpoint.hpp writes and reads the files),
  // whole only between steps: between_steps() is false after an error thrown inside step().
  void save(io::checkpoint_writer& w) const { sections(w, *this); }
  void load(io::checkpoint_reader& r) { sections(r, *this); }
  bool between_steps() const { return step_dt_ == 0.0; }

  // ---- results -----------------------------------------------------------------------
  double time() const { return time_; }
  index_t steps() const { return steps_; }
  double time_step() const { return dt_; }
  double min_time_step() const { return steps_ ? dt_min_ : dt_; }
  double max_time_step() const { return steps_ ? dt_max_ : dt_; }
  double reference_stable_step() const { return clock_.reference_stable_step(); }
  // Steps to the end time at the current step size (the progress line's estimate).
  double estimated_steps_left() const { return std::max(0.0, options_.end_time - time_) / dt_; }
  // Smallest support stretch over the quadrature points at the last force evaluation.
  double min_stretch() const { return points_.min_stretch(); }
  const energy_balance& energy() const { return energy_; }
  const run_options& options() const { return options_; }
  const discrete_model& model() const { return model_; }
  // The material of body b (problem::body_materials[b]; body 0: problem::material when the
  // problem gave no body_materials), the bodies and the body of particle I.
  const M& material(index_t b = 0) const { return materials_.of_body(b); }
  index_t bodies() const { return materials_.bodies(); }
  index_t body_of_particle(index_t I) const { return materials_.body_of_particle(I); }
  const Ct& contact() const { return contact_; }
  Ct& contact() { return contact_; }
  const contact_result& last_contact() const { return last_contact_; }
  double max_penetration() const { return max_penetration_; }
  const std::vector<double>& mass() const { return mass_; }
  const std::vector<vec2>& coefficients() const { return d_; }
  const std::vector<vec2>& coefficient_velocities() const { return v_; }
  const std::vector<vec2>& internal_force() const { return f_int_; }
  const std::vector<state_type>& point_states() const { return points_.states(); }
  // det F at quadrature point q at the last force evaluation.
  double point_det_F(index_t q) const { return points_.det_F(q); }
  const constraint_projector& constraints() const { return constraints_; }
  const std::vector<index_t>& slave_particles() const { return slave_; }
  // The body as the contact policy sees it (for calling it directly, as the benchmarks do).
  contact_body body() const {
    return {model_.particles.position, mass_, &model_.mesh, &model_.at_particles, G::is_axisymmetric};
  }

  // Cauchy stress sigma = tau / J at quadrature point q.
  mat3 point_cauchy_stress(index_t q) const { return points_.kirchhoff_stress(materials_, q) / points_.det_F(q); }
  // Physical displacements, velocities and current positions x_I = X_I + u(X_I).
  std::vector<vec2> particle_displacements() const { return values_at_particles(model_, d_); }
  std::vector<vec2> particle_velocities() const { return values_at_particles(model_, v_); }
  std::vector<vec2> particle_positions() const {
    std::vector<vec2> x = values_at_particles(model_, d_);
    for (index_t I = 0; I < model_.particle_count(); ++I) x[I] += model_.particles.position[I];
    return x;
  }
  template <class Value, class PointValue>
  std::vector<Value> project_to_particles(PointValue&& at_point) const {
    return rkpm::project_to_particles<Value>(model_, at_point);
  }
  double kinetic_energy() const {
    return sums_([&](index_t I, block_sums<2>::sums& s) { s[0] += 0.5 * mass_[I] * v_[I].squaredNorm(); })[0];
  }

 private:
  // Not saved: scratch of step() (d_start_, step_dt_) and the set-up.
  template <class Archive, class Self>
  static void sections(Archive& a, Self& s) {
    for (auto [name, field] : {std::pair{"solver.d", &s.d_}, {"solver.v", &s.v_}, {"solver.a", &s.a_},
                               {"solver.f_int", &s.f_int_}, {"solver.v_half_prev", &s.v_half_prev_}})
      a.array(name, *field);
    a.value("solver.energy", s.energy_);
    a.value("solver.last_contact", s.last_contact_);
    for (auto [name, field] : {std::pair{"solver.max_penetration", &s.max_penetration_}, {"solver.time", &s.time_},
                               {"solver.dt", &s.dt_}, {"solver.dt_min", &s.dt_min_}, {"solver.dt_max", &s.dt_max_}})
      a.value(name, *field);
    a.value("solver.steps", s.steps_);
    a.part(s.points_);  // material states, then the time-step controller and the contact
    a.part(s.clock_);
    a.part(s.contact_);
  }

  vec2 external_force(index_t I) const { return mass_[I] * body_force_; }

  void compute_internal_force() {
    points_.internal_force(model_, materials_, d_, f_int_, {steps_ + (step_dt_ > 0.0), time_ + step_dt_, step_dt_});
    energy_.plastic = points_.plastic_work();
  }

  // A run that would need more steps than options.max_steps is refused before it starts.
  void check_step_budget() const {
    const double steps = options_.end_time / dt_;
    if (steps > static_cast<double>(options_.max_steps))
      fail("the run would take about {:.3g} steps (end time {:.6g} s / stable step {:.3g} s), more than "
           "max_steps = {}: check the material constants and units (a modulus too large, a density too "
           "small?) or the particle spacing, or raise max_steps",
           steps, options_.end_time, dt_, options_.max_steps);
  }

  discrete_model model_;
  materials_by_body<M> materials_;
  Ct contact_;
  run_options options_;
  std::vector<double> mass_;
  vec2 body_force_ = vec2::Zero();
  std::vector<vec2> d_, v_, a_, v_half_prev_, f_int_;
  std::vector<vec2> d_start_;  // d(n) at the particles the constraints touch (constraints_.touched())
  block_sums<2> sums_;
  point_materials<G, M> points_;
  time_step_controller<G> clock_;
  constraint_projector constraints_;
  std::vector<index_t> slave_;
  energy_balance energy_;
  contact_result last_contact_;
  double max_penetration_ = 0.0;
  double step_dt_ = 0.0;  // the step being taken, 0 between steps
  double time_ = 0.0, dt_ = 0.0;
  double dt_min_ = std::numeric_limits<double>::infinity(), dt_max_ = 0.0;
  index_t steps_ = 0;
};

}  // namespace rkpm
