#pragma once
// simulate<Case>(request, parameters, make): builds the solver with make() and runs one case to its end time and writes its results:
//   summary.json  policies, sizes, steps, time-step range, timings, energies, key results
//   history.csv   time, the case's key measures, tool forces, energies (flushed per row)
//   CASE.pvd + CASE_NNNNNN.vtu  particles with displacement, velocity, stress, eps_p, det F
//   shape_*.csv and PNG figures (figures.hpp, drawn from the shapes and history kept in memory)
// A run that fails (NaN, inverted body) keeps what it wrote and records the error in
// summary.json. The loop itself does no I/O between output times.

#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include <rkpm/io/csv.hpp>
#include <rkpm/io/progress.hpp>
#include <rkpm/io/vtk.hpp>

#include "figures.hpp"
#include "json.hpp"
#include "outcome.hpp"
#include "request.hpp"

namespace rkpm::runner {

inline int active_threads() {
#ifdef _OPENMP
  return omp_get_max_threads();
#else
  return 1;
#endif
}

// Particle fields for the VTK snapshot.
template <class Solver>
io::point_data snapshot_fields(const Solver& s) {
  io::point_data data;
  data.add("displacement", s.particle_displacements());
  data.add("velocity", s.particle_velocities());
  data.add("stress", s.template project_to_particles<mat3>([&](index_t q) { return s.point_cauchy_stress(q); }));
  data.add("equivalent_plastic_strain", s.template project_to_particles<double>([&](index_t q) {
    return static_cast<double>(s.point_states()[q].equivalent_plastic_strain);
  }));
  data.add("det_F", s.template project_to_particles<double>([&](index_t q) { return s.point_det_F()[q]; }));
  return data;
}

// The policy names of a configuration, as summary.json records them. Passed as values so that
// simulate is compiled once per solver type (3 per case), not once per configuration (36).
struct method_names {
  std::string_view kernel, correction, quadrature, geometry, contact;
  template <class Config>
  static method_names of() {
    return {Config::kernel_type::name, Config::correction_type::name, Config::quadrature_type::name,
            Config::geometry_type::name, Config::contact_type::enforcement_type::name};
  }
};

template <class Case, class Solver>
run_outcome simulate(const run_request& request, const typename Case::parameters& params,
                     const method_names& method, const std::function<Solver()>& make) {
  namespace fs = std::filesystem;
  run_outcome outcome;
  outcome.directory = request.output_directory();
  const fs::path dir = outcome.directory;
  fs::create_directories(dir);

  json& summary = outcome.summary;
  summary = json::object();
  summary["case"] = Case::name;
  summary["kernel"] = method.kernel;
  summary["correction"] = method.correction;
  summary["quadrature"] = method.quadrature;
  summary["geometry"] = method.geometry;
  summary["contact"] = method.contact;
  summary["resolution"] = request.resolution;
  summary["status"] = "setting up";
  json& parameters = summary["parameters"];
  parameters = json::object();
  for (const auto& f : Case::parameters::fields)
    cases::visit_value(f, params, [&](auto value) { parameters[std::string(f.name)] = value; });

  const auto t0 = std::chrono::steady_clock::now();
  std::optional<Solver> holder;
  try {
    holder.emplace(make());
  } catch (const std::exception& e) {
    summary["status"] = "failed";
    summary["error"] = e.what();
    write_json(dir / "summary.json", summary);
    throw;
  }
  Solver& s = *holder;
  const double setup_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double end_time = s.options().end_time;
  const index_t tools = static_cast<index_t>(s.contact().tools().size());

  // history.csv columns: time, the case's measures, tool forces, energies.
  std::vector<vec2> mean_force(tools, vec2::Zero()), impulse(tools, vec2::Zero());
  auto measures = Case::measure(s, params, mean_force);
  std::vector<std::string> columns{"time_s"};
  for (const auto& [k, v] : measures) columns.push_back(k);
  for (const auto& tool : s.contact().tools()) {
    columns.push_back(tool.name() + "_force_x_N");
    columns.push_back(tool.name() + "_force_y_N");
  }
  for (const char* c : {"kinetic_J", "internal_J", "plastic_J", "contact_J", "external_J", "balance_error"})
    columns.emplace_back(c);
  io::csv_writer history(dir / "history.csv", columns);
  history_table table{columns, {}};  // the same rows, for the figures
  io::pvd_series vtk(dir / (std::string(Case::name) + ".pvd"));
  figure_recorder<Case> figures(dir, params);

  const int history_rows = 400, snapshots = 20;
  double next_history = 0.0, next_snapshot = 0.0, last_time = 0.0, interval_start = 0.0;
  io::progress_line progress(false);
  std::vector<double> row;
  auto observe = [&](const Solver& s) {
    const double t = s.time(), dt = t - last_time;
    last_time = t;
    for (index_t k = 0; k < tools; ++k) impulse[k] += s.contact().reactions()[k] * dt;
    const bool last = t >= end_time * (1.0 - 1e-12);
    if (!request.quiet) progress.update(t, end_time, static_cast<long>(s.steps()));
    if (t >= next_history || last) {
      const double span = t - interval_start;
      for (index_t k = 0; k < tools; ++k) mean_force[k] = span > 0.0 ? vec2(impulse[k] / span) : vec2::Zero();
      std::fill(impulse.begin(), impulse.end(), vec2::Zero());
      interval_start = t;
      measures = Case::measure(s, params, mean_force);
      row.assign(1, t);
      for (const auto& [k, v] : measures) row.push_back(v);
      for (const vec2& f : mean_force) {
        row.push_back(f[0]);
        row.push_back(f[1]);
      }
      const auto& e = s.energy();
      for (double v : {e.kinetic, e.internal, e.plastic, e.contact, e.external, e.balance_error()}) row.push_back(v);
      history.row(row);
      table.rows.push_back(row);
      next_history += end_time / history_rows;
    }
    if (t >= next_snapshot || last) {
      vtk.add_snapshot(t, s.particle_positions(), snapshot_fields(s));
      next_snapshot += end_time / snapshots;
    }
    figures.observe(s);
  };

  summary["status"] = "running";
  const auto t1 = std::chrono::steady_clock::now();
  std::string error;
  try {
    s.run(observe, 1);
  } catch (const std::exception& e) {
    error = e.what();
  }
  progress.finish();
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();

  summary["status"] = error.empty() ? "completed" : "failed";
  if (!error.empty()) summary["error"] = error;
  summary["particles"] = s.model().particle_count();
  summary["quadrature_points"] = s.model().point_count();
  summary["steps"] = s.steps();
  summary["dt_min_s"] = s.min_time_step();
  summary["dt_max_s"] = s.max_time_step();
  summary["end_time_s"] = s.time();
  summary["threads"] = active_threads();
  summary["wall_s"] = wall_s;
  summary["setup_s"] = setup_s;
  json& energy = summary["energy"];
  energy = json::object();
  const auto& e = s.energy();
  energy["kinetic_J"] = e.kinetic;
  energy["internal_J"] = e.internal;
  energy["plastic_J"] = e.plastic;
  energy["contact_J"] = e.contact;
  energy["external_J"] = e.external;
  energy["balance_error"] = e.balance_error();
  json& results = summary["results"];  // the case's measures at the end of the run
  results = json::object();
  for (const auto& [k, v] : measures) results[k] = v;
  write_json(dir / "summary.json", summary);
  if (request.plots) {
    try {
      figures.plot(table);
    } catch (const std::exception& ex) {
      fmt::print(stderr, "rkpm_run: figures skipped: {}\n", ex.what());
    }
  }
  if (!error.empty()) fail("{} (what was written so far is in {})", error, outcome.directory);
  outcome.completed = true;
  return outcome;
}

}  // namespace rkpm::runner
