#pragma once
// run_observer<Case, Solver>: what rkpm_run does after every step (simulate.hpp calls it through
// explicit_solver::run): the progress line, a history.csv row at every history interval (the
// case's measures, the tool forces averaged over the interval, the energies), a VTK snapshot at
// every snapshot interval (the background cells on the particles, with the tools' vertices), the
// figure shapes, and a checkpoint after the first step that reaches each multiple of the
// checkpoint interval. Its whole state is a run_record, which the checkpoints carry, so a
// restarted run continues the same outputs (run_record.hpp).

#include <chrono>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include <rkpm/io/checkpoint.hpp>
#include <rkpm/io/csv.hpp>
#include <rkpm/io/progress.hpp>
#include <rkpm/io/crack_snapshot.hpp>
#include <rkpm/io/solver_output.hpp>
#include <rkpm/io/pvd_series.hpp>
#include <rkpm/io/vtk.hpp>
#include <rkpm/solver/checkpoint.hpp>
#include <rkpm/solver/mass_scaling.hpp>

#include "case_traits.hpp"
#include "figures.hpp"
#include "interrupt.hpp"
#include "json.hpp"
#include "process_steps.hpp"
#include "quasi_static_warning.hpp"
#include "run_hooks.hpp"
#include "row_reduction.hpp"
#include "run_record.hpp"

namespace rkpm::runner {

// Whether a run rebuilds its model (re-referencing, or cracks that grow, docs/method.md sections
// 5.8 and 5.12): its energy then shows the remap term.
template <class Solver>
bool rebuilds_model(const Solver& s) {
  return s.options().rereference.enabled() || s.cracks_can_grow();
}

template <class Case, class Solver>
class run_observer {
 public:
  using measures = std::vector<std::pair<std::string, double>>;

  // Writes into `dir`: history.csv (the record's rows so far, then one per interval), CASE.pvd
  // (the record's snapshots, then new ones) and the figure shapes. `identity` is the runner's
  // description of the run (case, policies, parameters), kept in every checkpoint with the
  // record; `configuration` is the solver's configuration name (Config::name()); `hooks` what an
  // embedding caller asked for (run_hooks.hpp).
  run_observer(const std::filesystem::path& dir, const typename Case::parameters& params, const Solver& s,
               run_record record, json identity, std::string configuration, bool quiet,
               io::vtu_format snapshot_format = {}, run_hooks hooks = {})
      : dir_(dir), params_(params), record_(std::move(record)), identity_(std::move(identity)),
        configuration_(std::move(configuration)), quiet_(quiet), snapshot_format_(snapshot_format),
        hooks_(std::move(hooks)),
        tools_(static_cast<index_t>(s.contact().tools().size())),
        mean_force_(tools_, vec2::Zero()),
        measures_(Case::measure(s, params, mean_force_)),
        history_(dir / "history.csv", column_names(s)),
        vtk_(dir / (case_name<Case>(params) + ".pvd"), record_.snapshots),
        figures_(dir, params),
        segment_start_(std::chrono::steady_clock::now()) {
    record_.start_impulse.resize(tools_, vec2::Zero());
    record_.previous_start_impulse.resize(tools_, vec2::Zero());
    for (const auto& row : record_.history_rows) history_.row(row);
    rows_by_reduction_ = MeasuredByReduction<Case, Solver> && s.companions().empty();
  }

  // Called at the start, after every step and at the end of the run; its time is output_s().
  void operator()(const Solver& s) {
    if (std::exchange(skip_next_, false)) return;
    // Added to output_s_ however the call ends (a write that fails, an interrupt, a stop).
    const struct timed {
      std::chrono::steady_clock::time_point from;
      double& total;
      ~timed() { total += std::chrono::duration<double>(std::chrono::steady_clock::now() - from).count(); }
    } timer{std::chrono::steady_clock::now(), output_s_};
    const double t = s.time(), end_time = s.options().end_time;
    const bool last = is_last(t, end_time);
    if (!quiet_) progress_.update(t, end_time, static_cast<long>(s.steps()));
    if (t >= record_.next_history || last) {
      add_history_row(s, t, last);
      record_.next_history += record_.history_interval;
    }
    if (snapshot_at(t, last)) {
      if (in_pieces()) {  // written by the ranks before this call (ranks.hpp)
        const std::string index = vtk_.next_file(".pvtu");
        vtk_.add(t, index);
        record_.snapshots.emplace_back(t, index);
      } else {
        write_snapshot(s, t);
      }
      record_.next_snapshot += record_.snapshot_interval;
    }
    figures_.observe(s, positions_, whole_mesh_);
    record_.shapes = figures_.recorded();
    if (record_.checkpoint_interval > 0.0 && t >= record_.next_checkpoint && !last) {
      while (record_.next_checkpoint <= t) record_.next_checkpoint += record_.checkpoint_interval;
      write_checkpoint_now(s);
    }
    if (const int signal_number = pending_interrupt().load(); signal_number != 0 && !last)
      fail("interrupted by signal {} at t = {:.6g} s, step {}", signal_number, t, s.steps());
    if (hooks_.observe && (last || s.steps() % std::max(hooks_.every, 1L) == 0) &&
        !hooks_.observe(particle_state_of(s)) && !last)
      throw stop_requested{t, static_cast<long>(s.steps())};
  }

  // What the call at time t reads of the solver beyond its time and step: none (a run on several
  // processes then makes it through pass()); for a history row or a snapshot alone, rank 0's own
  // part (observe_part) when the rows' measures are reduced over the ranks and the
  // snapshots are written in pieces; else (and for anything reads_model lists) the whole model.
  // Set up in parts (process_steps::observes_part), every call that reads anything observes rank
  // 0's part: a figure shape then from the gathered positions.
  state_needed needs(double t, double end_time) const {
    if (skip_next_) return state_needed::none;
    const bool last = is_last(t, end_time);
    if (part_only_ && (last || figures_.due(t, last) || pending_interrupt().load() != 0))
      return state_needed::own_part;
    if (!part_only_ && reads_model(t, last)) return state_needed::whole_model;
    if (t < record_.next_history && !snapshot_at(t, last) && !checkpoint_due(t)) return state_needed::none;
    return divided_ && rows_by_reduction_ ? state_needed::own_part : state_needed::whole_model;
  }
  // A call that needs own_part: rank 0's part observed as the whole (its time, step, energies and
  // tool impulses are the run's), with `reduced`, the case's over the whole model (row_reduction.hpp).
  // `positions`: every particle's, in the whole model's order, when the call records a figure shape.
  void observe_part(const Solver& part, row_reduction reduced, const std::vector<vec2>* positions = nullptr) {
    row_reduced_ = std::move(reduced);
    positions_ = positions;
    const struct forget {
      row_reduction& r;
      const std::vector<vec2>*& x;
      ~forget() { r = {}, x = nullptr; }
    } after{row_reduced_, positions_};
    (*this)(part);
  }
  // The snapshot the call at time t writes, if any (empty if none): next to the .pvd, a .vtu, or
  // the .pvtu index of a snapshot the ranks write in pieces (divide).
  std::filesystem::path snapshot_due(double t, double end_time) const {
    if (skip_next_ || !snapshot_at(t, is_last(t, end_time))) return {};
    return dir_ / vtk_.next_file(in_pieces() ? ".pvtu" : ".vtu");
  }
  // Whether the call at time t records a figure shape.
  bool shape_due(double t, double end_time) const { return !skip_next_ && figures_.due(t, is_last(t, end_time)); }
  // A run on several processes, stepped by `steps` (ranks.hpp): each rank writes its piece of
  // every snapshot before the call that is due to write it (parallel/snapshot_pieces.hpp), which
  // then adds the index to the .pvd, and its part of every checkpoint, which this observer hands
  // over (process_steps::checkpoint_in_parts) instead of reading the whole model for it.
  // Set up in parts, rank 0 observes its part (process_steps::observes_part): its rows must reduce.
  void divide(process_steps<Solver>& steps) {
    divided_ = &steps;
    part_only_ = steps.observes_part();
    whole_mesh_ = steps.whole_mesh();
    if (part_only_ && !rows_by_reduction_)
      fail("a run set up in parts needs history rows by reduction (the case's measures, no companions)");
  }

  // The call when needs(t, end_time) is none: the progress line only.
  void pass(double t, double end_time, long steps) {
    if (std::exchange(skip_next_, false)) return;
    if (!quiet_) progress_.update(t, end_time, steps);
  }

  // Writes checkpoint_<step>.rkpmcp for the solver's current state (once per step); returns its path.
  std::filesystem::path write_checkpoint_now(const Solver& s) {
    if (!last_checkpoint_.empty() && last_checkpoint_.filename() == io::checkpoint_file_name(s.steps()))
      return last_checkpoint_;
    record_.wall_s = wall_s();
    json description = identity_;
    description["record"] = to_json(record_);
    const auto path = dir_ / io::checkpoint_file_name(s.steps());
    if (!divided_ || !divided_->checkpoint_in_parts(path, description.dump()))
      rkpm::write_checkpoint(s, path, configuration_, description.dump());
    last_checkpoint_ = path;
    return path;
  }

  // Continues a checkpoint's run: its figure shapes come from the folder they were written to,
  // and the first call (at the checkpoint's time, already observed before it was written) is
  // skipped.
  void resume(const std::filesystem::path& from) {
    figures_.restore(from, record_.shapes);
    skip_next_ = true;
  }

  void finish() { progress_.finish(); }
  double wall_s() const {
    return record_.wall_s + std::chrono::duration<double>(std::chrono::steady_clock::now() - segment_start_).count();
  }
  // Seconds spent in the calls of this process since it started or resumed the run: history
  // rows, snapshots, figure shapes and checkpoints, the part of wall_s that is not the steps.
  double output_s() const { return output_s_; }
  const measures& last_measures() const { return measures_; }
  const run_record& record() const { return record_; }
  const std::filesystem::path& last_checkpoint() const { return last_checkpoint_; }
  history_table table() const { return {history_.columns(), record_.history_rows}; }
  const figure_recorder<Case>& figures() const { return figures_; }

 private:
  // The call at the end time (within rounding), and whether a call at t writes a snapshot.
  static bool is_last(double t, double end_time) { return t >= end_time * (1.0 - 1e-12); }
  bool snapshot_at(double t, bool last) const { return last || t >= record_.next_snapshot; }
  bool checkpoint_due(double t) const { return record_.checkpoint_interval > 0.0 && t >= record_.next_checkpoint; }
  // Whether the call reads more than a row's measures and a snapshot's index: the last call, a
  // figure shape, a checkpoint (unless written in parts), an interrupt, a caller's hook, a
  // snapshot that several processes cannot write in pieces.
  bool reads_model(double t, bool last) const {
    return last || figures_.due(t, last) || (!divided_ && checkpoint_due(t)) || pending_interrupt().load() != 0 ||
           static_cast<bool>(hooks_.observe) || (divided_ && !in_pieces() && snapshot_at(t, last));
  }
  bool in_pieces() const { return divided_ && divided_->snapshots_in_pieces(); }  // the snapshots

  // The points, the cells, the vectors and the stress made piecewise as they are written, the
  // other arrays computed one at a time: at 10^6 particles the cells would hold 41 MB through
  // the run, the raw arrays 200 MB at once.
  void write_snapshot(const Solver& s, double t) {
    io::snapshot_parts snapshot = io::snapshot_of(s);  // with its crack faces and failed points, if any
    const auto vtu = vtk_.add_snapshot(t, snapshot.points, std::move(snapshot.xyz), snapshot.cells, snapshot.fields,
                                       snapshot_format_, io::snapshot_tools(s));
    record_.snapshots.emplace_back(t, vtu.filename().string());
  }

  // history.csv columns: time, the case's measures, tool forces, energies, the fragments when
  // cracks can grow.
  std::vector<std::string> column_names(const Solver& s) const {
    std::vector<std::string> columns{"time_s"};
    for (const auto& [k, v] : measures_) columns.push_back(k);
    for (const auto& tool : s.contact().tools()) {
      columns.push_back(tool.name() + "_force_x_N");
      columns.push_back(tool.name() + "_force_y_N");
    }
    for (const auto& [name, value] : io::energy_terms(s.energy(), rebuilds_model(s)))
      columns.emplace_back(name);
    if (s.options().mass_scaling.enabled()) columns.emplace_back("kinetic_to_internal");
    for (const auto& [name, value] : io::fragment_terms(s)) columns.emplace_back(name);
    for (const auto& companion : s.companions())
      for (const auto& [name, value] : companion->report(s)) columns.push_back(name);
    return columns;
  }

  // The tool forces are the impulses of the interval (explicit_solver::tool_impulses at its end
  // less at its start) over its length. The run's last interval can be a step or two long (the
  // row before fell just short of the end time): a force averaged over so short a span is one
  // step's contact impulse, not a force, so that row averages over it and the interval before.
  void add_history_row(const Solver& s, double t, bool last) {
    const double span = t - record_.interval_start;
    const bool merge = last && span < 0.5 * record_.history_interval && record_.previous_span > 0.0;
    const std::vector<vec2>& impulse = s.tool_impulses();
    for (index_t k = 0; k < tools_; ++k) {
      if (merge)
        mean_force_[k] = (impulse[k] - record_.previous_start_impulse[k]) / (span + record_.previous_span);
      else
        mean_force_[k] = span > 0.0 ? vec2((impulse[k] - record_.start_impulse[k]) / span) : vec2::Zero();
    }
    record_.previous_start_impulse = record_.start_impulse;
    record_.start_impulse = impulse;
    record_.previous_span = span;
    record_.interval_start = t;
    measures_ = row_measures<Case>(row_reduced_, s, params_, mean_force_);
    std::vector<double> row{t};
    for (const auto& [k, v] : measures_) row.push_back(v);
    for (const vec2& f : mean_force_) {
      row.push_back(f[0]);
      row.push_back(f[1]);
    }
    for (const auto& [name, value] : io::energy_terms(s.energy(), rebuilds_model(s)))
      row.push_back(value);
    if (s.options().mass_scaling.enabled()) {
      row.push_back(s.energy().internal > 0.0 ? s.energy().kinetic / s.energy().internal : 0.0);
      warn_if_dynamic(s, warned_dynamic_);
    }
    for (const auto& [name, value] : io::fragment_terms(s)) row.push_back(value);
    for (const auto& companion : s.companions())
      for (const auto& [name, value] : companion->report(s)) row.push_back(value);
    history_.row(row);
    record_.history_rows.push_back(std::move(row));
  }

  bool warned_dynamic_ = false;
  std::filesystem::path dir_;
  typename Case::parameters params_;
  run_record record_;
  json identity_;
  std::string configuration_;
  bool quiet_;
  io::vtu_format snapshot_format_;
  run_hooks hooks_;
  index_t tools_;
  std::vector<vec2> mean_force_;
  measures measures_;
  io::csv_writer history_;
  io::pvd_series vtk_;
  figure_recorder<Case> figures_;
  io::progress_line progress_{false};
  std::chrono::steady_clock::time_point segment_start_;
  std::filesystem::path last_checkpoint_;
  bool skip_next_ = false;
  double output_s_ = 0.0;
  process_steps<Solver>* divided_ = nullptr;  // divide(): snapshots in pieces, checkpoints in parts
  bool rows_by_reduction_ = false;  // the rows' measures reduce over the ranks (measure_maxima, no companions)
  row_reduction row_reduced_;       // the current call's, reduced over the ranks (observe_part)
  bool part_only_ = false;          // rank 0 observes its part only: no whole solver (set up in parts)
  const background_mesh* whole_mesh_ = nullptr;  // then the whole mesh, for the figure shapes
  const std::vector<vec2>* positions_ = nullptr;  // the current call's gathered positions, if any
};

}  // namespace rkpm::runner
