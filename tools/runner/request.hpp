#pragma once
// run_request: the options of `rkpm_run CASE ...`, parsed and checked.

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rkpm::runner {

struct run_request {
  std::string case_name;
  std::string quadrature = "q2";
  std::string kernel = "cubic";
  std::string correction = "linear";
  std::string contact = "paper";
  int resolution = 1;
  std::optional<double> end_time;  // s; overrides the case's
  int threads = 0;                 // 0: OpenMP's default
  std::string out_dir;             // default results/CASE-QUADRATURE
  bool plots = true;
  bool help = false;
  bool quiet = false;              // no progress line
  std::vector<std::pair<std::string, std::string>> sets;  // --set NAME=VALUE

  // The key of the dispatch table: "kernel-correction-quadrature-contact".
  std::string method_key() const { return kernel + "-" + correction + "-" + quadrature + "-" + contact; }
  std::string output_directory() const { return out_dir.empty() ? "results/" + case_name + "-" + quadrature : out_dir; }
};

// Parses argv[first..]; throws rkpm::error with a one-line message on bad input.
run_request parse_run_request(int argc, char** argv, int first);

std::string usage();

}  // namespace rkpm::runner
