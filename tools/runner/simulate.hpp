#pragma once
// simulate<Case>(request, parameters, method, make, restart): builds the solver with make(), or
// continues a checkpoint, runs one case to its end time and writes its results:
//   summary.json  policies, sizes, steps, time-step range, timings, energies, key results
//   history.csv   time, the case's key measures, tool forces, energies (flushed per row)
//   CASE.pvd + CASE_NNNNNN.vtu  particles (the background cells' nodes) with displacement,
//                 velocity, stress, eps_p, det F, and the tools' vertices
//   shape_*.csv and PNG figures (figures.hpp, drawn from the shapes and history kept in memory),
//                 and final_plastic_strain.png (the plastic strain on the deformed cells)
//   checkpoint_NNNNNNNNNN.rkpmcp  with --checkpoint-interval: after the first step reaching each
//                 multiple of the interval, and at the end (run_observer.hpp, run_record.hpp)
// A run that fails (NaN, inverted body) keeps what it wrote and records the error in
// summary.json; one stopped between steps (by the step limit, or by Ctrl-C or SIGTERM, see
// interrupt.hpp) also writes a checkpoint to continue from. The loop itself does no I/O between output times.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include <rkpm/io/solver_output.hpp>
#include <rkpm/solver/checkpoint.hpp>

#include "case_traits.hpp"
#include "final_figures.hpp"
#include "json.hpp"
#include "outcome.hpp"
#include "process_steps.hpp"
#include "request.hpp"
#include "run_observer.hpp"
#include "run_record.hpp"

namespace rkpm::runner {

inline int active_threads() {
#ifdef _OPENMP
  return omp_get_max_threads();
#else
  return 1;
#endif
}

// The policy names of a run, as summary.json records them, and its configuration's full name
// (config<...>::name()'s form, which checkpoints check). Passed as values so that simulate is
// compiled once per solver type (one per case), not once per combination.
struct run_policies {
  std::string_view kernel, correction, quadrature, geometry, contact;
  std::string configuration;
};

// What identifies a run for a restart: the case, its policies, resolution and parameters
// (summary.json's first keys, and the description of every checkpoint).
template <class Case>
json run_identity(const run_request& request, const typename Case::parameters& params, const run_policies& method) {
  json id = json::object();
  id["case"] = case_name<Case>(params);
  id["kernel"] = method.kernel;
  id["correction"] = method.correction;
  id["quadrature"] = method.quadrature;
  id["geometry"] = method.geometry;
  id["contact"] = method.contact;
  id["resolution"] = request.resolution;
  if (request.rereference.enabled())
    id["rereference"] = {{"max_stretch", request.rereference.max_stretch},
                         {"every_steps", request.rereference.every_steps}};
  if (request.mass_scaling.enabled())
    id["mass_scaling"] = {{"factor", request.mass_scaling.factor},
                          {"target_dt_s", request.mass_scaling.target_time_step},
                          {"max_kinetic_to_internal", request.mass_scaling.max_kinetic_to_internal}};
  if constexpr (is_file_case<Case>) id["case_file"] = std::filesystem::absolute(params.file).string();
  id["parameters"] = case_parameters<Case>(params);
  return id;
}

// The runner's snapshots: appended arrays, compressed as the request says.
inline io::vtu_format snapshot_format(const run_request& request) {
  return io::vtu_format(io::vtu_encoding::appended, request.vtu_compression);
}

// summary.json's figures of a run that has ended, failed or stopped: sizes, steps, time-step
// range, timings, the energy ledger, what ran beside the solver, the mass scaling's and the
// re-references' record, the fragments and the material state's extremes.
template <class Solver, class Observer>
void add_run_summary(json& summary, const Solver& s, const Observer& observe, int processes) {
  summary["particles"] = s.model().particle_count();
  summary["quadrature_points"] = s.model().point_count();
  summary["steps"] = s.steps();
  summary["dt_min_s"] = s.min_time_step();
  summary["dt_max_s"] = s.max_time_step();
  summary["end_time_s"] = s.time();
  summary["threads"] = active_threads();
  summary["processes"] = processes;
  summary["wall_s"] = observe.wall_s();
  summary["output_s"] = observe.output_s();  // of wall_s, this part of the run: not the steps
  summary["setup_s"] = observe.record().setup_s;
  if (!observe.record().restarts.empty()) summary["restarts"] = observe.record().restarts;
  if (!observe.last_checkpoint().empty()) summary["last_checkpoint"] = observe.last_checkpoint().filename().string();
  json& energy = summary["energy"];
  energy = json::object();
  for (const auto& [name, value] : io::energy_terms(s.energy(), rebuilds_model(s)))
    energy[std::string(name)] = value;
  // What ran beside the solver (a case file's "heat": the heat flows and temperatures at the end).
  for (const auto& companion : s.companions())
    for (const auto& [name, value] : companion->report(s)) summary["coupled"][name] = value;
  if (s.options().mass_scaling.enabled()) {
    // The mass added per body (kg per metre of depth in plane strain, kg axisymmetric) and how
    // far the run stayed from dynamics (85).
    std::vector<double> added(static_cast<std::size_t>(s.bodies()), 0.0);
    for (index_t I = 0; I < s.model().particle_count(); ++I)
      added[static_cast<std::size_t>(s.body_of_particle(I))] += s.mass()[I] - s.physical_mass()[I];
    const quasi_static_check& q = s.quasi_static();
    json& m = summary["scaled_masses"];
    m["factor"] = s.mass_scaling_factor();
    m["added_mass_per_body"] = added;
    m["max_kinetic_to_internal"] = std::isfinite(q.worst_ratio) ? q.worst_ratio : 1e300;
    m["max_kinetic_to_internal_at_s"] = q.worst_time;
    m["quasi_static"] = !q.left();
    if (q.left()) m["left_quasi_static_at_s"] = q.left_at;
  }
  for (const auto& [name, value] : io::fragment_terms(s)) summary[std::string(name)] = value;  // cracks can grow
  if (rebuilds_model(s)) {
    summary["rereferences"] = s.rereferences();
    summary["rereference_times_s"] = s.rereference_times();
  }
  // The material state's extremes (io/solver_output.hpp): the largest temperature, damage, the
  // failed fraction of the points, when the material has them.
  if (const auto points = io::state_summary(s); !points.empty()) {
    json& state = summary["points"];
    for (const auto& [k, v] : points) state[k] = v;
  }
}

// steps: how the solver is stepped (process_steps.hpp): null on one process (the solver steps
// itself); on several, rank 0's view of the divided run, whose set_up() builds the solver rank 0
// observes (its part, or a whole solver; make() is then not called).
template <class Case, class Solver>
run_outcome simulate(const run_request& request, const typename Case::parameters& params, const run_policies& method,
                     const std::function<Solver()>& make, const std::optional<restart_point>& restart = {},
                     process_steps<Solver>* steps = nullptr) {
  namespace fs = std::filesystem;
  one_process_steps<Solver> alone(method.configuration);
  if (!steps) steps = &alone;
  run_outcome outcome;
  outcome.directory = request.output_directory();
  const fs::path dir = outcome.directory;
  fs::create_directories(dir);

  json& summary = outcome.summary;
  // The identity's keys, with the status before the (long) parameters.
  const json identity = run_identity<Case>(request, params, method);
  summary = json::object();
  for (const auto& [key, value] : identity.items())
    if (key != "parameters") summary[key] = value;
  summary["status"] = "setting up";
  summary["parameters"] = identity.at("parameters");

  const auto t0 = std::chrono::steady_clock::now();
  std::optional<Solver> holder;
  Solver* observed = nullptr;  // the whole solver, or rank 0's part when the run is set up in parts
  run_record record;
  try {
    observed = steps->set_up();
    if (!observed) observed = &holder.emplace(make());
    if constexpr (requires { Case::attach(*observed, params, true); }) Case::attach(*observed, params, steps->divided());
    if (restart) {
      steps->read_checkpoint(restart->file, observed);
      record = record_from_json(restart->description.at("record"));
      record.restarts.push_back({{"checkpoint", fs::absolute(restart->file).string()},
                                 {"time_s", observed->time()}, {"step", observed->steps()}});
      // Snapshots written before live in the checkpoint's folder.
      const fs::path from = fs::absolute(restart->file).parent_path();
      if (from != fs::absolute(dir))
        for (auto& [t, file] : record.snapshots) file = fs::relative(from / file, fs::absolute(dir)).string();
    }
  } catch (const std::exception& e) {
    summary["status"] = "failed";
    summary["error"] = e.what();
    write_json(dir / "summary.json", summary);
    throw;
  }
  Solver& s = *observed;
  std::optional<run_observer<Case, Solver>> observer;
  try {
    if (restart && s.time() >= s.options().end_time * (1.0 - 1e-12))
      fail("--restart {}: the checkpoint is at t = {:.6g} s, the end time already; give a later --end-time to "
           "continue it",
           restart->file.string(), s.time());
    const double setup_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double end_time = s.options().end_time;
    if (!restart) {
      const auto [rows, snapshots] = output_counts<Case>(params);
      record.history_interval = end_time / rows;
      record.snapshot_interval = end_time / snapshots;
      record.setup_s = setup_s;
    }
    // A new interval (a first run, or a restart asking for another) starts at the next multiple
    // after now; a restart with the same interval keeps the checkpoint's clock, so that it writes
    // the uninterrupted run's checkpoints.
    if (request.checkpoint_interval && *request.checkpoint_interval != record.checkpoint_interval) {
      record.checkpoint_interval = *request.checkpoint_interval;
      record.next_checkpoint = std::floor(s.time() / record.checkpoint_interval) * record.checkpoint_interval;
      while (record.next_checkpoint <= s.time()) record.next_checkpoint += record.checkpoint_interval;
    }
    observer.emplace(dir, params, s, std::move(record), identity, method.configuration, request.quiet,
                     snapshot_format(request), request.hooks);
    if (restart) observer->resume(fs::absolute(restart->file).parent_path());
    if (steps->divided()) observer->divide(*steps);
    summary["status"] = "running";  // what a killed run's folder says
    write_json(dir / "summary.json", summary);
  } catch (const std::exception& e) {
    steps->abandon(e.what());  // the other ranks wait for the run: every rank throws
    throw;
  }
  run_observer<Case, Solver>& observe = *observer;
  std::string error;
  bool stopped = false, settled = false, written = false;
  // The whole solver brought up to date after the run, ended or failed, and the checkpoint then
  // handed over written in parts (on several processes; follow_run makes the same calls).
  const auto settle = [&] {
    if (!std::exchange(settled, true)) steps->settle(&s);
  };
  const auto write_pending = [&] {
    if (!std::exchange(written, true)) steps->write_pending_checkpoint();
  };
  try {
    steps->run(&s, {.needs = [&](double t, double end) { return observe.needs(t, end); },
                    .snapshot = [&](double t, double end) { return observe.snapshot_due(t, end); },
                    .pass = [&](double t, double end, long n) { observe.pass(t, end, n); },
                    .shape_due = [&](double t, double end) { return observe.shape_due(t, end); },
                    .observe = [&](const Solver& at) { observe(at); },
                    .observe_part = [&](const Solver& p, auto m, const std::vector<vec2>* x) {
                      observe.observe_part(p, std::move(m), x);
                    }});
    settle();
    if (observe.record().checkpoint_interval > 0.0) observe.write_checkpoint_now(s);
    write_pending();
  } catch (const stop_requested&) {
    stopped = true;  // the caller's observer asked (run_hooks.hpp): not an error
  } catch (const std::exception& e) {
    error = e.what();
    settle();
    // Stopped between steps (the step limit, Ctrl-C): the state is whole and can be continued.
    const bool whole = steps->between_steps(s);
    try {
      if (whole && (observe.record().checkpoint_interval > 0.0 || pending_interrupt().load() != 0))
        observe.write_checkpoint_now(s);
      write_pending();
    } catch (const std::exception& e2) {
      fmt::print(stderr, "rkpm_run: no checkpoint at the failure: {}\n", e2.what());
    }
  }
  observe.finish();

  summary["status"] = !error.empty() ? "failed" : stopped ? "stopped" : "completed";
  if (!error.empty()) summary["error"] = error;
  add_run_summary(summary, s, observe, steps->processes());
  steps->amend_summary(summary);
  if (steps->divided() && s.options().rereference.enabled()) summary["repartitions"] = steps->repartitions();
  json& results = summary["results"];  // the case's measures at the end of the run
  results = json::object();
  for (const auto& [k, v] : observe.last_measures()) results[k] = v;
  write_json(dir / "summary.json", summary);
  if (request.plots) {
    try {
      observe.figures().plot(observe.table());
      if (!steps->draw_end_state(dir, case_name<Case>(params)) && !steps->observes_part())  // ranks.hpp: gathered
        final_plastic_strain_png(dir, case_name<Case>(params), s, io::snapshot_cell_layout(s));
    } catch (const std::exception& ex) {
      fmt::print(stderr, "rkpm_run: figures skipped: {}\n", ex.what());
    }
  }
  outcome.history = observe.table();
  if (request.hooks.keep_final_state) outcome.final_state = particle_state_of(s);
  if (!error.empty()) {
    const std::string hint = observe.last_checkpoint().empty()
                                 ? std::string()
                                 : fmt::format("; continue with --restart {}", observe.last_checkpoint().string());
    throw run_failure(fmt::format("{} (what was written so far is in {}{})", error, outcome.directory, hint));
  }
  outcome.completed = !stopped;
  return outcome;
}

}  // namespace rkpm::runner
