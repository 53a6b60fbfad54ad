#pragma once
// What one run hands back to the command line and to `rkpm_run paper`.

#include <string>

#include <rkpm/io/json.hpp>

namespace rkpm::runner {

struct run_outcome {
  bool completed = false;
  std::string directory;
  io::json summary;
};

}  // namespace rkpm::runner
