#pragma once
// explicit_solver's set-up and step (solver/explicit_solver.hpp, docs/method.md section 5):
//   the constructor    masses, body forces, point states and what derive_from_model derives,
//                      then the initial velocities, f_int(0), a(0) and the first stable step;
//   step()             the velocity form of the central difference, (41)-(44), with contact and
//                      constraints on the predicted configuration and the energy ledger (section 7);
//   end_step()         the step's end: cracks cut, the model rebuilt, or the stable step updated;
//   derive_from_model  what the step reads of the model besides the point states (the
//                      constraint rows, the contact slaves, the particle sums): the one path the
//                      constructor, a re-reference and a restart take (solver/rereference_step.hpp);
//   body()             the model as the contact sees it (with the faces of its cracks);
//   fragments()        the pieces: the model's, or on a rank's part the run's.
// Out of the class, so that a program may compile them once (solver/solver_instances.hpp).
// Included at the end of solver/explicit_solver.hpp.

#include <optional>
#include <utility>
#include <vector>

#include <rkpm/solver/explicit_solver.hpp>

namespace rkpm {

// Set-up and step out of the class: a program may compile them once (solver/solver_instances.hpp).
template <Geometry G, Material M, Contact Ct>
contact_body explicit_solver<G, M, Ct>::body() const {
  return {model_.particles.position, mass_, &model_.bodies, &model_.at_particles, model_.deformed_reference,
          &model_.crack_faces, model_.particle_id};
}

template <Geometry G, Material M, Contact Ct>
explicit_solver<G, M, Ct>::explicit_solver(discrete_model model, problem<M, Ct> prob, run_options options,
                                           model_factory factory)
    : model_(model.is_part() ? std::move(model) : with_bodies<G>(std::move(model))),
      factory_(std::move(factory)),
      materials_(model_, std::move(prob.material), std::move(prob.body_materials)),
      contact_{std::move(prob.contact)},
      options_(options) {
  options_.validate();
  model_.own.validate(model_.particle_count(), model_.point_count());
  mass_ = materials_.lumped_masses(model_);
  d_.assign(model_.particle_count(), vec2::Zero());
  v_ = a_ = v_half_prev_ = f_int_ = d_;
  points_ = point_materials<G, M>(model_, materials_);
  if (options_.mass_scaling.enabled()) scale_masses();
  f_ext_ = body_forces(prob.body_force, std::move(prob.body_force_field), model_.particles.position, physical_mass());
  // A rank's part of a model has them already: the whole model's (parallel/distributed_problem.hpp).
  if (!model_.is_part()) add_axis_constraints<G>(model_, options_.axis_tolerance, prob.constraints);
  derive_from_model(std::move(prob.constraints), std::move(prob.slave_particles));
  initial_velocities(model_, prob, v_);
  constraints_.apply(0.0, v_);
  v_half_prev_ = v_;
  compute_internal_force();
  for (index_t I = 0; I < model_.particle_count(); ++I) a_[I] = (f_ext_.at(I, physical_mass()) - f_int_[I]) / mass_[I];
  timeline_.dt = clock_.start(model_, materials_.moduli(), mass_, points_.deformation_gradients(), options_);
  timeline_.check_budget(options_);
  energy_.initial_kinetic = energy_.kinetic = kinetic_energy();
  energy_.record();
}

template <Geometry G, Material M, Contact Ct>
void explicit_solver<G, M, Ct>::step() {
  if (rereference_pending_)
    fail("t = {:.6g} s: a re-reference is due on several processes: step the run with "
         "parallel::distributed_solver::step(), which rebuilds every rank's part",
         timeline_.time);
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
  const std::vector<double>& weighed = physical_mass();
  f_ext_.advance(timeline_.time + dt, initial_positions(), weighed);
  // v(n+1/2) is final: keep it, and book the work of f_int(n) and f_ext over d(n+1) - d(n) =
  // dt v(n+1/2) (the trapezoidal rule's first half; the second follows f_int(n+1)).
  const auto [work_before, external] = sums_([&](index_t I, block_sums<2>::sums& s) {
    v_half_prev_[I] = v_[I];
    const vec2 dd = dt * v_[I];
    s[0] += 0.5 * f_int_[I].dot(dd);
    s[1] += f_ext_.over_step(I, weighed).dot(dd);
  });
  compute_internal_force();
  // The kinetic energy here unless the constraints change v(n+1) afterwards.
  const bool constrained_end = constraints_.size() > 0;
  const auto [work_after, kinetic] = sums_([&](index_t I, block_sums<2>::sums& s) {
    s[0] += 0.5 * f_int_[I].dot(dt * v_[I]);
    a_[I] = (f_ext_.at(I, weighed) - f_int_[I]) / mass_[I];
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
  if (options_.mass_scaling.enabled())
    quasi_static_.observe(options_.mass_scaling, timeline_.time, options_.end_time, energy_.kinetic, energy_.internal);
  end_step();
  for (const auto& c : companions_) c->after_step(*this);
}

// On a rank's part the rebuild is left pending, decided alike on every rank (grow_cracks and
// rereference_due reduce over the ranks); the distributed solver calls a whole solver's end_step()
// in its place (parallel/distributed_rereference.hpp).
template <Geometry G, Material M, Contact Ct>
void explicit_solver<G, M, Ct>::end_step() {
  if (grow_cracks() || rereference_due()) {
    if (model_.is_part()) rereference_pending_ = true;
    else rereference();
  } else if (timeline_.steps % options_.time_step_update_interval == 0)
    timeline_.dt = clock_.update(model_, materials_.moduli(), mass_, points_.deformation_gradients(),
                          points_.min_stretch(), options_, timeline_.time, timeline_.steps);
}

// One process: the model's pieces (crack_fragments). A rank's part cannot see the others' links:
// parallel::distributed_solver counts the run's pieces at each build and gives them to it.
template <Geometry G, Material M, Contact Ct>
fragment_count explicit_solver<G, M, Ct>::fragments() const {
  if (!model_.is_part()) return crack_fragments(model_, physical_mass());
  if (!run_fragments_)
    fail("fragments() of a rank's part: parallel::distributed_solver counts the run's pieces when cracks can grow");
  return *run_fragments_;
}

// Mass scaling (84): every mass times one factor, given or found from the unscaled step (a power
// iteration on the unscaled masses); the physical masses kept for the body forces.
template <Geometry G, Material M, Contact Ct>
void explicit_solver<G, M, Ct>::scale_masses() {
  const mass_scaling_policy& p = options_.mass_scaling;
  double dt0 = 0.0;
  if (p.target_time_step > 0.0) {
    time_step_controller<G> unscaled;
    unscaled.start(model_, materials_.moduli(), mass_, points_.deformation_gradients(), options_);
    dt0 = options_.time_step_fraction * unscaled.reference_stable_step();
  }
  mass_factor_ = p.factor_for(dt0);
  physical_mass_ = mass_;
  for (double& m : mass_) m *= mass_factor_;
}

template <Geometry G, Material M, Contact Ct>
void explicit_solver<G, M, Ct>::carry_masses(std::vector<double> mass, std::vector<double> physical, double factor) {
  if (mass.size() != mass_.size() || !(physical.empty() || physical.size() == mass_.size()))
    fail("carry_masses: {} masses for {} particles", mass.size(), mass_.size());
  mass_ = std::move(mass);
  physical_mass_ = std::move(physical);
  mass_factor_ = factor;
  derive_from_model(constraints_.constraints());
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
