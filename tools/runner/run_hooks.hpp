#pragma once
// What a caller that embeds the runner (the Python module, tools/python) can ask of a run beyond
// the command line's outputs: an observer called with the particles every `every` steps, which
// stops the run cleanly by returning false, and the particles at the end. The command line sets
// none of this; a run without hooks is the same run, bit for bit.

#include <functional>
#include <vector>

#include <rkpm/core/types.hpp>
#include <rkpm/io/solver_output.hpp>
#include <rkpm/io/vtk.hpp>

namespace rkpm::runner {

// The particles at one instant: positions (m) and every field of a snapshot
// (io::snapshot_fields: displacement, velocity, stress, equivalent plastic strain, det F and the
// material's own fields), so that a caller sees what ParaView would.
struct particle_state {
  double time_s = 0.0;
  long step = 0;
  std::vector<vec2> positions;
  io::point_data fields;
};

template <class Solver>
particle_state particle_state_of(const Solver& s) {
  return {s.time(), static_cast<long>(s.steps()), s.particle_positions(), io::snapshot_fields(s)};
}

struct run_hooks {
  // Called at the start, every `every` steps and at the end; false stops the run after this step.
  std::function<bool(const particle_state&)> observe;
  long every = 1;
  bool keep_final_state = false;  // run_outcome::final_state
};

// Thrown by the run observer when run_hooks::observe returns false; simulate() ends the run
// there with the status "stopped" (not an error).
struct stop_requested {
  double time_s;
  long step;
};

}  // namespace rkpm::runner
