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
// No heap allocation inside step(); the result does not depend on the thread count. The loops and
// sums run through the execution layer (core/execution.hpp), over the particles this process owns
// (discrete_model::own); the step names where an MPI backend exchanges ghost values.

#include <algorithm>
#include <memory>
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
#include <rkpm/solver/crack_growth.hpp>
#include <rkpm/solver/discrete_model.hpp>
#include <rkpm/solver/energy.hpp>
#include <rkpm/solver/fields.hpp>
#include <rkpm/solver/mass_scaling.hpp>
#include <rkpm/solver/point_materials.hpp>
#include <rkpm/solver/problem.hpp>
#include <rkpm/solver/step_companion.hpp>
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
    while (before_end()) {
      step_to_end();
      if (every > 0 && timeline_.steps % every == 0 && before_end()) observe(*this);
    }
    observe(*this);
  }
  void run() { run([](const explicit_solver&) {}); }
  // Whether the run has yet to reach options().end_time; one step toward it as run() takes them.
  bool before_end() const { return timeline_.before(options_.end_time); }
  void step_to_end() { timeline_.approach_end(options_); step(); }
  // A component stepped with the solver (solver/step_companion.hpp): after every step and every
  // rebuild of the model, in the checkpoints (attach it before reading one), in the runner's
  // history and summary.
  void attach(std::shared_ptr<step_companion<explicit_solver>> c) { companions_.push_back(std::move(c)); }
  const std::vector<std::shared_ptr<step_companion<explicit_solver>>>& companions() const { return companions_; }
  // Sets every point's temperature, T(q) in K, between steps (coupled heat conduction,
  // thermal/heat_coupling.hpp): the material's set_temperature keeps what the state derives from it.
  template <class PointTemperature>
  void set_point_temperatures(PointTemperature&& T) {
    if (!between_steps()) fail("set_point_temperatures() between steps only");
    points_.update_states([&](index_t q, state_type& s) { materials_.at_point(q).set_temperature(s, T(q)); });
  }
  // Checkpoint sections (solver/checkpoint.hpp), whole only between steps (not after an error in step()).
  void save(io::checkpoint_writer& w) const { sections(w, *this); }
  void load(io::checkpoint_reader& r) {
    sections(r, *this);
    f_ext_.restore(timeline_.time, initial_positions(), physical_mass());
  }
  bool between_steps() const { return timeline_.between_steps(); }

  // ---- the model's lifecycle (docs/method.md section 5.8) ------------------------------
  // Rebuilds the model in the current configuration through model_builder(), carrying the state
  // (solver/rereference_step.hpp): step() calls it when options().rereference says so or a crack grows;
  // a caller may, between steps. A rank's part marks it pending (parallel::distributed_solver does it).
  void rereference();
  // What step() ends with: new cracks cut and the model rebuilt if due, else the stable step updated.
  void end_step();
  bool rereference_pending() const { return rereference_pending_; }
  // A rank's part built on a re-referenced model takes the run's masses (`physical`: empty without mass scaling).
  void carry_masses(std::vector<double> mass, std::vector<double> physical, double factor);
  index_t rereferences() const { return static_cast<index_t>(rereference_times_.size()); }
  const std::vector<double>& rereference_times() const { return rereference_times_; }  // s
  // Cuts cells (a notch) as a crack cuts them (113), each normal to its n, and rebuilds the model.
  void cut_cells(const std::vector<std::pair<index_t, vec2>>& cells_and_normals);
  // The cells cut by cracks (solver/crack_growth.hpp), and the pieces (a body each until it breaks):
  // on a rank's part the run's, which parallel::distributed_solver counts (set_run_fragments).
  const std::vector<cell_crack>& cracks() const { return cracks_; }
  bool cracks_can_grow() const { return opens_cracks(materials_); }  // whether failed points cut cells
  fragment_count fragments() const;
  void set_run_fragments(fragment_count pieces) { run_fragments_ = pieces; }
  // The particles' initial reference positions X_I (the model's until the first re-reference).
  const std::vector<vec2>& initial_positions() const {
    return initial_position_.empty() ? model_.particles.position : initial_position_;
  }

  double time() const { return timeline_.time; }
  index_t steps() const { return timeline_.steps; }
  double time_step() const { return timeline_.dt; }
  double min_time_step() const { return timeline_.min_step(); }
  double max_time_step() const { return timeline_.max_step(); }
  double reference_stable_step() const { return clock_.reference_stable_step(); }
  double estimated_steps_left() const { return std::max(0.0, options_.end_time - timeline_.time) / timeline_.dt; }
  double min_stretch() const { return points_.min_stretch(); }  // the narrowest support stretch
  const energy_balance& energy() const { return energy_; }
  const run_options& options() const { return options_; }
  const discrete_model& model() const { return model_; }
  const model_factory& model_builder() const { return factory_; }  // model()'s builder (or empty)
  // Body b's material (problem::body_materials[b], or problem::material), the bodies, I's body.
  const M& material(index_t b = 0) const { return materials_.of_body(b); }
  index_t bodies() const { return model_.bodies.count(); }
  index_t body_of_particle(index_t I) const { return model_.bodies.of_particle(I); }
  const Ct& contact() const { return contact_.policy; }
  Ct& contact() { return contact_.policy; }
  const contact_result& last_contact() const { return contact_.last; }
  // Each tool's impulse since t = 0 (N s): the mean force over [t1, t2] is the impulse's change / (t2 - t1).
  const std::vector<vec2>& tool_impulses() const { return contact_.impulse; }
  double max_penetration() const { return contact_.max_penetration; }
  // The lumped masses the step moves (scaled: options().mass_scaling), and the physical ones (the same without).
  const std::vector<double>& mass() const { return mass_; }
  const std::vector<double>& physical_mass() const { return physical_mass_.empty() ? mass_ : physical_mass_; }
  // The mass scaling factor (84) (1 without), and the kinetic to internal energy ratio (85) so far.
  double mass_scaling_factor() const { return mass_factor_; }
  const quasi_static_check& quasi_static() const { return quasi_static_; }
  const std::vector<vec2>& coefficients() const { return d_; }
  const std::vector<vec2>& coefficient_velocities() const { return v_; }
  const std::vector<vec2>& internal_force() const { return f_int_; }
  const std::vector<state_type>& point_states() const { return points_.states(); }
  double point_det_F(index_t q) const { return points_.det_F(q); }  // at the last force evaluation
  // V_0 / w_q, point q's initial volume per unit of its weight (1 until a re-reference).
  double point_initial_volume_per_weight(index_t q) const { return points_.initial_volume_per_weight(q); }
  // F relative to the current reference at point q (F itself until a re-reference): how far the
  // kernels have been distorted since they were built.
  mat3 point_relative_deformation_gradient(index_t q) const { return points_.relative_deformation_gradient(q); }
  const constraint_projector& constraints() const { return constraints_; }
  const std::vector<index_t>& slave_particles() const { return contact_.slaves; }
  // The body as the contact policy sees it (for calling it directly, as the benchmarks do).
  contact_body body() const;
  // Cauchy stress sigma = tau / J at quadrature point q.
  mat3 point_cauchy_stress(index_t q) const { return points_.kirchhoff_stress(materials_, q) / points_.det_F(q); }
  // Physical displacements since the start (across re-references: x_I - X_I^0), velocities and
  // current positions x_I = X_I + u(X_I).
  std::vector<vec2> particle_displacements() const;
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
    if (s.options_.mass_scaling.enabled()) a.value("solver.quasi_static", s.quasi_static_);
    for (const auto& c : s.companions_) a.part(*c);
  }

  template <class Archive, class Self>
  static void reference_sections(Archive& a, Self& s);
  // What the step derives from the model besides the point states: the constraint rows, the
  // contact slaves' rows and surfaces and the particle sums. `slaves`: the problem's, on the first
  // model; none on a rebuilt one, whose contact keeps its slaves and state (contact_stage::rebind).
  void derive_from_model(std::vector<velocity_constraint> constraints,
                         std::optional<std::vector<index_t>> slaves = std::nullopt);
  bool rereference_due() const;
  bool grow_cracks();  // cuts the cells of newly failed points; whether it cut any
  bool insert_cuts(const std::vector<std::pair<index_t, vec2>>& cells_and_normals, bool not_beside_cuts);
  void scale_masses();

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
  std::vector<double> physical_mass_;  // empty without mass scaling
  double mass_factor_ = 1.0;
  quasi_static_check quasi_static_;
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
  bool rereference_pending_ = false;  // on a rank's part: due, for the distributed solver
  std::vector<vec2> initial_position_;  // empty until the first re-reference
  std::vector<cell_crack> cracks_;
  std::optional<fragment_count> run_fragments_;  // on a rank's part: the whole run's pieces
  std::vector<std::shared_ptr<step_companion<explicit_solver>>> companions_;
};

}  // namespace rkpm

// The set-up and the step (out of the class, so that a program may compile them once:
// solver/solver_instances.hpp), and the re-reference.
#include <rkpm/solver/explicit_step.hpp>
#include <rkpm/solver/rereference_step.hpp>
