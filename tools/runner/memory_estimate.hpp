#pragma once
// A warning before a large run is built: the memory a problem will take, estimated from its
// particle and quadrature-point counts with the footprint measured on the Taylor bar
// (docs/performance.md, third round: peak resident set 1.48 KB per particle with Q2 at
// 10^6 particles, most of it the shape-function table at the points, 450 B per point, which
// grows with the points per particle), against what /proc/meminfo says is available. On several
// processes of one machine: set up in parts (ranks.hpp, part_setup.hpp), each process holds its
// share of the particles with their ghosts and the shared region, and the whole model's layout
// while it sets up; set up whole, every process holds the whole model and rank 0 a whole solver
// besides.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <string>

#include <fmt/format.h>

#include <rkpm/core/types.hpp>

namespace rkpm::runner {

// MemAvailable in bytes, if the system says (RKPM_AVAILABLE_MEMORY_BYTES overrides it, for tests).
inline std::optional<double> available_memory_bytes() {
  if (const char* forced = std::getenv("RKPM_AVAILABLE_MEMORY_BYTES")) return std::strtod(forced, nullptr);
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  double kb = 0.0;
  std::string unit;
  while (meminfo >> key >> kb >> unit)
    if (key == "MemAvailable:") return kb * 1024.0;
  return std::nullopt;
}

// Bytes a run of `particles` particles with `points_per_particle` quadrature points each is
// expected to need (1.7 KB per particle at Q2's two points per cell, about one cell per particle;
// 0.55 KB per point: 16 table entries of 28 B, the material state, position, weight and cell;
// 0.6 KB per particle for the solver's and controller's vectors, the table at the particles, the
// particles, the mesh and the runner's output buffers).
inline double estimated_run_bytes(index_t particles, double points_per_particle) {
  return static_cast<double>(particles) * (0.6e3 + 0.55e3 * points_per_particle);
}

// The particles a process holds when `particles` are set up in parts over `processes`: its share,
// the ghosts of a square part (3.5 for each of its 4 sqrt(share) boundary particles) and the
// shared region every process holds (8.8 sqrt(particles): the contact surface and the axis;
// docs/method.md 9.8), at most all of them.
inline double particles_per_process_in_parts(index_t particles, int processes) {
  const double n = static_cast<double>(particles), share = n / std::max(processes, 1);
  return std::min(n, share + 14.0 * std::sqrt(share) + 8.8 * std::sqrt(n));
}
// The layout of the whole model every process holds while it sets up in parts (positions,
// supports, cells, points, the neighbour search, the partition: docs/performance.md).
inline constexpr double layout_bytes_per_particle = 200.0;

// A run's processes on one machine. Set up whole (ranks.hpp), each builds the whole model before
// it keeps its part, and rank 0 keeps a whole solver besides: copies() whole models. Set up in
// parts, each holds its part (particles_per_process_in_parts) and the layout.
struct machine_share {
  bool divided = false;      // the run is on several processes
  int processes = 1;         // its processes on this machine
  bool holds_rank_0 = true;  // whether rank 0 is one of them
  int all_processes = 1;     // the run's processes on every machine
  bool in_parts = false;     // set up in parts (part_setup.hpp)
  int copies() const { return processes + (divided && holds_rank_0 ? 1 : 0); }
};

// Prints a warning to stderr when the estimate exceeds what is available.
// `points`: the quadrature points the rule will make (rkpm::quadrature_point_count).
inline void warn_if_too_large(index_t particles, double points, machine_share here = {}) {
  const auto available = available_memory_bytes();
  const double points_per_particle = particles > 0 ? points / double(particles) : 0.0;
  const double one = estimated_run_bytes(particles, points_per_particle);
  const double local = particles_per_process_in_parts(particles, here.all_processes);
  const double per_process = estimated_run_bytes(static_cast<index_t>(std::ceil(local)), points_per_particle) +
                             layout_bytes_per_particle * static_cast<double>(particles);
  const double needed = here.divided && here.in_parts ? here.processes * per_process : here.copies() * one;
  if (!available || needed <= *available) return;
  if (here.divided && here.in_parts)
    fmt::print(stderr,
               "rkpm_run: warning: the {} processes on this machine each set up their part of {} particles in parts: "
               "about {:.0f} particles with their ghosts and {:.0f} MB each (with the whole model's layout while it "
               "sets up), {:.0f} MB in all, but only {:.0f} MB is available: the run may be killed or swap; lower "
               "--resolution, run fewer processes per machine, or free memory\n",
               here.processes, particles, std::ceil(local), per_process / 1e6, needed / 1e6, *available / 1e6);
  else if (!here.divided)
    fmt::print(stderr,
               "rkpm_run: warning: {} particles need about {:.0f} MB (about {:.1f} KB per particle), but only {:.0f} MB "
               "is available: the run may be killed or swap; lower --resolution or free memory\n",
               particles, needed / 1e6, one / particles / 1e3, *available / 1e6);
  else
    fmt::print(stderr,
               "rkpm_run: warning: the {} processes on this machine each build the whole model of {} particles{}: "
               "about {:.0f} MB for {} copies (about {:.1f} KB per particle each), but only {:.0f} MB is available: the "
               "run may be killed or swap; lower --resolution, run fewer processes per machine, or free memory\n",
               here.processes, particles, here.holds_rank_0 ? ", and rank 0 keeps a whole solver" : "", needed / 1e6,
               here.copies(), one / particles / 1e3, *available / 1e6);
}

}  // namespace rkpm::runner
