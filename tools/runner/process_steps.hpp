#pragma once
// process_steps<Solver>: how simulate() steps the solver it observes. On one process
// (one_process_steps, below) the solver steps itself and the observer sees every step. Divided
// over several processes (rkpm_run under mpiexec; ranks.hpp implements it with MPI), a run set
// up in parts (part_setup.hpp) has rank 0 observe its own part at every call (observes_part):
// rows by reduction, figure shapes from gathered positions, no whole solver. Otherwise rank 0
// observes a one-process solver of the whole model, `whole`, which never steps itself: the
// ranks step their parts, and the object puts their state into `whole`
// (parallel::mirror_state) at the calls where the observer reads the model's particles or points
// beyond a history row's extremes (the last call, figure shapes, checkpoints, a caller's hook, a
// case whose measures are not extremes). `whole` is then the solver one process would have, bit
// for bit, so the observer writes the one-process files unchanged. A call that adds a history
// row (or a snapshot's index) alone observes rank 0's part instead, with the case's extremes
// reduced over the ranks (row_reduction.hpp): no gather, the same row. Every call is collective: the other ranks make the same calls
// with no `whole` (follow_run in ranks.hpp), so an error on any rank is thrown on every rank
// alike.

#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <rkpm/solver/checkpoint.hpp>

#include "json.hpp"
#include "row_reduction.hpp"

namespace rkpm::runner {

// What an observation reads of the solver beyond its time and step.
enum class state_needed {
  none,         // nothing: pass(time, end time, steps) alone
  own_part,     // a history row's reductions (or a snapshot's index) alone: observe_part(rank
                // 0's part, the case's maxima and sums reduced over the ranks: row_reduction.hpp)
  whole_model,  // `whole` is brought up to date and observe(whole) called
};

// What rank 0's observer (run_observer.hpp) tells the divided run at each observation, at (time,
// end time): what the call reads (needs); the .pvtu index of the snapshot that call writes,
// if any (empty if none), whose pieces every rank writes before it; whether it records a figure
// shape (shape_due: the positions are then gathered for observe_part).
template <class Solver>
struct rank0_observation {
  std::function<state_needed(double, double)> needs;
  std::function<std::filesystem::path(double, double)> snapshot;
  std::function<void(double, double, long)> pass;
  std::function<bool(double, double)> shape_due;
  std::function<void(const Solver&)> observe;
  // rank 0's part, the reduced measures, and every particle's position when a shape is due (else null)
  std::function<void(const Solver&, row_reduction, const std::vector<vec2>*)> observe_part;
};

template <class Solver>
class process_steps {
 public:
  virtual ~process_steps() = default;
  virtual int processes() const = 0;
  // How many times a re-reference partitioned the particles again (parallel/distributed_rereference.hpp).
  virtual index_t repartitions() const { return 0; }
  // Whether the run is divided over processes (mpiexec, even with one): snapshots in pieces,
  // unless the pieces cannot hold them (then rank 0 writes them whole from `whole`).
  virtual bool divided() const = 0;
  virtual bool snapshots_in_pieces() const { return divided(); }
  // Collective: sets the run up; returns the solver rank 0 observes when the object builds it
  // (null: simulate() builds it with its make()).
  virtual Solver* set_up() { return nullptr; }
  // Whether rank 0 observes its part (set up in parts) instead of a whole solver, and then the
  // whole mesh (rank 0's copy, for figure shapes).
  virtual bool observes_part() const { return false; }
  virtual const background_mesh* whole_mesh() const { return nullptr; }
  // Rank 0 observing its part: draws the end-state figures (final_figures.hpp) from the fields
  // gathered after the run; false if it has none.
  virtual bool draw_end_state(const std::filesystem::path& /*dir*/, const std::string& /*name*/) const {
    return false;
  }
  // summary.json's entries of the division (the whole model's counts when rank 0 observes a part).
  virtual void amend_summary(json& /*summary*/) const {}

  // Every rank reads the checkpoint, then `whole` takes the state.
  virtual void read_checkpoint(const std::filesystem::path& file, Solver* whole) = 0;
  // Rank 0's set-up before the run failed with `message`: every rank throws it.
  virtual void abandon(const std::string& message) = 0;
  // Steps to the end, observed as `observation` says (given on rank 0 only).
  virtual void run(Solver* whole, const rank0_observation<Solver>& observation) = 0;
  // After the run, ended or failed: whether the parts stopped between steps (their state whole),
  // and, when they did, `whole` brought up to date.
  virtual bool between_steps(const Solver& whole) const = 0;
  virtual void settle(Solver* whole) = 0;

  // Divided: rank 0's observer hands the checkpoint due (its path and description) here instead
  // of writing the whole solver's file, and returns true; every rank then writes its part
  // (parallel/checkpoint_parts.hpp) at the observation's end, or at write_pending_checkpoint. One
  // process: false, the observer writes the file.
  virtual bool checkpoint_in_parts(const std::filesystem::path& /*path*/, std::string /*description*/) {
    return false;
  }
  // Collective, after settle(): writes the checkpoint handed over since the run ended, if any.
  virtual void write_pending_checkpoint() {}
};

// One process: the solver steps itself under the observer; a checkpoint is read into it.
template <class Solver>
class one_process_steps final : public process_steps<Solver> {
 public:
  explicit one_process_steps(std::string configuration) : configuration_(std::move(configuration)) {}
  int processes() const override { return 1; }
  bool divided() const override { return false; }
  void read_checkpoint(const std::filesystem::path& file, Solver* whole) override {
    rkpm::read_checkpoint(*whole, file, configuration_);
  }
  void abandon(const std::string&) override {}
  void run(Solver* whole, const rank0_observation<Solver>& observation) override {
    whole->run([&](const Solver& at) { observation.observe(at); }, 1);
  }
  bool between_steps(const Solver& whole) const override { return whole.between_steps(); }
  void settle(Solver*) override {}

 private:
  std::string configuration_;
};

}  // namespace rkpm::runner
