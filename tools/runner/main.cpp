// rkpm_run: runs one of the paper's cases with the policies chosen on the command line, or
// the whole paper (`rkpm_run paper`). See `rkpm_run --help`.
#include <cstdio>
#include <string>

#include <fmt/format.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include <rkpm/core/error.hpp>

#include "dispatch.hpp"
#include "paper.hpp"

int main(int argc, char** argv) {
  using namespace rkpm::runner;
  try {
    if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
      fmt::print("{}", usage());
      return argc < 2 ? 2 : 0;
    }
    if (std::string(argv[1]) == "paper") return run_paper(argc, argv);
    const run_request r = parse_run_request(argc, argv, 1);
#ifdef _OPENMP
    if (r.threads > 0) omp_set_num_threads(r.threads);
#endif
    run_outcome out;
    if (r.case_name == "taylor_bar") out = run_taylor_bar(r);
    if (r.case_name == "block_forging") out = run_block_forging(r);
    if (r.case_name == "wheel_forging") out = run_wheel_forging(r);
    if (r.help) return 0;
    const auto& s = out.summary;
    fmt::print("{} ({}-{}-{}-{}): {} steps in {:.2f} s (set-up {:.2f} s), energy balance error {:.2e}\n",
               r.case_name, r.kernel, r.correction, r.quadrature, r.contact, s.at("steps").as_number(),
               s.at("wall_s").as_number(), s.at("setup_s").as_number(),
               s.at("energy").at("balance_error").as_number());
    for (const auto& [k, v] : s.at("results").members()) fmt::print("  {:<34} {:.6g}\n", k, v.as_number());
    fmt::print("results in {}\n", out.directory);
    return 0;
  } catch (const std::exception& e) {
    fmt::print(stderr, "rkpm_run: {}\n", e.what());
    return 1;
  }
}
