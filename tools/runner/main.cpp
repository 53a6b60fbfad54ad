// rkpm_run: runs one of the paper's cases with the policies chosen on the command line, or
// the whole paper (`rkpm_run paper`). See `rkpm_run --help`.
#include <cstdio>
#include <string>

#include <fmt/format.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include <rkpm/core/error.hpp>

#include "case_list.hpp"
#include "interrupt.hpp"
#include "paper.hpp"
#include "run_case_file.hpp"
#include "request.hpp"

int main(int argc, char** argv) {
  using namespace rkpm::runner;
  try {
    const command_line cl = parse_command_line(argc, argv);
    if (cl.what == command_line::action::exit) return cl.exit_code;
    if (cl.what == command_line::action::paper) return run_paper(cl.paper);
    const run_request& r = cl.run;
#ifdef _OPENMP
    if (r.threads > 0) omp_set_num_threads(r.threads);
#endif
    stop_between_steps_on_interrupt();
    const run_outcome out = r.case_file.empty() ? run_named_case(r) : run_case_file(r);
    const auto& s = out.summary;
    fmt::print("{} ({}-{}-{}-{}): {} steps in {:.2f} s (set-up {:.2f} s), energy balance error {:.2e}\n",
               s.at("case").get<std::string>(), s.at("kernel").get<std::string>(),
               s.at("correction").get<std::string>(), s.at("quadrature").get<std::string>(),
               s.at("contact").get<std::string>(), s.at("steps").get<long>(), s.at("wall_s").get<double>(),
               s.at("setup_s").get<double>(), s.at("energy").at("balance_error").get<double>());
    for (const auto& [k, v] : s.at("results").items()) fmt::print("  {:<34} {:.6g}\n", k, v.get<double>());
    fmt::print("results in {}\n", out.directory);
    return 0;
  } catch (const std::exception& e) {
    fmt::print(stderr, "rkpm_run: {}\n", e.what());
    return 1;
  }
}
