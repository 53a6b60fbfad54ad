#pragma once
// What rkpm_run keeps in a checkpoint besides the solver's state (solver/checkpoint.hpp), as JSON
// in the checkpoint's description (io/checkpoint_format.hpp): the case, policies, resolution and
// parameters the run was started with, and the record of its outputs so far (the history rows,
// the snapshots, the output clocks, the tool impulses at the history intervals' starts, the wall
// time). A restart rebuilds the same problem from the first part and continues the outputs
// from the second, so that its history.csv, snapshots and summary.json are the uninterrupted
// run's (docs/method.md section 9.5).

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/io/checkpoint.hpp>
#include <rkpm/io/checkpoint_parts.hpp>

#include "json.hpp"

namespace rkpm::runner {

// The observer's state between two steps.
struct run_record {
  double history_interval = 0.0, snapshot_interval = 0.0, checkpoint_interval = 0.0;  // s; 0: none
  double next_history = 0.0, next_snapshot = 0.0, next_checkpoint = 0.0;               // s
  double interval_start = 0.0;  // s, the start of the open history row
  // The tools' impulses since t = 0 (explicit_solver::tool_impulses) at interval_start and at
  // the start of the last closed interval (N s).
  std::vector<vec2> start_impulse, previous_start_impulse;
  double previous_span = 0.0;                    // s, the last closed interval's length
  std::vector<std::vector<double>> history_rows;
  std::vector<std::pair<double, std::string>> snapshots;  // .pvd entries: time, file relative to the run folder
  std::size_t shapes = 0;                                 // figure shapes recorded (figures.hpp)
  double wall_s = 0.0, setup_s = 0.0;                     // over every part of the run so far
  json restarts = json::array();                          // {checkpoint, time_s, step} per restart
};

inline json to_json(const run_record& r) {
  json impulse = json::array(), previous = json::array();
  for (const vec2& i : r.start_impulse) impulse.push_back({i[0], i[1]});
  for (const vec2& i : r.previous_start_impulse) previous.push_back({i[0], i[1]});
  return {{"history_interval_s", r.history_interval}, {"snapshot_interval_s", r.snapshot_interval},
          {"checkpoint_interval_s", r.checkpoint_interval}, {"next_history_s", r.next_history},
          {"next_snapshot_s", r.next_snapshot}, {"next_checkpoint_s", r.next_checkpoint},
          {"interval_start_s", r.interval_start},
          {"start_impulse_N_s", impulse}, {"previous_start_impulse_N_s", previous},
          {"previous_span_s", r.previous_span},
          {"history_rows", r.history_rows}, {"snapshots", r.snapshots},
          {"shapes", r.shapes}, {"wall_s", r.wall_s}, {"setup_s", r.setup_s}, {"restarts", r.restarts}};
}

inline run_record record_from_json(const json& j) {
  run_record r;
  r.history_interval = j.at("history_interval_s").get<double>();
  r.snapshot_interval = j.at("snapshot_interval_s").get<double>();
  r.checkpoint_interval = j.at("checkpoint_interval_s").get<double>();
  r.next_history = j.at("next_history_s").get<double>();
  r.next_snapshot = j.at("next_snapshot_s").get<double>();
  r.next_checkpoint = j.at("next_checkpoint_s").get<double>();
  r.interval_start = j.at("interval_start_s").get<double>();
  for (const auto& i : j.at("start_impulse_N_s"))
    r.start_impulse.emplace_back(i.at(0).get<double>(), i.at(1).get<double>());
  for (const auto& i : j.at("previous_start_impulse_N_s"))
    r.previous_start_impulse.emplace_back(i.at(0).get<double>(), i.at(1).get<double>());
  r.previous_span = j.at("previous_span_s").get<double>();
  r.history_rows = j.at("history_rows").get<std::vector<std::vector<double>>>();
  r.snapshots = j.at("snapshots").get<std::vector<std::pair<double, std::string>>>();
  r.shapes = j.at("shapes").get<std::size_t>();
  r.wall_s = j.at("wall_s").get<double>();
  r.setup_s = j.at("setup_s").get<double>();
  r.restarts = j.at("restarts");
  return r;
}

// A checkpoint to restart from: the file, and the runner's description in it.
struct restart_point {
  std::filesystem::path file;
  json description;  // case, kernel, correction, quadrature, contact, resolution, parameters, record
};

// The latest checkpoint of the folder of `file` (a checkpoint_file_name) named before it that
// reads intact, if any: where to restart when `file` is damaged or truncated.
inline std::optional<std::filesystem::path> earlier_intact_checkpoint(const std::filesystem::path& file) {
  const std::string name = file.filename().string();
  if (!name.starts_with("checkpoint_")) return std::nullopt;
  const auto all = io::checkpoints_in(file.has_parent_path() ? file.parent_path() : ".");
  for (auto it = all.rbegin(); it != all.rend(); ++it) {
    if (it->filename().string() >= name) continue;
    try {
      io::read_any_checkpoint_header(*it);
      return *it;
    } catch (const rkpm::error&) {
    }
  }
  return std::nullopt;
}

// PATH is a checkpoint file, a checkpoint in parts (a folder checkpoint_*.rkpmcp of
// part-K-of-P.rkpmcp files, io/checkpoint_parts.hpp) or a run folder (its latest checkpoint).
// Refuses, in one line, a path that is none of these, a checkpoint the runner did not write, and
// a damaged, truncated or incomplete one, naming the folder's latest intact earlier checkpoint if
// there is one.
inline restart_point find_restart_point(const std::filesystem::path& given) {
  namespace fs = std::filesystem;
  const fs::path path = given.has_filename() ? given : given.parent_path();  // "run/" is "run"
  restart_point p;
  if (fs::is_directory(path) && path.extension() != io::checkpoint_extension) {
    const auto latest = io::latest_checkpoint(path);
    if (!latest)
      fail("--restart {}: the folder has no checkpoint_*{} file; run with --checkpoint-interval SECONDS to "
           "write checkpoints",
           path.string(), io::checkpoint_extension);
    p.file = *latest;
  } else if (fs::exists(path)) {
    p.file = path;
  } else {
    fail("--restart {}: no such checkpoint file or run folder", path.string());
  }
  io::checkpoint_header header;
  try {
    header = io::read_any_checkpoint_header(p.file);
  } catch (const io::checkpoint_damaged& e) {
    const auto earlier = earlier_intact_checkpoint(p.file);
    if (!earlier) throw;
    fail("{}: {}", e.what(), earlier->string());  // "...; restart from an earlier checkpoint: PATH"
  }
  p.description = json::parse(header.description, nullptr, false);
  if (p.description.is_discarded() || !p.description.is_object() || !p.description.contains("record"))
    fail("checkpoint '{}' was not written by rkpm_run (its description is not the runner's): restart it "
         "from the program that wrote it",
         p.file.string());
  return p;
}

}  // namespace rkpm::runner
