#pragma once
// A case run on the processes mpiexec started (rkpm_run under `mpiexec -np P`, or
// `tools/rkpm run CASE --ranks P`; docs/method.md section 9.8). Every rank builds the problem
// (the case description is small), then its part, in one of two ways:
//   in parts (part_setup.hpp: a cell rule, rows by reduction, no re-referencing, cracks, mass
//     scaling or caller's hooks; one body or several): the model's layout, coordinate bisection, its own part
//     (parallel/rank_setup.hpp); no rank builds the whole model, rank 0 observes its own part;
//   whole (any other run; summary.json's "whole_model_because" says why): the whole model on
//     every rank, METIS's partition, and on rank 0 a whole solver that never steps itself.
// Each rank steps its part (parallel::distributed_solver). What an observer call gathers:
//   the time and step only (most calls): nothing, the progress line (pass);
//   a history row, a snapshot: nothing whole; the case's extremes and exact sums over each part
//     reduced on rank 0 (row_reduction.hpp, reduce_on_root.hpp), which observes its own part,
//     whose time, energies and tool impulses are the run's; each rank writes its snapshot piece
//     (snapshot_pieces.hpp; whole on rank 0, as below, when cracks can grow);
//   a checkpoint: nothing; rank 0's observer hands its path and description over and each rank
//     writes its part (parallel/checkpoint_parts.hpp), a folder of P files;
//   in parts, a figure shape: the positions (16 B a particle) on rank 0, drawn on its copy of the
//     whole mesh; the end: the points' extremes and failed count reduced, and with figures the
//     positions and projected fields gathered;
//   set up whole, the last call, a figure shape, a caller's hook, every row of a case without row
//     reductions: the whole state mirrored into the whole solver (parallel::mirror_state).
// So summary.json, history.csv and the figures are one process's files, bit for bit; rank 0 adds
// the snapshots' .pvtu indexes to the .pvd; a checkpoint in parts continues on any number of
// processes. summary.json adds the set-up and each rank's owned and ghost particles. The other
// ranks make the same collective calls (follow_run, run_on_ranks.hpp) and write nothing else.
// A re-referenced run re-references through distributed_solver::run, every rank building its part
// again from a one-process solver of the whole model (parallel/distributed_rereference.hpp); the
// mirror's gathers and the snapshot pieces follow (layout(), pieces()). Cracks cut cells through
// the same path; the history's and summary's fragments are the run's (distributed_solver::fragments).
// Replicated in parts: the problem's particles and cells and the snapshot cells on every rank, the
// layout while it sets up, the whole mesh on rank 0.

#include <algorithm>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <mpi.h>

#include <rkpm/parallel/checkpoint_parts.hpp>
#include <rkpm/parallel/communicator.hpp>
#include <rkpm/parallel/coordinate_bisection.hpp>
#include <rkpm/parallel/distributed_checkpoint.hpp>
#include <rkpm/parallel/distributed_solver.hpp>
#include <rkpm/parallel/partition.hpp>
#include <rkpm/parallel/snapshot_pieces.hpp>
#include <rkpm/solver/make_model.hpp>

#include "part_setup.hpp"
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
  using geometry = typename Solver::geometry_type;

  // snapshot_format: the snapshots' (alike on every rank: simulate.hpp's snapshot_format);
  // reduction: the case's measures' extremes and sums over a part (row_reduction_of; empty: the
  // rows gather); request: what the run reads beyond its rows (part_setup.hpp); warn: the memory
  // warning for the problem, set up in parts or not (memory_estimate.hpp).
  rank_steps(parallel::communicator& comm, std::string configuration, io::vtu_format snapshot_format,
             std::function<row_reduction(const Solver&)> reduction, std::function<problem_type()> make_problem,
             method_names method, run_options options, part_setup_request request,
             std::function<void(const problem_type&, bool)> warn = {})
      : comm_(comm), configuration_(std::move(configuration)), snapshot_format_(snapshot_format),
        reduction_(std::move(reduction)), make_problem_(std::move(make_problem)), method_(std::move(method)),
        options_(std::move(options)), request_(request), warn_(std::move(warn)) {
    request_.rows_reduce = static_cast<bool>(reduction_);
  }

  // Collective: every rank builds the problem, then its part: in parts from the model's layout
  // (part_setup.hpp) when the run allows it, else from the whole model, which rank 0 keeps as
  // the whole solver it observes. Returns on rank 0 the solver it observes (its own part, or the
  // whole solver), null elsewhere.
  Solver* set_up() override {
    using G = geometry;
    std::optional<problem_type> prob;
    std::string refusal;
    comm_.guarded([&] {
      prob.emplace(make_problem_());
      if (static_cast<index_t>(prob->particles.size()) < comm_.size())
        fail("{} processes for {} particles: give at most one process per particle (--ranks)", comm_.size(),
             prob->particles.size());
      request_.cracks = opens_cracks(*prob);
      refusal = set_up_in_parts_refusal(method_, prob->mesh, request_);
      if (warn_) warn_(*prob, refusal.empty());
    });
    comm_.agree();
    in_parts_ = refusal.empty();
    whole_model_because_ = refusal;
    std::optional<parallel::particle_partition> partition;
    if (in_parts_) {
      std::optional<parallel::model_layout> layout;
      comm_.guarded([&] {
        layout.emplace(make_layout<G>(method_, std::move(prob->particles), std::move(prob->mesh),
                                      options_.max_moment_condition));
        prob->particles = {};
        prob->mesh = {};
        particles_ = layout->whole.particle_count();
        points_ = layout->whole.point_count();
        cells_ = io::snapshot_cells(layout->whole);
        if (comm_.rank() == 0) mesh_ = layout->whole.mesh;  // the figure shapes' cells
        partition.emplace(parallel::bisect_coordinates(layout->whole.particles.position, comm_.size()));
      });
      comm_.agree();
      run_.emplace(comm_, std::move(*layout), std::move(*prob), options_, *partition);
    } else {
      discrete_model model;
      comm_.guarded([&] { model = make_model<G>(method_, prob->particles, prob->mesh, options_.max_moment_condition); });
      comm_.agree();
      comm_.guarded([&] {
        if (comm_.rank() == 0) whole_.emplace(model, *prob, options_, model_factory_of<G>(method_));
      });
      comm_.agree();
      particles_ = model.particle_count();
      points_ = model.point_count();
      partition.emplace(parallel::partition_particles(model.at_points, model.particle_count(), comm_.size()));
      cells_ = io::snapshot_cells(model);
      run_.emplace(comm_, std::move(model), std::move(*prob), options_, *partition);
    }
    // A re-reference, a crack's cut (and the read of a re-referenced checkpoint) go through the
    // whole model's one-process solver on every rank (parallel/distributed_rereference.hpp), made
    // as rank 0's; the parts' fragments() are then the run's, counted at each rebuild.
    if (options_.rereference.enabled() || run_->solver().cracks_can_grow())
      run_->rereference_through([make_problem = make_problem_, method = method_, options = options_] {
        problem_type p = make_problem();
        discrete_model m = make_model<G>(method, p.particles, p.mesh, options.max_moment_condition);
        return Solver(std::move(m), std::move(p), options, model_factory_of<G>(method));
      });
    local_counts_ = gather_local_counts(comm_, run_->plan());
    pieces_.emplace(comm_, *partition, cells_);
    if (comm_.rank() != 0) return nullptr;
    return in_parts_ ? &run_->solver() : &*whole_;
  }

  // summary.json on several processes: how the run was set up and each rank's particles; set up
  // in parts, the whole model's counts and the points' extremes reduced over the ranks (settle).
  void amend_summary(json& summary) const override {
    summary["set_up"] = in_parts_ ? "in parts" : "whole";
    if (!in_parts_) summary["whole_model_because"] = whole_model_because_;
    json& local = summary["local_particles"];
    local = json::array();
    for (const auto& [owned, ghosts] : local_counts_) local.push_back({{"owned", owned}, {"ghosts", ghosts}});
    if (!in_parts_) return;
    summary["particles"] = particles_;
    summary["quadrature_points"] = points_;
    summary.erase("points");
    if (!state_summary_.empty())
      for (const auto& [k, v] : state_summary_) summary["points"][k] = v;
  }
  bool observes_part() const override { return in_parts_; }
  bool draw_end_state(const std::filesystem::path& dir, const std::string& name) const override {
    if (!end_state_) return false;
    end_state_pngs(dir, name, *end_state_, io::cell_layout::given(cells_));
    return true;
  }
  const background_mesh* whole_mesh() const override { return in_parts_ ? &mesh_ : nullptr; }

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
    if (!in_parts_) parallel::mirror_state(*run_, layout(), whole, configuration_);
  }

  void abandon(const std::string& message) override {
    comm_.guarded([&] { fail("{}", message); });
    comm_.agree();
  }

  // Each observation: rank 0 says in one byte whether the whole solver is brought up to date, or
  // the row's extremes reduced, whether a snapshot is due, and (set up in parts) whether a figure
  // shape is, then the snapshot's index, whose pieces every rank writes.
  void run(Solver* whole, const rank0_observation<Solver>& o) override {
    comm_.agree();  // rank 0's set-up (abandon)
    started_ = true;
    const bool root = comm_.rank() == 0;
    const double end = run_->solver().options().end_time;
    constexpr char observe_whole = 1, snapshot = 2, observe_part = 4, positions = 8;
    const auto reads = [&](double t) -> char {
      const state_needed needs = o.needs(t, end);
      if (needs == state_needed::none) return 0;
      const char shape = in_parts_ && o.shape_due(t, end) ? positions : 0;
      return reduction_ && needs == state_needed::own_part ? observe_part | shape : observe_whole;
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
            std::vector<vec2> x;
            if (wanted & positions) x = gathered_positions(comm_, *run_);
            comm_.guarded([&] {
              if (root) o.observe_part(part, std::move(reduced), wanted & positions ? &x : nullptr);
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
  // Set up in parts: the points' extremes (summary.json's "points") reduced instead.
  void settle(Solver* whole) override {
    if (in_parts_) {
      if (!started_) return;
      state_summary_ = reduced_state_summary(comm_, run_->solver());
      if (request_.plots) end_state_ = gathered_end_state(comm_, *run_);
    } else if (parts_between_steps()) {
      parallel::mirror_state(*run_, layout(), whole, configuration_);
    }
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

  // Whether a material of the problem opens cracks (as opens_cracks of the solver's materials).
  static bool opens_cracks(const problem_type& p) {
    using M = typename Solver::material_type;
    if constexpr (!BreakingState<typename M::state_type>)
      return false;
    else if constexpr (!OpensCracks<M>)
      return true;
    else if (p.body_materials.empty())
      return p.material.opens_cracks();
    else
      return std::ranges::any_of(p.body_materials, [](const M& m) { return m.opens_cracks(); });
  }

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
  std::function<problem_type()> make_problem_;
  method_names method_;
  run_options options_;
  part_setup_request request_;
  std::function<void(const problem_type&, bool)> warn_;
  bool in_parts_ = false;
  std::string whole_model_because_;             // why not in parts (part_setup.hpp)
  std::optional<Solver> whole_;                 // rank 0, set up whole: the solver it observes
  background_mesh mesh_;                        // rank 0, in parts: the whole mesh, for figure shapes
  index_t particles_ = 0, points_ = 0;          // the whole model's counts
  std::vector<std::pair<index_t, index_t>> local_counts_;  // rank 0: each rank's owned particles and ghosts
  std::vector<std::pair<std::string, double>> state_summary_;  // rank 0, in parts: reduced at settle()
  std::optional<end_state_fields> end_state_;  // rank 0, in parts, with figures: gathered at settle()
  std::optional<parallel::mpi_checkpoint_layout> layout_;  // the syncs' gathers (layout())
  index_t layout_rebuilds_ = 0;
  io::vtu_cells cells_;  // the whole model's snapshot cells, for the pieces of a new partition
  std::optional<parallel::snapshot_pieces> pieces_;
  index_t pieces_repartitions_ = 0;
  std::optional<std::pair<std::string, std::string>> handed_over_;  // rank 0: a checkpoint's path, description
  bool started_ = false;
};

}  // namespace rkpm::runner
