#pragma once
// What one run hands back to the command line and to `rkpm_run paper`.

#include <string>

#include "json.hpp"

namespace rkpm::runner {

struct run_outcome {
  bool completed = false;
  std::string directory;
  json summary;  // the content of summary.json
};

}  // namespace rkpm::runner
