#pragma once
// What one run hands back to the command line, to `rkpm_run paper` and to the Python module.

#include <optional>
#include <string>

#include <rkpm/core/error.hpp>

#include "history_table.hpp"
#include "json.hpp"
#include "run_hooks.hpp"

namespace rkpm::runner {

struct run_outcome {
  bool completed = false;  // reached the end time (false: stopped by run_hooks::observe)
  std::string directory;
  json summary;            // the content of summary.json
  history_table history;   // the rows of history.csv
  std::optional<particle_state> final_state;  // with run_hooks::keep_final_state
};

// A run that failed after its set-up (NaN, an inverted body, an interrupt): what was written so
// far stays in the run's folder. Errors before (the request, the case file, the set-up) are
// plain rkpm::error.
class run_failure : public error {
 public:
  using error::error;
};

}  // namespace rkpm::runner
