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

#include "case_list.hpp"
#include "simulate.hpp"  // active_threads

namespace rkpm::runner {
namespace {

double number(const json& s, const char* key) { return s.at(key).get<double>(); }
long count(const json& s, const char* key) { return s.at(key).get<long>(); }
double result(const json& s, const char* key) { return s.at("results").at(key).get<double>(); }

// Beyond the paper: two rods head on against the Taylor bar with the same rule (docs/method.md
// section 6.9). By symmetry each rod is a Taylor bar on a frictionless wall.
std::string rod_on_rod_section(const std::map<std::string, json>& summary) {
  std::string md;
  for (const std::string q : {"q2", "q4"}) {
    const auto rods = summary.find("rod_on_rod-" + q), bar = summary.find("taylor_bar-" + q);
    if (rods == summary.end() || bar == summary.end()) continue;
    if (md.empty())
      md = "\n## Beyond the paper: two deformable bodies in contact (`rod_on_rod`)\n\n"
           "Two copper rods with the Taylor bar's data meet head on, each at the Taylor bar's speed; the upper "
           "rod's particles are slaves against the lower rod's surface (docs/method.md section 6.9). By symmetry "
           "each rod is a Taylor bar on a frictionless rigid wall: the differences below are the method's, "
           "resolution and rule alike.\n\n"
           "| rule | rod | length (mm) | radius (mm) | Taylor bar length, radius (mm) | difference | momentum error |\n"
           "|---|---|---|---|---|---|---|\n";
    // The rod's extent in z against the bar's (its length, not its height above the wall).
    const double H = result(bar->second, "length_mm"), R = result(bar->second, "radius_mm");
    for (const std::string rod : {"lower", "upper"}) {
      const double h = result(rods->second, (rod + "_final_height_mm").c_str());
      const double r = result(rods->second, (rod + "_final_radius_mm").c_str());
      md += fmt::format("| {} | {} | {:.3f} | {:.3f} | {:.3f}, {:.3f} | {:+.2f}%, {:+.2f}% | {:.1e} |\n", q, rod, h, r, H,
                        R, 100.0 * (h / H - 1.0), 100.0 * (r / R - 1.0), result(rods->second, "momentum_error"));
    }
  }
  if (summary.count("rod_on_rod-q2"))
    md += "\n![rods](rod_on_rod-q2/shape.png) ![radius](rod_on_rod-q2/radius.png) ![height](rod_on_rod-q2/height.png)\n";
  return md;
}

}  // namespace

int run_paper(const paper_request& o) {
  const std::vector<std::string> chosen = o.cases.empty() ? case_names() : o.cases;
#ifdef _OPENMP
  if (o.threads > 0) omp_set_num_threads(o.threads);
#endif
  const auto start = std::chrono::steady_clock::now();
  std::map<std::string, json> summary;  // "case-q2" -> summary
  auto run = [&](const std::string& c, const std::string& q, std::string_view label) {
    run_request r;
    r.case_name = c;
    r.quadrature = q;
    r.resolution = o.resolution;
    r.plots = o.plots;
    r.out_dir = fmt::format("{}/{}-{}", o.out, c, q);
    fmt::print("paper: running {} with {}{} ...\n", c, q, label);
    std::fflush(stdout);
    run_outcome out = run_named_case(r);
    fmt::print("paper: {} {} done, {} steps, {:.1f} s\n", c, q, count(out.summary, "steps"), number(out.summary, "wall_s"));
    summary[fmt::format("{}-{}", c, q)] = std::move(out.summary);
  };
  for (const auto& c : chosen)
    for (const std::string_view q : {quadrature::q4::name, quadrature::q2::name}) run(c, std::string(q), "");
  // Beyond the paper: the same cases with the other integration rules (docs/method.md section 3).
  for (const auto& c : chosen)
    for (const auto& q : o.rules) run(c, q, " (beyond the paper)");
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::string md = "# rkpm: the paper's tables, reproduced\n\n";
  md += fmt::format("Written by `tools/rkpm paper` (resolution {}, {} thread(s)); the whole command took {:.0f} s.\n\n",
                    o.resolution, active_threads(), total);
  if (summary.count("taylor_bar-q4") && summary.count("taylor_bar-q2")) {
    const auto& s4 = summary["taylor_bar-q4"];
    const auto& s2 = summary["taylor_bar-q2"];
    md += "## Table 3: Taylor bar, final radius of the impact face and final height at 80 us\n\n";
    md += "The length is the height less the lowest point of the bar (above the wall once it lifts off).\n\n";
    md += "| method | radius (mm) | height (mm) | length (mm) | energy balance error |\n|---|---|---|---|---|\n";
    md += fmt::format("| rkpm Q2 | {:.2f} | {:.2f} | {:.2f} | {:.2e} |\n", result(s2, "radius_mm"), result(s2, "height_mm"),
                      result(s2, "length_mm"), s2.at("energy").at("balance_error").get<double>());
    md += fmt::format("| rkpm Q4 | {:.2f} | {:.2f} | {:.2f} | {:.2e} |\n", result(s4, "radius_mm"), result(s4, "height_mm"),
                      result(s4, "length_mm"), s4.at("energy").at("balance_error").get<double>());
    md += fmt::format("| paper RKPM Q2 | {:.2f} | {:.2f} | | |\n", cases::taylor_bar::paper_radius_q2_mm, cases::taylor_bar::paper_height_q2_mm);
    md += fmt::format("| paper RKPM Q4 | {:.2f} | {:.2f} | | |\n", cases::taylor_bar::paper_radius_q4_mm, cases::taylor_bar::paper_height_q4_mm);
    md += "| paper LS-DYNA (FEM) | 7.06 | 21.52 | | |\n\n";
    md += "![Taylor bar Q4](taylor_bar-q4/fig4_shape.png) ![Taylor bar Q2](taylor_bar-q2/fig4_shape.png)\n\n";
    md += "![radius](taylor_bar-q4/fig5_radius.png) ![height](taylor_bar-q4/fig6_height.png)\n\n";
  }
  md += "## Table 5: time-stepping CPU time, Q2 against Q4 (same build, same run of this command)\n\n";
  md += "| case | Q4 steps | Q4 loop (s) | Q2 steps | Q2 loop (s) | Q2 / Q4 | reduction | paper's reduction | Q2 / Q4 "
        "without output |\n|---|---|---|---|---|---|---|---|---|\n";
  const std::map<std::string, std::string> paper_reduction{
      {"taylor_bar", "47.98%"}, {"block_forging", "46.89%"}, {"wheel_forging", "47.91%"}};
  for (const auto& c : chosen) {
    if (!paper_reduction.contains(c)) continue;  // a case beyond the paper
    const auto& s4 = summary[c + "-q4"];
    const auto& s2 = summary[c + "-q2"];
    const double ratio = number(s2, "wall_s") / number(s4, "wall_s");
    // The steps alone: wall_s less the snapshots, history rows and figure shapes (output_s),
    // which cost the same per particle under both rules.
    const double steps_ratio =
        (number(s2, "wall_s") - number(s2, "output_s")) / (number(s4, "wall_s") - number(s4, "output_s"));
    md += fmt::format("| {} | {} | {:.2f} | {} | {:.2f} | {:.3f} | {:.1f}% | {} | {:.3f} |\n", c, count(s4, "steps"),
                      number(s4, "wall_s"), count(s2, "steps"), number(s2, "wall_s"), ratio, 100.0 * (1.0 - ratio),
                      paper_reduction.at(c), steps_ratio);
  }
  md += "\n## Other results\n\n| case | quadrature | key results |\n|---|---|---|\n";
  for (const auto& [key, s] : summary) {
    std::string res;
    for (const auto& [k, v] : s.at("results").items()) res += fmt::format("{} = {:.4g}; ", k, v.get<double>());
    md += fmt::format("| {} | {} | {} |\n", s.at("case").get<std::string>(), s.at("quadrature").get<std::string>(), res);
  }
  if (!o.rules.empty()) {
    md += "\n## Beyond the paper: other integration rules\n\n";
    md += "The paper's two readings of its two-point cell that rkpm does not use (`q2_split`, `q2_tri`), the "
          "variationally consistent rules (`+vci`) and stabilized conforming nodal integration (`scni`), beside Q2 "
          "and Q4, from the same run of this command "
          "(docs/method.md section 3). Time per step is relative to Q2's in this run.\n\n";
    for (const auto& c : chosen) {
      md += fmt::format("### {}\n\n| rule | key results | energy balance error | steps | loop (s) | time per step / Q2 |\n"
                        "|---|---|---|---|---|---|\n", c);
      const auto& s2 = summary[c + "-q2"];
      const double q2_per_step = number(s2, "wall_s") / static_cast<double>(count(s2, "steps"));
      std::vector<std::string> rules{"q2", "q4"};
      rules.insert(rules.end(), o.rules.begin(), o.rules.end());
      for (const auto& q : rules) {
        const auto& s = summary[c + "-" + q];
        std::string res;
        for (const auto& [k, v] : s.at("results").items()) res += fmt::format("{} = {:.4g}; ", k, v.get<double>());
        const double per_step = number(s, "wall_s") / static_cast<double>(count(s, "steps"));
        md += fmt::format("| {} | {} | {:.2e} | {} | {:.2f} | {:.2f} |\n", q, res,
                          s.at("energy").at("balance_error").get<double>(), count(s, "steps"), number(s, "wall_s"),
                          per_step / q2_per_step);
      }
      md += "\n";
    }
  }
  md += rod_on_rod_section(summary);
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
