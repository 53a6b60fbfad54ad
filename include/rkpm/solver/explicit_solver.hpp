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
// No heap allocation inside step(); the result does not depend on the thread count. The loops
// and sums run through the execution layer (core/execution.hpp), over the particles this
// process owns (discrete_model::own), and the step names the points where an MPI backend
// exchanges ghost values: after the prediction, after contact and constraints, after the scatter.

#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

#include <rkpm/concepts/contact.hpp>
#include <rkpm/concepts/geometry.hpp>
#include <rkpm/concepts/material.hpp>
#include <rkpm/core/execution.hpp>
#include <rkpm/io/checkpoint.hpp>
#include <rkpm/solver/body_forces.hpp>
#include <rkpm/solver/body_materials.hpp>
#include <rkpm/solver/body_setup.hpp>
#include <rkpm/solver/constraints.hpp>
#include <rkpm/solver/contact_stage.hpp>
#include <rkpm/solver/discrete_model.hpp>
#include <rkpm/solver/energy.hpp>
#include <rkpm/solver/fields.hpp>
#include <rkpm/solver/point_materials.hpp>
#include <rkpm/solver/problem.hpp>
#include <rkpm/solver/step_timeline.hpp>
#include <rkpm/solver/time_step_controller.hpp>

namespace rkpm {

template <Geometry G, Material M, Contact Ct>
class explicit_solver {
 public:
  using geometry_type = G;
  using material_type = M;
  using contact_type = Ct;
  using state_type = typename M::state_type;

  // `factory`: the builder `model` came from (make_solver passes it), kept for model_builder().
  explicit_solver(discrete_model model, problem<M, Ct> prob, run_options options, model_factory factory = {});
  // ---- stepping ----------------------------------------------------------------------
  void step();

  // Steps to options.end_time, calling observe(*this) at the start, every `every` steps
  // (0: never in between) and at the end. Stops with an error past options.max_steps.
  template <class Observer>
  void run(Observer&& observe, index_t every = 0) {
    observe(*this);
    while (timeline_.before(options_.end_time)) {
      timeline_.approach_end(options_);
      step();
      if (every > 0 && timeline_.steps % every == 0 && timeline_.before(options_.end_time)) observe(*this);
    }
    observe(*this);
  }
  void run() { run([](const explicit_solver&) {}); }
  // Checkpoint sections (io/checkpoint.hpp; solver/checkpoint.hpp writes and reads the files),
  // whole only between steps: between_steps() is false after an error thrown inside step().
  void save(io::checkpoint_writer& w) const { sections(w, *this); }
  void load(io::checkpoint_reader& r) {
    sections(r, *this);
    f_ext_.restore(timeline_.time, initial_positions(), mass_);
  }
  bool between_steps() const { return timeline_.between_steps(); }

  // ---- the model's lifecycle (docs/method.md section 5.8) ------------------------------
  // Rebuilds the model in the current configuration through model_builder() and carries the
  // state over (solver/rereference_step.hpp): step() calls it when options().rereference says so;
  // a caller may call it between steps. Refused on several processes and without a builder.
  void rereference();
  // The re-references so far and when they happened (s).
  index_t rereferences() const { return static_cast<index_t>(rereference_times_.size()); }
  const std::vector<double>& rereference_times() const { return rereference_times_; }
  // The particles' initial reference positions X_I (the model's until the first re-reference).
  const std::vector<vec2>& initial_positions() const {
    return initial_position_.empty() ? model_.particles.position : initial_position_;
  }

  // ---- results -----------------------------------------------------------------------
  double time() const { return timeline_.time; }
  index_t steps() const { return timeline_.steps; }
  double time_step() const { return timeline_.dt; }
  double min_time_step() const { return timeline_.min_step(); }
  double max_time_step() const { return timeline_.max_step(); }
  double reference_stable_step() const { return clock_.reference_stable_step(); }
  // Steps to the end time at the current step size (the progress line's estimate).
  double estimated_steps_left() const { return std::max(0.0, options_.end_time - timeline_.time) / timeline_.dt; }
  // Smallest support stretch over the quadrature points at the last force evaluation.
  double min_stretch() const { return points_.min_stretch(); }
  const energy_balance& energy() const { return energy_; }
  const run_options& options() const { return options_; }
  const discrete_model& model() const { return model_; }
  // The builder of model() with its method (empty if none was given): the tables on new particles.
  const model_factory& model_builder() const { return factory_; }
  // Body b's material (problem::body_materials[b], or problem::material), the bodies, I's body.
  const M& material(index_t b = 0) const { return materials_.of_body(b); }
  index_t bodies() const { return model_.bodies.count(); }
  index_t body_of_particle(index_t I) const { return model_.bodies.of_particle(I); }
  const Ct& contact() const { return contact_.policy; }
  Ct& contact() { return contact_.policy; }
  const contact_result& last_contact() const { return contact_.last; }
  // Each tool's impulse since t = 0 (N s): the mean force over [t1, t2] is (I(t2) - I(t1)) / (t2 - t1).
  const std::vector<vec2>& tool_impulses() const { return contact_.impulse; }
  double max_penetration() const { return contact_.max_penetration; }
  const std::vector<double>& mass() const { return mass_; }
  const std::vector<vec2>& coefficients() const { return d_; }
  const std::vector<vec2>& coefficient_velocities() const { return v_; }
  const std::vector<vec2>& internal_force() const { return f_int_; }
  const std::vector<state_type>& point_states() const { return points_.states(); }
  // det F at quadrature point q at the last force evaluation.
  double point_det_F(index_t q) const { return points_.det_F(q); }
  // F relative to the current reference at point q (F itself until a re-reference): how far the
  // kernels have been distorted since they were built.
  mat3 point_relative_deformation_gradient(index_t q) const { return points_.relative_deformation_gradient(q); }
  const constraint_projector& constraints() const { return constraints_; }
  const std::vector<index_t>& slave_particles() const { return contact_.slaves; }
  // The body as the contact policy sees it (for calling it directly, as the benchmarks do).
  contact_body body() const { return {model_.particles.position, mass_, &model_.bodies, &model_.at_particles}; }
  // Cauchy stress sigma = tau / J at quadrature point q.
  mat3 point_cauchy_stress(index_t q) const { return points_.kirchhoff_stress(materials_, q) / points_.det_F(q); }
  // Physical displacements, velocities and current positions x_I = X_I + u(X_I).
  // The displacements since the start (across re-references: x_I - X_I^0).
  std::vector<vec2> particle_displacements() const {
    std::vector<vec2> u = values_at_particles(model_, d_);
    if (!initial_position_.empty())
      for (index_t I = 0; I < model_.particle_count(); ++I) u[I] += model_.particles.position[I] - initial_position_[I];
    return u;
  }
  std::vector<vec2> particle_velocities() const { return values_at_particles(model_, v_); }
  std::vector<vec2> particle_positions() const { return positions_at_particles(model_, d_); }
  template <class Value, class PointValue>
  std::vector<Value> project_to_particles(PointValue&& at_point) const {
    return rkpm::project_to_particles<Value>(model_, at_point);
  }
  double kinetic_energy() const {
    return sums_([&](index_t I, block_sums<2>::sums& s) { s[0] += 0.5 * mass_[I] * v_[I].squaredNorm(); })[0];
  }

 private:
  // Not saved: scratch of step() (d_start_, timeline_.taking) and the set-up.
  template <class Archive, class Self>
  static void sections(Archive& a, Self& s) {
    reference_sections(a, s);  // first: a re-referenced model is rebuilt before the rest is read
    for (auto [name, field] : {std::pair{"solver.d", &s.d_}, {"solver.v", &s.v_}, {"solver.a", &s.a_},
                               {"solver.f_int", &s.f_int_}, {"solver.v_half_prev", &s.v_half_prev_}})
      a.array(name, *field);
    a.value("solver.energy", s.energy_);
    a.part(s.timeline_);  // solver.time, dt, dt_min, dt_max, steps
    a.part(s.points_);    // material states
    a.part(s.clock_);
    a.part(s.contact_);   // what the run reports of contact, then the policy's state
  }

  template <class Archive, class Self>
  static void reference_sections(Archive& a, Self& s);
  // What the step derives from the model besides the point states: the constraint rows, the
  // contact slaves' rows and surfaces and the particle sums. `slaves`: the problem's, on the first
  // model; none on a rebuilt one, whose contact keeps its slaves and state (contact_stage::rebind).
  void derive_from_model(std::vector<velocity_constraint> constraints,
                         std::optional<std::vector<index_t>> slaves = std::nullopt);
  bool rereference_due() const;

  // f_int at d; inside a step, at the step's end (the context names it in errors).
  // On several processes an error of the force loop on one rank (an inverted point) is thrown on
  // every rank, with the same message, by the collective calls that follow it.
  void compute_internal_force() {
    const auto loop = [&] {
      points_.internal_force(model_, materials_, d_, f_int_, {timeline_.current_step(), timeline_.current_time(), timeline_.taking});
    };
    if (model_.own.group) model_.own.group->guarded(loop);
    else loop();
    exec::exchange(exchange_point::after_scatter, model_.own, f_int_);
    points_.combine(model_);
    energy_.plastic = points_.plastic_work();
  }

  discrete_model model_;
  model_factory factory_;
  materials_by_body<M> materials_;
  contact_stage<Ct> contact_;
  run_options options_;
  std::vector<double> mass_;
  body_forces f_ext_;
  std::vector<vec2> d_, v_, a_, v_half_prev_, f_int_;
  std::vector<vec2> d_start_;  // d(n) at the particles the constraints touch (constraints_.touched())
  block_sums<2> sums_;
  point_materials<G, M> points_;
  time_step_controller<G> clock_;
  constraint_projector constraints_;
  energy_balance energy_;
  step_timeline timeline_;
  std::vector<double> rereference_times_;
  index_t last_rereference_step_ = 0;
  std::vector<vec2> initial_position_;  // empty until the first re-reference
};

// Set-up and step out of the class: a program may compile them once (solver/solver_instances.hpp).
template <Geometry G, Material M, Contact Ct>
explicit_solver<G, M, Ct>::explicit_solver(discrete_model model, problem<M, Ct> prob, run_options options,
                                           model_factory factory)
    : model_(model.is_part() ? std::move(model) : with_bodies<G>(std::move(model))),
      factory_(std::move(factory)),
      materials_(model_, std::move(prob.material), std::move(prob.body_materials)),
      contact_{std::move(prob.contact)},
      options_(options) {
  options_.validate();
  if (options_.rereference.enabled() && model_.is_part())
    fail("re-referencing on several processes is not available yet: run on one process, or without "
         "\"rereference\"");
  model_.own.validate(model_.particle_count(), model_.point_count());
  mass_ = materials_.lumped_masses(model_);
  d_.assign(model_.particle_count(), vec2::Zero());
  v_ = a_ = v_half_prev_ = f_int_ = d_;
  f_ext_ = body_forces(prob.body_force, std::move(prob.body_force_field), model_.particles.position, mass_);
  points_ = point_materials<G, M>(model_, materials_);
  // A rank's part of a model has them already: the whole model's (parallel/distributed_problem.hpp).
  if (!model_.is_part()) add_axis_constraints<G>(model_, options_.axis_tolerance, prob.constraints);
  derive_from_model(std::move(prob.constraints), std::move(prob.slave_particles));
  initial_velocities(model_, prob, v_);
  constraints_.apply(0.0, v_);
  v_half_prev_ = v_;
  compute_internal_force();
  for (index_t I = 0; I < model_.particle_count(); ++I) a_[I] = (f_ext_.at(I, mass_) - f_int_[I]) / mass_[I];
  timeline_.dt = clock_.start(model_, materials_.moduli(), mass_, points_.deformation_gradients(), options_);
  timeline_.check_budget(options_);
  energy_.initial_kinetic = energy_.kinetic = kinetic_energy();
  energy_.record();
}

template <Geometry G, Material M, Contact Ct>
void explicit_solver<G, M, Ct>::step() {
  const double dt = timeline_.begin_step();
  const index_range owned = model_.own.particles;
  const std::vector<index_t>& constrained = constraints_.touched();
  for (std::size_t k = 0; k < constrained.size(); ++k) d_start_[k] = d_[constrained[k]];
  // a(n) is spent once v(n+1/2) is predicted, until a(n+1) below: with contact it holds the
  // velocities before the contact corrections, for their work.
  std::vector<vec2>& v_before = a_;
  const bool tools = contact_.active();
  exec::parallel_for(owned, [&](index_t I) {
    v_[I] += 0.5 * dt * a_[I];
    d_[I] += dt * v_[I];
    if (tools) v_before[I] = v_[I];
  });
  exec::exchange(exchange_point::after_predictor, model_.own, d_, v_);
  if (tools) energy_.contact += contact_.enforce(body(), timeline_.time + dt, dt, d_, v_, v_before, v_half_prev_, sums_);
  if (constraints_.size() > 0) {
    energy_.constraint += constraints_.apply_with_work(timeline_.time + 0.5 * dt, v_, mass_, v_half_prev_);
    for (std::size_t k = 0; k < constrained.size(); ++k) d_[constrained[k]] = d_start_[k] + dt * v_[constrained[k]];
  }
  exec::exchange(exchange_point::after_contact, model_.own, d_, v_);
  // The ghosts' v(n+1/2) as well, for the constraints' work at the step's end.
  exec::parallel_for(model_.own.ghost_particles, [&](index_t I) { v_half_prev_[I] = v_[I]; });
  f_ext_.advance(timeline_.time + dt, initial_positions(), mass_);
  // v(n+1/2) is final: keep it, and book the work of f_int(n) and f_ext over d(n+1) - d(n) =
  // dt v(n+1/2) (the trapezoidal rule's first half; the second follows f_int(n+1)).
  const auto [work_before, external] = sums_([&](index_t I, block_sums<2>::sums& s) {
    v_half_prev_[I] = v_[I];
    const vec2 dd = dt * v_[I];
    s[0] += 0.5 * f_int_[I].dot(dd);
    s[1] += f_ext_.over_step(I, mass_).dot(dd);
  });
  compute_internal_force();
  // The kinetic energy here unless the constraints change v(n+1) afterwards.
  const bool constrained_end = constraints_.size() > 0;
  const auto [work_after, kinetic] = sums_([&](index_t I, block_sums<2>::sums& s) {
    s[0] += 0.5 * f_int_[I].dot(dt * v_[I]);
    a_[I] = (f_ext_.at(I, mass_) - f_int_[I]) / mass_[I];
    v_[I] += 0.5 * dt * a_[I];
    if (!constrained_end) s[1] += 0.5 * mass_[I] * v_[I].squaredNorm();
  });
  energy_.internal += work_before + work_after;
  energy_.external += external;
  energy_.kinetic = kinetic;
  if (constrained_end) {
    exec::exchange(exchange_point::before_constraints, model_.own, v_);
    energy_.constraint += constraints_.apply_with_work(timeline_.time + dt, v_, mass_, v_half_prev_);
    energy_.kinetic = kinetic_energy();
  }
  timeline_.finish_step();
  energy_.record();
  if (rereference_due()) rereference();
  else if (timeline_.steps % options_.time_step_update_interval == 0)
    timeline_.dt = clock_.update(model_, materials_.moduli(), mass_, points_.deformation_gradients(),
                          points_.min_stretch(), options_, timeline_.time, timeline_.steps);
}

template <Geometry G, Material M, Contact Ct>
void explicit_solver<G, M, Ct>::derive_from_model(std::vector<velocity_constraint> constraints,
                                                  std::optional<std::vector<index_t>> slaves) {
  sums_ = block_sums<2>(model_.own.particles.size(), model_.own.group);  // owned particles come first
  constraints_ = constraint_projector(std::move(constraints), model_.at_particles, mass_, model_.particle_id);
  d_start_.resize(constraints_.touched().size());
  if (slaves) contact_.setup(model_, body(), std::move(*slaves));
  else contact_.rebind(model_, body());
}

}  // namespace rkpm

#include <rkpm/solver/rereference_step.hpp>
