#pragma once
// The command line of rkpm_run, parsed and checked by CLI11 (request.cpp):
//   rkpm_run CASE [options]     one case (the cases are listed once, in case_list.hpp)
//   rkpm_run paper [options]    all cases with Q2 and Q4, and the report (paper.cpp)

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include <rkpm/solver/mass_scaling.hpp>
#include <rkpm/solver/rereference.hpp>
#include <rkpm/io/vtu_encoding.hpp>

#include "methods.hpp"
#include "run_hooks.hpp"

namespace rkpm::runner {

struct run_request {
  std::string case_name;
  std::string case_file;  // rkpm_run FILE.json: the case file (case_name is then its "name")
  std::string quadrature{paper_quadrature::name};
  std::string kernel{paper_kernel::name};
  std::string correction{paper_correction::name};
  std::string contact{paper_enforcement::name};
  int resolution = 1;
  std::optional<double> end_time;  // s; overrides the case's
  int threads = 0;                 // 0: OpenMP's default (per process)
  int processes = 1;               // the processes mpiexec started (main.cpp), each stepping a part (ranks.hpp)
  int ranks = 0;                   // --ranks: the processes the command line expects (0: any)
  // Where this process runs among them (main.cpp), for the memory warning (memory_estimate.hpp):
  // the run's processes on its machine, its place there (0 speaks for the machine), and whether
  // rank 0 is on it.
  int processes_here = 1, machine_rank = 0;
  bool with_rank_0 = true;
  long max_steps = 50'000'000;     // run_options::max_steps: longer runs are refused before they start
  rereference_policy rereference;  // run_options::rereference (--rereference-stretch, --rereference-every)
  mass_scaling_policy mass_scaling;  // run_options::mass_scaling (--mass-scaling-factor, --mass-scaling-dt)
  std::string out_dir;             // default results/CASE-QUADRATURE
  bool plots = true;
  bool quiet = false;              // no progress line
  // The snapshots' compression: zlib (smallest, every reader), lz4 (fast; ParaView, not meshio), none.
  io::vtu_compression vtu_compression = io::default_vtu_compression;
  std::vector<std::pair<std::string, std::string>> sets;  // --set NAME=VALUE
  std::optional<double> checkpoint_interval;  // s of simulated time between checkpoints
  std::string restart;                        // checkpoint file or run folder to continue
  std::vector<std::string> given;             // the options given on the command line ("--kernel", ...)
  run_hooks hooks;                            // none from the command line (run_hooks.hpp)

  std::string output_directory() const { return out_dir.empty() ? "results/" + case_name + "-" + quadrature : out_dir; }
};

struct paper_request {
  int resolution = 1;
  int threads = 0;  // 0: OpenMP's default
  std::string out = "results/paper";
  std::vector<std::string> cases;  // empty: every case
  // Rules beyond the paper run beside Q2 and Q4 for the report's last section (methods.hpp).
  std::vector<std::string> rules = report_rule_names();
  bool plots = true;
};

struct command_line {
  enum class action { run, paper, exit };
  action what = action::exit;
  int exit_code = 0;  // for action::exit: help printed (0) or no arguments (2)
  run_request run;
  paper_request paper;
};

// For --restart: takes the policies and resolution from the checkpoint's description (run_record.hpp)
// and refuses, in one line, another case, a --set, or a policy or resolution option that differs
// from the checkpoint's.
void adopt_checkpoint_run(run_request& r, const nlohmann::ordered_json& description, std::string_view case_name);

// Parses argv. Prints the help itself (--help, or the usage when there are no arguments);
// throws rkpm::error with a one-line message on bad input, before anything runs.
command_line parse_command_line(int argc, char** argv);

}  // namespace rkpm::runner
