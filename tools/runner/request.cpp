#include "request.hpp"

#include <charconv>
#include <cmath>
#include <string_view>

#include <rkpm/core/error.hpp>

namespace rkpm::runner {
namespace {

bool one_of(const std::string& v, std::initializer_list<std::string_view> allowed) {
  for (auto a : allowed)
    if (v == a) return true;
  return false;
}

template <class T>
T parse_number(std::string_view option, std::string_view text) {
  T value{};
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size())
    fail("{} expects a number, got '{}'", option, text);
  return value;
}

}  // namespace

std::string usage() {
  return "usage: rkpm_run CASE [options]      CASE: taylor_bar | block_forging | wheel_forging\n"
         "       rkpm_run paper [--resolution K] [--threads N] [--out DIR]\n"
         "options:\n"
         "  --quadrature q2|q4|q9          background integration rule (default q2)\n"
         "  --kernel cubic|quartic         kernel (default cubic)\n"
         "  --correction linear|quadratic  correction order (default linear)\n"
         "  --contact paper|effective_mass|penalty   contact enforcement (default paper)\n"
         "  --resolution K                 refine the particle grid K times per direction (default 1)\n"
         "  --end-time SECONDS             simulated time (default: the case's)\n"
         "  --threads N                    OpenMP threads (default: all)\n"
         "  --out DIR                      output directory (default results/CASE-QUADRATURE)\n"
         "  --set NAME=VALUE               override a case parameter (see CASE --help)\n"
         "  --no-plots                     skip the gnuplot figures\n"
         "  --quiet                        no progress line\n"
         "  --help                         this text, and with a CASE its parameters\n";
}

run_request parse_run_request(int argc, char** argv, int first) {
  run_request r;
  if (first >= argc) fail("no case given; {}", "the cases are taylor_bar, block_forging, wheel_forging");
  r.case_name = argv[first];
  if (r.case_name == "--help" || r.case_name == "-h") {
    r.help = true;
    r.case_name.clear();
    return r;
  }
  if (!one_of(r.case_name, {"taylor_bar", "block_forging", "wheel_forging"}))
    fail("unknown case '{}'; the cases are taylor_bar, block_forging, wheel_forging", r.case_name);
  for (int i = first + 1; i < argc; ++i) {
    const std::string opt = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) fail("{} needs a value", opt);
      return argv[++i];
    };
    if (opt == "--help" || opt == "-h") {
      r.help = true;
    } else if (opt == "--quadrature") {
      r.quadrature = value();
      if (!one_of(r.quadrature, {"q2", "q4", "q9"})) fail("--quadrature must be q2, q4 or q9, got '{}'", r.quadrature);
    } else if (opt == "--kernel") {
      r.kernel = value();
      if (!one_of(r.kernel, {"cubic", "quartic"})) fail("--kernel must be cubic or quartic, got '{}'", r.kernel);
    } else if (opt == "--correction") {
      r.correction = value();
      if (!one_of(r.correction, {"linear", "quadratic"}))
        fail("--correction must be linear or quadratic, got '{}'", r.correction);
    } else if (opt == "--contact") {
      r.contact = value();
      if (!one_of(r.contact, {"paper", "effective_mass", "penalty"}))
        fail("--contact must be paper, effective_mass or penalty, got '{}'", r.contact);
    } else if (opt == "--resolution") {
      r.resolution = parse_number<int>(opt, value());
      if (r.resolution < 1 || r.resolution > 16) fail("--resolution must be a whole number from 1 to 16, got {}", r.resolution);
    } else if (opt == "--end-time") {
      const double t = parse_number<double>(opt, value());
      if (!(t > 0.0) || !std::isfinite(t)) fail("--end-time must be positive (seconds), got {}", t);
      r.end_time = t;
    } else if (opt == "--threads") {
      r.threads = parse_number<int>(opt, value());
      if (r.threads < 1 || r.threads > 1024) fail("--threads must be at least 1, got {}", r.threads);
    } else if (opt == "--out") {
      r.out_dir = value();
    } else if (opt == "--set") {
      const std::string kv = value();
      const auto eq = kv.find('=');
      if (eq == std::string::npos || eq == 0) fail("--set expects NAME=VALUE, got '{}'", kv);
      r.sets.emplace_back(kv.substr(0, eq), kv.substr(eq + 1));
    } else if (opt == "--no-plots") {
      r.plots = false;
    } else if (opt == "--quiet") {
      r.quiet = true;
    } else {
      fail("unknown option '{}' (see --help)", opt);
    }
  }
  return r;
}

}  // namespace rkpm::runner
