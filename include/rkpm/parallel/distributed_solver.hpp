#pragma once
// distributed_solver<Solver>: one rank's part of an explicit solver (solver/explicit_solver.hpp)
// on P processes, from the whole model and problem that every rank builds alike (docs/method.md
// section 9.8). Set-up, on every rank:
//   1. on the whole model: its bodies, the axis constraints and the contact slaves, as one
//      process finds them;
//   2. the shared region: the constrained and slave particles and their rows' columns, which
//      every rank holds (as ghosts where it does not own them), so that every rank computes the
//      constraints' projection and the contact corrections of the whole model alike, as one
//      process does: the replicated region (shared_region.hpp), surface and axis, a thin band;
//   3. the halo plan (parallel/halo.hpp) with it and the owned particles' rows, the rank's
//      model (local_model) and its process group (mpi_process_group);
//   4. the solver on that model, the problem's constraints and slaves renamed to local ids.
// Then step() and run() are the solver's: owned values are updated on their owner, ghosts
// forwarded, sums taken in one process's order. Every rank's owned values, and every total
// (energies, time, step size), equal one process's bit for bit, on any partition.
// An error on one rank in the set-up or a step is thrown on every rank with one message
// (communicator::agree). The whole model is dropped once the rank's part is built. Built whole
// on every rank, it is the set-up's memory limit (the step's is the part); from a model_layout
// (parallel/rank_setup.hpp) each rank builds its part without a table of the whole, and the
// same part.
// Contact between bodies and tool vertices against the surfaces read the bodies' surfaces: their
// particles and rows join the shared region (from a layout too), every rank corrects them alike.
// All body pairs read the crack faces too: the columns of their rows join it, and the part's
// model carries the faces in local ids (local_model), so every rank computes their contact alike.
// Re-referencing and cracks (docs/method.md sections 5.8 and 5.12) through step(), run() or
// rereference(): every rank re-references (and cuts) a one-process solver of the whole model
// (rereference_through) and builds its part again from it, on a new partition when the load
// has become unbalanced (parallel/distributed_rereference.hpp). When cracks can grow, the run's
// pieces (fragments()) are counted at the set-up and at each rebuild, one process's on every rank.

#include <algorithm>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include <rkpm/concepts/contact.hpp>
#include <rkpm/parallel/communicator.hpp>
#include <rkpm/parallel/halo.hpp>
#include <rkpm/parallel/local_model.hpp>
#include <rkpm/parallel/mpi_process_group.hpp>
#include <rkpm/parallel/partition.hpp>
#include <rkpm/parallel/rank_setup.hpp>
#include <rkpm/parallel/run_fragments.hpp>
#include <rkpm/parallel/shared_region.hpp>
#include <rkpm/solver/body_setup.hpp>
#include <rkpm/solver/discrete_model.hpp>
#include <rkpm/solver/part_cracks.hpp>
#include <rkpm/solver/problem.hpp>

namespace rkpm::parallel {

template <class Solver>
class distributed_solver {
 public:
  using geometry_type = typename Solver::geometry_type;
  using problem_type = problem<typename Solver::material_type, typename Solver::contact_type>;

  // Collective. `partition`: one part per process (partition_particles, or a given one).
  distributed_solver(communicator& comm, discrete_model whole, problem_type prob, run_options options,
                     const particle_partition& partition)
      : partition_(partition), options_(options) {
    keep(prob);
    build(comm, std::move(whole), std::move(prob), true);
    count_fragments(comm);
  }

  // Collective. The set-up in parts (parallel/rank_setup.hpp): from the layout of the whole model,
  // each rank builds its part alone; no rank holds a table of the whole. The layout is dropped
  // once the part is built.
  distributed_solver(communicator& comm, model_layout layout, problem_type prob, run_options options,
                     const particle_partition& partition)
      : partition_(partition), options_(options) {
    keep(prob);
    check(comm, partition, layout.whole.particle_count());
    rank_model r;
    comm.guarded([&] {
      const std::vector<index_t> region = shared_region(layout.whole, prob, options, true);
      r = rank_model_of(layout, partition, comm.rank(), region,
                        [&](const shape_table<2>& rows) { return shared_of(rows, prob); });
    });
    comm.agree();
    group_ = std::make_unique<mpi_process_group>(comm, partition, r.plan, r.point_owner);
    layout = model_layout{};
    group_->forward(r.local.lumped_volume);  // the ghosts' volumes, from their owners
    finish(comm, std::move(r), std::move(prob), options);
    count_fragments(comm);
  }

  Solver& solver() { return *solver_; }
  const Solver& solver() const { return *solver_; }
  // This rank's plan: its owned particles and ghosts by global id (local ids: owned, then ghosts).
  const halo_plan& plan() const { return plan_; }
  mpi_process_group& group() { return *group_; }
  // The particles every rank holds and corrects alike: the constrained and slave particles and
  // their rows' columns.
  index_t shared_count() const { return shared_; }

  // ---- re-referencing (parallel/distributed_rereference.hpp) -------------------------------
  // `make_whole`: the one-process solver of the whole model as set up (make_solver of the same
  // problem and options), built on every rank at each re-reference and at the read of a
  // re-referenced checkpoint; without it both are refused.
  void rereference_through(std::function<Solver()> make_whole) { make_whole_ = std::move(make_whole); }
  bool rereferences_through_whole() const { return static_cast<bool>(make_whole_); }
  // Collective: one step, then the re-reference if it is due (Solver::rereference_pending()).
  void step();
  void step_to_end();
  // Collective: Solver::run's loop through step_to_end(); observe(solver()) as Solver::run calls it.
  template <class Observer>
  void run(Observer&& observe, index_t every = 0) {
    observe(solver());
    while (solver().before_end()) {
      step_to_end();
      if (every > 0 && solver().steps() % every == 0 && solver().before_end()) observe(solver());
    }
    observe(solver());
  }
  // Collective: every rank's part re-referenced as one process re-references the whole model.
  void rereference();
  // Collective: every rank's part built again from `whole`, a one-process solver of the whole
  // model with the same state on every rank (its model, constraints, slaves, masses and state).
  void rebuild_from(const Solver& whole);
  // Collective: a checkpoint (a file or a folder of parts) read into the whole solver on every
  // rank, and the parts built from it: read_checkpoint's path when rereference_through was given,
  // for a re-referenced checkpoint's model.
  void read_whole(const std::filesystem::path& path, std::string_view configuration);
  // How many times the parts were built again (a caller's layouts of the old parts are stale),
  // and how many of those on a new partition (a caller's pieces of the old one are stale).
  index_t rebuilds() const { return rebuilds_; }
  index_t repartitions() const { return repartitions_; }
  // The partition the parts are built on: the set-up's, or the last repartition's.
  const particle_partition& partition() const { return partition_; }
  // The run's pieces (solver().fragments() too), one process's on every rank, when cracks can grow.
  fragment_count fragments() const { return solver_->fragments(); }

 private:
  // The problem as given, without its particles and cells (the model has them): a part built
  // again takes its materials, contact policy and body forces.
  void keep(const problem_type& prob) {
    problem_.emplace(prob);
    problem_->particles = {};
    problem_->mesh = {};
  }

  // The set-up from the whole model; `find_axis`: add the axis constraints (not to a rebuilt
  // model's, which has them).
  void build(communicator& comm, discrete_model whole, problem_type prob, bool find_axis) {
    check(comm, partition_, whole.particle_count());
    rank_model r;
    comm.guarded([&] {
      whole = with_bodies<geometry_type>(std::move(whole));
      shared_region(whole, prob, options_, find_axis);
      r.plan = make_halo_plan(partition_, whole.at_points, comm.rank(), &whole.at_particles,
                              shared_of(whole.at_particles, prob));
      r.shared = shared_;
      r.local = local_model(whole, r.plan);
      if constexpr (BreakingState<typename Solver::state_type>)  // for part_cuts_a_cell (else it asks the whole)
        if (whole.bodies.nodes_are_particles()) r.local.cells_around = cells_around_points(whole.mesh, r.local);
    });
    comm.agree();
    group_ = std::make_unique<mpi_process_group>(comm, partition_, r.plan, whole.at_points);
    whole = discrete_model{};
    finish(comm, std::move(r), std::move(prob), options_);
  }

  // Collective, when cracks can grow: the run's pieces given to the part (explicit_solver::fragments).
  // They change only when the model is rebuilt. A rebuild's whole solver counts them alone, as one
  // process does; at the set-up (from a layout too) the ranks count them (parallel/run_fragments.hpp).
  void count_fragments(communicator& comm, const Solver* whole = nullptr) {
    if (!solver_->cracks_can_grow()) return;
    comm.guarded([&] {
      if (whole) solver_->set_run_fragments(whole->fragments());
    });
    comm.agree();
    if (!whole) solver_->set_run_fragments(part_fragments(comm, solver_->model(), solver_->physical_mass()));
  }

  // Collective: the parts built again from a whole solver that ends the step as one process does
  // (`step_end`: the part's step left a rebuild pending) or re-references it
  // (parallel/distributed_rereference.hpp).
  void rebuild(bool step_end);

  void check(communicator& comm, const particle_partition& partition, index_t particles) const {
    if (partition.parts != comm.size())
      fail("distributed solver: a partition into {} parts on {} processes; partition into as many parts as "
           "processes",
           partition.parts, comm.size());
    if (partition.particles() != particles)
      fail("distributed solver: the partition has {} particles but the model {}; partition this model's particles",
           partition.particles(), particles);
  }

  // On the whole model (or its layout), as one process finds them: the axis constraints, the
  // contact slaves and, when the contact reads them, the bodies' surfaces (surfaces_) and the
  // crack faces (faces_); returns the particles whose rows decide the shared region.
  std::vector<index_t> shared_region(const discrete_model& whole, problem_type& prob, const run_options& options,
                                     bool find_axis) {
    if (find_axis) add_axis_constraints<geometry_type>(whole, options.axis_tolerance, prob.constraints);
    prob.slave_particles = slave_particles(whole, std::move(prob.slave_particles), has_contact(prob.contact));
    surfaces_.clear();
    if (reads_surfaces(prob.contact)) surfaces_ = whole.bodies.surface("contact on several processes");
    faces_ = reads_crack_faces(prob.contact) && !whole.crack_faces.empty() ? &whole.crack_faces : nullptr;
    std::vector<index_t> region = prob.slave_particles;
    for (const velocity_constraint& c : prob.constraints) region.push_back(c.particle);
    for (const boundary_chain& c : surfaces_) region.insert(region.end(), c.node.begin(), c.node.end());
    return region;
  }
  std::vector<stored_index> shared_of(const shape_table<2>& rows, const problem_type& prob) {
    std::vector<stored_index> shared = shared_particles(rows, prob.constraints, prob.slave_particles, surfaces_, faces_);
    shared_ = static_cast<index_t>(shared.size());
    return shared;
  }

  // The solver on the rank's model, the problem's constraints and slaves renamed to local ids.
  void finish(communicator& comm, rank_model r, problem_type prob, const run_options& options) {
    plan_ = std::move(r.plan);
    shared_ = r.shared;
    surfaces_.clear();
    faces_ = nullptr;
    r.local.own.group = group_.get();
    std::vector<stored_index> local_id(plan_.global_particles, -1);
    for (index_t i = 0; i < plan_.local_particles(); ++i) local_id[plan_.global_particle(i)] = static_cast<stored_index>(i);
    for (velocity_constraint& c : prob.constraints) c.particle = local_id[c.particle];
    for (index_t& I : prob.slave_particles) I = local_id[I];
    comm.guarded([&] { solver_.emplace(std::move(r.local), std::move(prob), options); });
    comm.agree();
  }

  halo_plan plan_;
  index_t shared_ = 0;
  std::vector<boundary_chain> surfaces_;  // during the set-up
  const crack_face_rows* faces_ = nullptr;  // during the set-up: the whole model's
  std::unique_ptr<mpi_process_group> group_;  // the solver's model points to it
  std::optional<Solver> solver_;
  particle_partition partition_;
  run_options options_;
  std::optional<problem_type> problem_;
  std::function<Solver()> make_whole_;
  index_t rebuilds_ = 0;
  index_t repartitions_ = 0;
};

}  // namespace rkpm::parallel

// step(), rereference() and rebuild_from().
#include <rkpm/parallel/distributed_rereference.hpp>
