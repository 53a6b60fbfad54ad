#pragma once
// A case run on the processes mpiexec started (rkpm_run under `mpiexec -np P`, or
// `tools/rkpm run CASE --ranks P`; docs/method.md section 9.8). Every rank builds the whole
// problem and model alike, METIS divides the particles, and each rank steps its part
// (parallel::distributed_solver). Rank 0 runs simulate() as one process does, on a whole solver
// that never steps itself. What each observer call gathers:
//   the time and step only (most calls)   nothing: the progress line (pass)
//   a history row, a snapshot             nothing whole: each rank takes the case's extremes
//                                         and exact sums over its part, one MPI_MAX and one
//                                         MPI_SUM bring them to rank 0 (row_reduction.hpp,
//                                         reduce_on_root.hpp; a probe's nearest value too),
//                                         which observes its own part, whose
//                                         time, energies and tool impulses are the run's; each
//                                         rank writes its snapshot piece (snapshot_pieces.hpp;
//                                         whole on rank 0, as below, when cracks can grow)
//   a checkpoint                          nothing: rank 0's observer hands its path and
//                                         description over, and each rank writes its part
//                                         (parallel/checkpoint_parts.hpp), a folder of P files
//   the last call, a figure shape, a      the whole state into the whole solver
//   caller's hook, every row of a case    (parallel::mirror_state), observed as one process
//   without them                          observes its own
// so summary.json, history.csv and the figures are the files one process writes, bit for bit,
// rank 0 adds the snapshots' .pvtu indexes to the .pvd, and a checkpoint in parts continues on
// any number of processes (--restart takes a file or a folder of parts). The other ranks follow
// the same collective calls (follow_run) and write nothing else.
// A re-referenced run re-references through distributed_solver::run: at each re-reference every
// rank builds its part again from a one-process solver of the whole model that it makes and
// re-references (parallel/distributed_rereference.hpp); the mirror's gathers follow (layout()),
// and the snapshot pieces follow a new partition (pieces()); summary.json counts the repartitions.
// Cracks cut cells through the same path; the history's and summary's fragments are the run's
// (distributed_solver::fragments, the parts' fragments()).
// Cost of this form: rank 0 holds the whole model beside its part (every rank, during a re-reference).

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <mpi.h>

#include <rkpm/parallel/checkpoint_parts.hpp>
#include <rkpm/parallel/communicator.hpp>
#include <rkpm/parallel/distributed_checkpoint.hpp>
#include <rkpm/parallel/distributed_solver.hpp>
#include <rkpm/parallel/partition.hpp>
#include <rkpm/parallel/snapshot_pieces.hpp>
#include <rkpm/solver/make_model.hpp>

#include "process_steps.hpp"
#include "reduce_on_root.hpp"
#include "row_reduction.hpp"
#include "run_record.hpp"
#include "simulate.hpp"

namespace rkpm::runner {

template <class Solver>
class rank_steps final : public process_steps<Solver> {
 public:
  using problem_type = problem<typename Solver::material_type, typename Solver::contact_type>;

  // snapshot_format: the snapshots' (alike on every rank: simulate.hpp's snapshot_format);
  // reduction: the case's measures' extremes and sums over a part (row_reduction_of; empty: the
  // rows gather).
  rank_steps(parallel::communicator& comm, std::string configuration, io::vtu_format snapshot_format,
             std::function<row_reduction(const Solver&)> reduction = {})
      : comm_(comm), configuration_(std::move(configuration)), snapshot_format_(snapshot_format),
        reduction_(std::move(reduction)) {}

  // Collective: builds the problem and the whole model on every rank, divides the particles, and
  // returns on rank 0 the whole solver it observes (empty elsewhere).
  std::optional<Solver> build(const std::function<problem_type()>& make_problem, const method_names& method,
                              const run_options& options) {
    using G = typename Solver::geometry_type;
    std::optional<problem_type> prob;
    discrete_model model;
    comm_.guarded([&] {
      prob.emplace(make_problem());
      model = make_model<G>(method, prob->particles, prob->mesh, options.max_moment_condition);
      if (model.particle_count() < comm_.size())
        fail("{} processes for {} particles: give at most one process per particle (--ranks)", comm_.size(),
             model.particle_count());
    });
    comm_.agree();
    std::optional<Solver> whole;
    comm_.guarded([&] {
      if (comm_.rank() != 0) return;
      whole.emplace(model, *prob, options, model_factory_of<G>(method));
    });
    comm_.agree();
    const parallel::particle_partition partition =
        parallel::partition_particles(model.at_points, model.particle_count(), comm_.size());
    const io::vtu_cells cells = io::snapshot_cells(model);
    run_.emplace(comm_, std::move(model), std::move(*prob), options, partition);
    // A re-reference, a crack's cut (and the read of a re-referenced checkpoint) go through the
    // whole model's one-process solver on every rank (parallel/distributed_rereference.hpp), made
    // as rank 0's; the parts' fragments() are then the run's, counted at each rebuild.
    if (options.rereference.enabled() || run_->solver().cracks_can_grow())
      run_->rereference_through([make_problem, method, options] {
        problem_type p = make_problem();
        discrete_model m = make_model<G>(method, p.particles, p.mesh, options.max_moment_condition);
        return Solver(std::move(m), std::move(p), options, model_factory_of<G>(method));
      });
    cells_ = cells;
    pieces_.emplace(comm_, partition, cells);
    return whole;
  }

  int processes() const override { return comm_.size(); }
  // The pieces hold no crack faces or failed points (io/crack_snapshot.hpp): when cracks can
  // grow, rank 0 writes each snapshot whole, from the whole solver, as one process does.
  bool snapshots_in_pieces() const override { return !run_->solver().cracks_can_grow(); }
  index_t repartitions() const override { return run_->repartitions(); }
  bool divided() const override { return true; }

  // A checkpoint file (from any number of processes) or a folder of parts (from any number too).
  void read_checkpoint(const std::filesystem::path& file, Solver* whole) override {
    if (std::filesystem::is_directory(file))
      parallel::read_checkpoint_parts(*run_, file, configuration_);
    else
      parallel::read_checkpoint(*run_, file, configuration_);
    parallel::mirror_state(*run_, layout(), whole, configuration_);
  }

  void abandon(const std::string& message) override {
    comm_.guarded([&] { fail("{}", message); });
    comm_.agree();
  }

  // Each observation: rank 0 says in one byte whether the whole solver is brought up to date, or
  // the row's extremes reduced, and whether a snapshot is due, then the snapshot's index, whose
  // pieces every rank writes.
  void run(Solver* whole, const rank0_observation<Solver>& o) override {
    comm_.agree();  // rank 0's set-up (abandon)
    started_ = true;
    const bool root = comm_.rank() == 0;
    const double end = run_->solver().options().end_time;
    constexpr char observe_whole = 1, snapshot = 2, observe_part = 4;
    const auto reads = [&](double t) -> char {
      const state_needed needs = o.needs(t, end);
      if (needs == state_needed::none) return 0;
      return reduction_ && needs == state_needed::own_part ? observe_part : observe_whole;
    };
    // Through the run (not its part's run()): a re-reference builds every rank's part again.
    run_->run(
        [&](const Solver& part) {
          std::string index = root ? o.snapshot(part.time(), end).string() : std::string();
          char wanted = !root ? 0 : reads(part.time()) | (index.empty() || !snapshots_in_pieces() ? 0 : snapshot);
          MPI_Bcast(&wanted, 1, MPI_CHAR, 0, comm_.get());
          if (wanted & snapshot) {
            comm_.broadcast(index);
            pieces().write(part, index, snapshot_format_);
          }
          if (wanted & observe_part) {
            row_reduction reduced = reduce_on_root(comm_, reduction_(part));
            comm_.guarded([&] {
              if (root) o.observe_part(part, std::move(reduced));
            });
            comm_.agree();
            write_checkpoint_handed_over();
            return;
          }
          if (!(wanted & observe_whole)) {
            if (root) o.pass(part.time(), end, static_cast<long>(part.steps()));
            return;
          }
          parallel::mirror_state(*run_, layout(), whole, configuration_);
          comm_.guarded([&] {
            if (root) o.observe(*whole);
          });
          comm_.agree();
          write_checkpoint_handed_over();
        },
        1);
  }

  bool started() const { return started_; }
  bool between_steps(const Solver&) const override { return parts_between_steps(); }
  void settle(Solver* whole) override {
    if (parts_between_steps()) parallel::mirror_state(*run_, layout(), whole, configuration_);
  }

  bool checkpoint_in_parts(const std::filesystem::path& path, std::string description) override {
    handed_over_.emplace(path.string(), std::move(description));
    return true;
  }
  void write_pending_checkpoint() override {
    if (started_) write_checkpoint_handed_over();
  }

 private:
  bool parts_between_steps() const { return run_->solver().between_steps(); }

  // The mirror's gathers, built again once a re-reference has built the parts again.
  parallel::mpi_checkpoint_layout& layout() {
    if (!layout_ || layout_rebuilds_ != run_->rebuilds()) {
      layout_.emplace(run_->group(), run_->solver().model());
      layout_rebuilds_ = run_->rebuilds();
    }
    return *layout_;
  }

  // The snapshot pieces, made again (collectively) once a re-reference has repartitioned the particles.
  parallel::snapshot_pieces& pieces() {
    if (pieces_repartitions_ != run_->repartitions()) {
      pieces_.reset();
      pieces_.emplace(comm_, run_->partition(), cells_);
      pieces_repartitions_ = run_->repartitions();
    }
    return *pieces_;
  }

  // Collective: rank 0 says whether its observer handed a checkpoint over, and its path and
  // description; every rank writes its part of it.
  void write_checkpoint_handed_over() {
    char due = handed_over_ ? 1 : 0;
    MPI_Bcast(&due, 1, MPI_CHAR, 0, comm_.get());
    if (!due) return;
    auto [path, description] = handed_over_.value_or(std::pair<std::string, std::string>());
    handed_over_.reset();
    comm_.broadcast(path);
    comm_.broadcast(description);
    parallel::write_checkpoint_parts(*run_, path, configuration_, description);
  }

  parallel::communicator& comm_;
  std::string configuration_;
  std::optional<parallel::distributed_solver<Solver>> run_;
  io::vtu_format snapshot_format_;
  std::function<row_reduction(const Solver&)> reduction_;
  std::optional<parallel::mpi_checkpoint_layout> layout_;  // the syncs' gathers (layout())
  index_t layout_rebuilds_ = 0;
  io::vtu_cells cells_;  // the whole model's snapshot cells, for the pieces of a new partition
  std::optional<parallel::snapshot_pieces> pieces_;
  index_t pieces_repartitions_ = 0;
  std::optional<std::pair<std::string, std::string>> handed_over_;  // rank 0: a checkpoint's path, description
  bool started_ = false;
};

// The ranks other than 0: the calls simulate() makes on rank 0, with no whole solver and no files.
template <class Solver>
void follow_run(rank_steps<Solver>& steps, const std::optional<restart_point>& restart) {
  if (restart) steps.read_checkpoint(restart->file, nullptr);
  bool settled = false, written = false;  // as simulate() on rank 0
  try {
    steps.run(nullptr, {});
    settled = true;
    steps.settle(nullptr);
    written = true;
    steps.write_pending_checkpoint();
  } catch (...) {
    if (steps.started() && !settled) steps.settle(nullptr);
    if (!std::exchange(written, true)) {
      try {
        steps.write_pending_checkpoint();
      } catch (const std::exception&) {  // rank 0 says it ("no checkpoint at the failure")
      }
    }
    throw;
  }
}

// run_with's form on several processes (dispatch.hpp): simulate() on rank 0, follow_run elsewhere.
template <class Case, class Solver>
run_outcome run_on_ranks(const run_request& r, const typename Case::parameters& p, const run_policies& policies,
                         const std::function<typename rank_steps<Solver>::problem_type()>& make_problem,
                         const method_names& method, const run_options& options,
                         const std::optional<restart_point>& restart) {
  parallel::communicator world;
  rank_steps<Solver> steps(world, policies.configuration, snapshot_format(r), row_reduction_of<Case, Solver>(p));
  if (world.rank() == 0)
    return simulate<Case, Solver>(
        r, p, policies, [&] { return std::move(*steps.build(make_problem, method, options)); }, restart, &steps);
  steps.build(make_problem, method, options);
  follow_run(steps, restart);
  return {};
}

}  // namespace rkpm::runner
