#include "paper.hpp"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <fmt/format.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include <rkpm/io/gnuplot.hpp>

#include "cases/taylor_bar.hpp"
#include "dispatch.hpp"

namespace rkpm::runner {
namespace {

struct paper_options {
  int resolution = 1;
  int threads = 0;
  std::string out = "results/paper";
  std::vector<std::string> cases{"taylor_bar", "block_forging", "wheel_forging"};
  bool plots = true;
};

paper_options parse(int argc, char** argv) {
  paper_options o;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) fail("{} needs a value", a);
      return argv[++i];
    };
    if (a == "--resolution") {
      o.resolution = std::stoi(value());
      if (o.resolution < 1) fail("--resolution must be >= 1");
    } else if (a == "--threads") {
      o.threads = std::stoi(value());
      if (o.threads < 1) fail("--threads must be >= 1");
    } else if (a == "--out") {
      o.out = value();
    } else if (a == "--cases") {
      o.cases.clear();
      std::string list = value(), item;
      for (std::size_t p = 0; p <= list.size(); ++p) {
        if (p == list.size() || list[p] == ',') {
          if (item != "taylor_bar" && item != "block_forging" && item != "wheel_forging")
            fail("--cases: unknown case '{}'", item);
          o.cases.push_back(item);
          item.clear();
        } else {
          item += list[p];
        }
      }
    } else if (a == "--no-plots") {
      o.plots = false;
    } else {
      fail("paper: unknown option '{}' (options: --resolution K --threads N --out DIR --cases a,b --no-plots)", a);
    }
  }
  return o;
}

double number(const io::json& s, const char* key) { return s.at(key).as_number(); }
double result(const io::json& s, const char* key) { return s.at("results").at(key).as_number(); }

}  // namespace

int run_paper(int argc, char** argv) {
  const paper_options o = parse(argc, argv);
#ifdef _OPENMP
  if (o.threads > 0) omp_set_num_threads(o.threads);
#endif
  const auto start = std::chrono::steady_clock::now();
  std::map<std::string, io::json> summary;  // "case-q2" -> summary
  for (const auto& c : o.cases)
    for (const char* q : {"q4", "q2"}) {
      run_request r;
      r.case_name = c;
      r.quadrature = q;
      r.resolution = o.resolution;
      r.plots = o.plots;
      r.out_dir = fmt::format("{}/{}-{}", o.out, c, q);
      fmt::print("paper: running {} with {} ...\n", c, q);
      std::fflush(stdout);
      run_outcome out = c == "taylor_bar" ? run_taylor_bar(r) : c == "block_forging" ? run_block_forging(r) : run_wheel_forging(r);
      fmt::print("paper: {} {} done, {} steps, {:.1f} s\n", c, q, number(out.summary, "steps"), number(out.summary, "wall_s"));
      summary[c + "-" + q] = out.summary;
    }
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::string md = "# rkpm: the paper's tables, reproduced\n\n";
  md += fmt::format("Written by `tools/rkpm paper` (resolution {}, {} thread(s)); the whole command took {:.0f} s.\n\n",
                    o.resolution, active_threads(), total);
  if (summary.count("taylor_bar-q4") && summary.count("taylor_bar-q2")) {
    const auto& s4 = summary["taylor_bar-q4"];
    const auto& s2 = summary["taylor_bar-q2"];
    md += "## Table 3: Taylor bar, final radius of the impact face and final height at 80 us\n\n";
    md += "| method | radius (mm) | height (mm) | energy balance error |\n|---|---|---|---|\n";
    md += fmt::format("| rkpm Q2 | {:.2f} | {:.2f} | {:.2e} |\n", result(s2, "final_radius_mm"), result(s2, "final_height_mm"),
                      s2.at("energy").at("balance_error").as_number());
    md += fmt::format("| rkpm Q4 | {:.2f} | {:.2f} | {:.2e} |\n", result(s4, "final_radius_mm"), result(s4, "final_height_mm"),
                      s4.at("energy").at("balance_error").as_number());
    md += fmt::format("| paper RKPM Q2 | {:.2f} | {:.2f} | |\n", cases::taylor_bar::paper_radius_q2_mm, cases::taylor_bar::paper_height_q2_mm);
    md += fmt::format("| paper RKPM Q4 | {:.2f} | {:.2f} | |\n", cases::taylor_bar::paper_radius_q4_mm, cases::taylor_bar::paper_height_q4_mm);
    md += "| paper LS-DYNA (FEM) | 7.06 | 21.52 | |\n\n";
    md += "![Taylor bar Q4](taylor_bar-q4/fig4_shape.png) ![Taylor bar Q2](taylor_bar-q2/fig4_shape.png)\n\n";
    md += "![radius](taylor_bar-q4/fig5_radius.png) ![height](taylor_bar-q4/fig6_height.png)\n\n";
  }
  md += "## Table 5: time-stepping CPU time, Q2 against Q4 (same build, same run of this command)\n\n";
  md += "| case | Q4 steps | Q4 loop (s) | Q2 steps | Q2 loop (s) | Q2 / Q4 | reduction | paper's reduction |\n|---|---|---|---|---|---|---|---|\n";
  const std::map<std::string, std::string> paper_reduction{
      {"taylor_bar", "47.98%"}, {"block_forging", "46.89%"}, {"wheel_forging", "47.91%"}};
  for (const auto& c : o.cases) {
    const auto& s4 = summary[c + "-q4"];
    const auto& s2 = summary[c + "-q2"];
    const double ratio = number(s2, "wall_s") / number(s4, "wall_s");
    md += fmt::format("| {} | {} | {:.2f} | {} | {:.2f} | {:.3f} | {:.1f}% | {} |\n", c, number(s4, "steps"),
                      number(s4, "wall_s"), number(s2, "steps"), number(s2, "wall_s"), ratio, 100.0 * (1.0 - ratio),
                      paper_reduction.at(c));
  }
  md += "\n## Other results\n\n| case | quadrature | key results |\n|---|---|---|\n";
  for (const auto& [key, s] : summary) {
    std::string res;
    for (const auto& [k, v] : s.at("results").members()) res += fmt::format("{} = {:.4g}; ", k, v.as_number());
    md += fmt::format("| {} | {} | {} |\n", s.at("case").as_string(), s.at("quadrature").as_string(), res);
  }
  if (summary.count("block_forging-q4"))
    md += "\n![block forging shapes](block_forging-q4/shapes.png) ![tool force](block_forging-q4/tool_force.png)\n";
  if (summary.count("wheel_forging-q4"))
    md += "\n![wheel Q4](wheel_forging-q4/shape.png) ![wheel Q2](wheel_forging-q2/shape.png)\n";
  std::filesystem::create_directories(o.out);
  std::ofstream(std::filesystem::path(o.out) / "report.md") << md;
  fmt::print("{}\nreport: {}/report.md\n", md, o.out);
  return 0;
}

}  // namespace rkpm::runner
