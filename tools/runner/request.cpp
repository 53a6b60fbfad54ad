// The command line of rkpm_run through CLI11: one subcommand per case (from case_list.hpp) and
// `paper`. Choices come from the policy lists (methods.hpp), ranges and numbers are checked by
// CLI11, `--set NAME=VALUE` by the case's own parameter list; every error is one line.
#include "request.hpp"

#include <charconv>
#include <cmath>
#include <algorithm>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <rkpm/core/error.hpp>

#include "case_list.hpp"

namespace rkpm::runner {
namespace {

// A positive, finite number of seconds.
const CLI::Validator positive_seconds(
    [](std::string& text) -> std::string {
      double t = 0.0;
      const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), t);
      if (ec != std::errc() || end != text.data() + text.size() || !(t > 0.0) || !std::isfinite(t))
        return fmt::format("must be a positive number of seconds, got '{}'", text);
      return {};
    },
    "> 0");

// NAME=VALUE where NAME is a parameter of Case and VALUE suits it.
template <class Case>
CLI::Validator parameter_setting() {
  return CLI::Validator(
      [](std::string& setting) -> std::string {
        const auto eq = setting.find('=');
        if (eq == std::string::npos || eq == 0) return fmt::format("expects NAME=VALUE, got '{}'", setting);
        typename Case::parameters p;
        try {
          cases::set_parameter(p, std::string_view(setting).substr(0, eq), std::string_view(setting).substr(eq + 1));
        } catch (const rkpm::error& e) {
          return e.what();
        }
        return {};
      },
      "NAME=VALUE");
}

// The options every run takes (a named case or a case file), bound to `r`.
void add_run_options(CLI::App* sub, run_request& r) {
  sub->add_option("--quadrature", r.quadrature, "background integration rule")
      ->check(CLI::IsMember(policy_names(quadratures)))
      ->capture_default_str();
  sub->add_option("--kernel", r.kernel, "kernel")->check(CLI::IsMember(policy_names(kernels)))->capture_default_str();
  sub->add_option("--correction", r.correction, "correction order")
      ->check(CLI::IsMember(policy_names(corrections)))
      ->capture_default_str();
  // The contact's enforcement only: the tools, friction and body pairs come from the case.
  // --contact is the name it had first.
  sub->add_option("--enforcement,--contact", r.contact,
                  "how contact forces are computed (the tools and friction come from the case)")
      ->check(CLI::IsMember(policy_names(enforcements)))
      ->capture_default_str();
  sub->add_option("--resolution", r.resolution,
                  "K times the particles per direction (K - 1 more per gap); a run that would need more memory "
                  "than the machine has available is warned about before it is built")
      ->check(CLI::Range(1, 32))
      ->capture_default_str();
  sub->add_option_function<std::string>(
         "--end-time", [&r](const std::string& t) { r.end_time = std::stod(t); },
         "simulated time (default: the case's; the wheel's stroke follows it)")
      ->type_name("SECONDS")
      ->check(positive_seconds);
  sub->add_option("--threads", r.threads, "OpenMP threads (default: all)")->check(CLI::Range(1, 1024));
  sub->add_option("--ranks", r.ranks,
                  "the processes to run on: tools/rkpm run starts them (mpiexec -np N); rkpm_run itself checks "
                  "that mpiexec started as many")
      ->check(CLI::Range(1, 1 << 20));
  sub->add_option("--max-steps", r.max_steps,
                  "refuse a run estimated to need more steps (a wrong constant, not a long run)")
      ->check(CLI::Range(1L, 1'000'000'000'000L))
      ->capture_default_str();
  sub->add_option("--rereference-stretch", r.rereference.max_stretch,
                  "rebuild the kernels in the current configuration when a point's principal stretch since the "
                  "last rebuild (or its inverse) exceeds this, e.g. 1.8 (docs/method.md section 5.8)")
      ->check(CLI::Range(1.0, 1e6));
  sub->add_option("--rereference-every", r.rereference.every_steps,
                  "rebuild the kernels in the current configuration every N steps (1: updated Lagrangian)")
      ->check(CLI::Range(index_t{1}, index_t{1'000'000'000}));
  sub->add_option("--rebalance-above", r.rereference.rebalance_above,
                  "on several processes, partition the particles again after a re-reference when the most loaded "
                  "process's work exceeds this multiple of the mean (default 1.1; the results are the same bits)")
      ->check(CLI::Range(1.0, 1e300));
  sub->add_option("--mass-scaling-factor", r.mass_scaling.factor,
                  "multiply every mass by this (>= 1) for a process slower than the waves: the step grows by its "
                  "square root (docs/method.md section 5.10); the summary reports the added mass")
      ->check(CLI::Range(1.0, 1e12));
  sub->add_option("--mass-scaling-dt", r.mass_scaling.target_time_step,
                  "scale every mass by the factor that makes the time step this (s)")
      ->check(CLI::Range(1e-15, 1.0));
  sub->add_option("--out", r.out_dir, "output directory (default results/CASE-QUADRATURE)");
  sub->add_option_function<std::string>(
         "--checkpoint-interval", [&r](const std::string& t) { r.checkpoint_interval = std::stod(t); },
         "write checkpoint_STEP.rkpmcp after the first step reaching each multiple of this simulated time, "
         "and at the end")
      ->type_name("SECONDS")
      ->check(positive_seconds);
  sub->add_option("--restart", r.restart,
                  "continue a checkpoint (a file, or a run folder's latest) to the end time, with the policies "
                  "and parameters it was started with; output appends to its folder unless --out is given")
      ->type_name("PATH");
  sub->add_flag_callback("--no-plots", [&r] { r.plots = false; }, "skip the gnuplot figures");
  sub->add_flag("--quiet", r.quiet, "no progress line");
  sub->add_option_function<std::string>(
         "--vtu-compression",
         [&r](const std::string& c) {
           r.vtu_compression = c == "lz4"    ? io::vtu_compression::lz4
                               : c == "none" ? io::vtu_compression::none
                                             : io::vtu_compression::zlib;
         },
         "compression of the VTK snapshots: zlib (the default: smallest; every VTK reader and meshio), lz4 (about 3 "
         "times as fast to write at 10^6 particles, a quarter larger; ParaView 5.5 and later, not meshio) or none")
      ->check(CLI::IsMember({"zlib", "lz4", "none"}));
}

// The options given on the command line, which a case file or a checkpoint must not override.
void record_given_options(const CLI::App* sub, run_request& r) {
  for (const char* name : {"--quadrature", "--kernel", "--correction", "--enforcement", "--resolution", "--set",
                           "--rereference-stretch", "--rereference-every", "--rebalance-above", "--mass-scaling-factor",
                           "--mass-scaling-dt"})
    if (sub->count(name) > 0) r.given.emplace_back(name);
}

// `rkpm_run CASE [options]`.
template <class Case>
void add_case(CLI::App& app, run_request& r, std::vector<std::string>& sets) {
  CLI::App* sub = app.add_subcommand(std::string(Case::name), std::string(Case::description));
  add_run_options(sub, r);
  sub->add_option("--set", sets, "override a case parameter, SI units (`CASE --help` lists them); repeatable")
      ->check(parameter_setting<Case>())
      ->allow_extra_args(false);
  sub->footer([] {
    return fmt::format("parameters of {} (--set NAME=VALUE; name, default, unit, meaning):\n{}", Case::name,
                       cases::describe_parameters(typename Case::parameters{}));
  });
  sub->callback([&r, sub] {
    r.case_name = sub->get_name();
    record_given_options(sub, r);
  });
}

// `rkpm_run FILE.json [options]` (the parser turns it into `rkpm_run file FILE.json`).
void add_case_file(CLI::App& app, run_request& r, std::vector<std::string>& sets) {
  CLI::App* sub = app.add_subcommand("file", "a problem from a JSON case file (rkpm_run FILE.json also works); "
                                             "tools/runner/case_file/README.md gives the schema");
  sub->add_option("path", r.case_file, "the case file, e.g. cases/taylor_bar.json")->required()->type_name("FILE.json");
  add_run_options(sub, r);
  sub->add_option("--set", sets,
                  "override a field of the file by its JSON pointer, e.g. /bodies/0/material/yield_stress_Pa=3e8 "
                  "(the value is JSON, or else text); repeatable")
      ->check(CLI::Validator(
          [](std::string& setting) -> std::string {
            if (!setting.starts_with("/") || setting.find('=') == std::string::npos)
              return fmt::format("expects /JSON/POINTER=VALUE, got '{}'", setting);
            return {};
          },
          "/POINTER=VALUE"))
      ->allow_extra_args(false);
  sub->footer("The policies default to the file's \"method\"; an option given here overrides it.");
  sub->callback([&r, sub] { record_given_options(sub, r); });
}

void add_paper(CLI::App& app, paper_request& p) {
  CLI::App* sub = app.add_subcommand("paper", "every case with Q2 and Q4, and a report beside the paper's tables");
  sub->add_option("--resolution", p.resolution, "K times the particles per direction")
      ->check(CLI::Range(1, 16))
      ->capture_default_str();
  sub->add_option("--threads", p.threads, "OpenMP threads (default: all)")->check(CLI::Range(1, 1024));
  sub->add_option("--out", p.out, "output directory")->capture_default_str();
  sub->add_option("--cases", p.cases, "comma-separated cases to run (default: all)")
      ->delimiter(',')
      ->check(CLI::IsMember(case_names()));
  sub->add_option_function<std::vector<std::string>>(
         "--rules",
         [&p](const std::vector<std::string>& rules) {
           p.rules = rules;
           std::erase(p.rules, "none");
         },
         fmt::format("integration rules beyond the paper for the report's last section, comma-separated, or none "
                     "(default {})",
                     fmt::join(report_rule_names(), ",")))
      ->delimiter(',')
      ->check(CLI::IsMember([] {
        auto names = policy_names(quadratures);
        names.emplace_back("none");
        return names;
      }()));
  sub->add_flag_callback("--no-plots", [&p] { p.plots = false; }, "skip the gnuplot figures");
}

}  // namespace

void adopt_checkpoint_run(run_request& r, const nlohmann::ordered_json& description, std::string_view case_name) {
  const std::string ran = description.at("case").get<std::string>();
  if (ran != case_name)
    fail("--restart {}: the checkpoint is of a {} run, not {}: rkpm_run {} --restart {}", r.restart, ran, case_name,
         ran, r.restart);
  auto adopt = [&](const char* option, std::string& value, const char* key) {
    const std::string theirs = description.at(key).get<std::string>();
    if (std::ranges::find(r.given, option) != r.given.end() && value != theirs)
      fail("{} {}: the checkpoint was run with {} {}, and a restart continues the same configuration (drop {})",
           option, value, option, theirs, option);
    value = theirs;
  };
  adopt("--kernel", r.kernel, "kernel");
  adopt("--correction", r.correction, "correction");
  adopt("--quadrature", r.quadrature, "quadrature");
  adopt("--enforcement", r.contact, "contact");
  const int resolution = description.at("resolution").get<int>();
  if (std::ranges::find(r.given, "--resolution") != r.given.end() && r.resolution != resolution)
    fail("--resolution {}: the checkpoint was run at resolution {}, and a restart continues the same problem "
         "(drop --resolution)",
         r.resolution, resolution);
  r.resolution = resolution;
  // The re-referencing the run had (none when the description names none).
  rereference_policy theirs;
  if (const auto k = description.find("rereference"); k != description.end()) {
    theirs.max_stretch = k->at("max_stretch").get<double>();
    theirs.every_steps = k->at("every_steps").get<index_t>();
  }
  const bool given = std::ranges::find(r.given, "--rereference-stretch") != r.given.end() ||
                     std::ranges::find(r.given, "--rereference-every") != r.given.end();
  if (given && (r.rereference.max_stretch != theirs.max_stretch || r.rereference.every_steps != theirs.every_steps))
    fail("--rereference-*: the checkpoint was run with other re-referencing, and a restart continues the same "
         "run (drop them)");
  theirs.rebalance_above = r.rereference.rebalance_above;  // the processes' balance, not the run's
  r.rereference = theirs;
  // The mass scaling the run had (none when the description names none).
  mass_scaling_policy scaled;
  if (const auto k = description.find("mass_scaling"); k != description.end()) {
    scaled.factor = k->at("factor").get<double>();
    scaled.target_time_step = k->at("target_dt_s").get<double>();
    scaled.max_kinetic_to_internal = k->at("max_kinetic_to_internal").get<double>();
  }
  const bool scaling_given = std::ranges::find(r.given, "--mass-scaling-factor") != r.given.end() ||
                             std::ranges::find(r.given, "--mass-scaling-dt") != r.given.end();
  if (scaling_given &&
      (r.mass_scaling.factor != scaled.factor || r.mass_scaling.target_time_step != scaled.target_time_step))
    fail("--mass-scaling-*: the checkpoint was run with other mass scaling, and a restart continues the same run "
         "(drop them)");
  r.mass_scaling = scaled;
  if (!r.sets.empty())
    fail("--set {}={}: a restart continues the checkpoint's problem with the parameters it was started with "
         "(only --end-time may change)",
         r.sets.front().first, r.sets.front().second);
}

command_line parse_command_line(int argc, char** argv) {
  command_line cl;
  std::vector<std::string> sets;
  CLI::App app("rkpm_run: the paper's cases with the policies chosen on the command line", "rkpm_run");
  app.require_subcommand(1);
  hana::for_each(case_types, [&](auto t) { add_case<typename decltype(t)::type>(app, cl.run, sets); });
  add_case_file(app, cl.run, sets);
  add_paper(app, cl.paper);
  // The options every case takes, also in the top-level help.
  const CLI::App* first_case = app.get_subcommand(std::string(decltype(+hana::front(case_types))::type::name));
  app.footer([first_case] {
    return "options of every CASE (`rkpm_run CASE --help` adds the case's parameters):\n" +
           CLI::Formatter().make_groups(first_case, CLI::AppFormatMode::Sub);
  });

  if (argc < 2) {
    fmt::print("{}", app.help());
    cl.exit_code = 2;
    return cl;
  }
  // `rkpm_run FILE.json ...` is `rkpm_run file FILE.json ...`.
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.front().ends_with(".json")) args.insert(args.begin(), "file");
  std::reverse(args.begin(), args.end());  // CLI11 takes the arguments last first
  try {
    app.parse(args);
  } catch (const CLI::CallForHelp&) {
    fmt::print("{}", app.help());  // the chosen subcommand's help, if one was given
    return cl;
  } catch (const CLI::ParseError& e) {
    if (app.get_subcommands().empty() && !app.remaining().empty()) {
      const std::string first = app.remaining().front();
      if (first.starts_with("-"))
        fail("give the case first: rkpm_run CASE [options], where CASE is {} or paper", fmt::join(case_names(), ", "));
      fail("unknown case '{}'; the cases are {} (or paper for all of them)", first, fmt::join(case_names(), ", "));
    }
    std::string message = e.what();
    for (char& c : message)
      if (c == '\n') c = ' ';
    fail("{} (see --help)", message);
  }
  if (app.got_subcommand("paper")) {
    cl.what = command_line::action::paper;
    return cl;
  }
  cl.what = command_line::action::run;
  for (const auto& s : sets) {
    const auto eq = s.find('=');
    cl.run.sets.emplace_back(s.substr(0, eq), s.substr(eq + 1));
  }
  return cl;
}

}  // namespace rkpm::runner
