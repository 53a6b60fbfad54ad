#pragma once
// The PNG figures of each case (gnuplot), from CSV files the run writes:
//   taylor_bar     fig4_shape.png (final deformed section), fig5_radius.png, fig6_height.png
//                  (the paper's figures 4, 5 and 6)
//   block_forging  shapes.png (0, 40 and 60% compression), tool_force.png (force vs stroke)
//   wheel_forging  shape.png (final shape with punch and die), punch_force.png
// figure_recorder<Case>::observe writes shape_LABEL.csv when the run passes each shape time;
// plot() draws the figures after the run.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include <rkpm/io/csv.hpp>
#include <rkpm/io/gnuplot.hpp>

#include "cases/block_forging.hpp"
#include "cases/taylor_bar.hpp"
#include "cases/wheel_forging.hpp"

namespace rkpm::runner {

struct shape_time {
  std::string label;
  double time;
};

template <class Case>
std::vector<shape_time> shape_times(const typename Case::parameters& p) {
  if constexpr (std::is_same_v<Case, cases::block_forging>) {
    // Compression c reached when 2 v t = c H.
    auto at = [&](double c) { return c * p.height_m / (2.0 * p.tool_velocity_m_s); };
    std::vector<shape_time> out{{"0", 0.0}};
    for (double c : {0.2, 0.4, 0.6})
      if (at(c) <= Case::end_time(p) * (1.0 + 1e-9)) out.push_back({fmt::format("{:.0f}", c * 100), at(c)});
    return out;
  } else {
    return {{"initial", 0.0}, {"final", Case::end_time(p)}};
  }
}

template <class Case>
class figure_recorder {
 public:
  figure_recorder(std::filesystem::path dir, const typename Case::parameters& p)
      : dir_(std::move(dir)), params_(p), times_(shape_times<Case>(p)) {}

  template <class Solver>
  void observe(const Solver& s) {
    const bool last = s.time() >= s.options().end_time * (1.0 - 1e-12);
    while (next_ < times_.size() && (s.time() >= times_[next_].time * (1.0 - 1e-9) || last)) {
      write_shape(s, times_[next_].label);
      if (last && times_[next_].time > s.time() * (1.0 + 1e-9)) {
        ++next_;
        continue;
      }
      written_.push_back(times_[next_].label);
      ++next_;
    }
  }

  void plot() const {
    if constexpr (std::is_same_v<Case, cases::taylor_bar>) {
      shapes_png("fig4_shape.png", "Taylor bar: initial and final section (r, z)", {"initial", "final"}, "", true);
      history_png("fig5_radius.png", "Taylor bar: radius of the impact face", "time (us)", "1*1e6", "radius (mm)",
                  "final_radius_mm");
      history_png("fig6_height.png", "Taylor bar: height", "time (us)", "1*1e6", "height (mm)", "final_height_mm");
    } else if constexpr (std::is_same_v<Case, cases::block_forging>) {
      shapes_png("shapes.png", "block forging: section at 0, 20, 40 and 60% compression", written_, "", false,
                 "% compression");
      history_png("tool_force.png", "block forging: top tool force per metre", "stroke (mm)",
                  fmt::format("1*{}", 2.0 * params_.tool_velocity_m_s * 1e3), "force (MN/m)",
                  "final_tool_force_N_per_m", 1e-6);
    } else {
      shapes_png("shape.png", "wheel forging: final section with punch and die", {"final"}, tools_at_end(), true);
      history_png("punch_force.png", "wheel forging: punch force", "stroke (mm)",
                  fmt::format("1*{}", params_.tool_velocity_m_s * 1e3), "force (kN)", "final_punch_force_N", 1e-3);
    }
  }

 private:
  // The deformed background cells (their nodes are the particles in the paper's cases),
  // one closed outline per cell separated by blank lines, which gnuplot draws as a mesh.
  template <class Solver>
  void write_shape(const Solver& s, const std::string& label) const {
    const auto x = s.particle_positions();
    const auto& mesh = s.model().mesh;
    std::ofstream out(dir_ / ("shape_" + label + ".csv"));
    out << "x_mm,y_mm\n";
    if (mesh.node.size() != x.size()) {
      for (const vec2& p : x) out << fmt::format("{},{}\n", p[0] * 1e3, p[1] * 1e3);
      return;
    }
    for (const auto& c : mesh.cell) {
      for (int k = 0; k <= 4; ++k) out << fmt::format("{},{}\n", x[c[k % 4]][0] * 1e3, x[c[k % 4]][1] * 1e3);
      out << "\n";
    }
  }

  // Gnuplot commands that draw the punch and die of the wheel case at the end of the stroke.
  std::string tools_at_end() const {
    if constexpr (std::is_same_v<Case, cases::wheel_forging>) {
      std::string s;
      const vec2 shift(0.0, -params_.stroke_m);
      auto poly = [&](const std::vector<vec2>& pts, const vec2& d, const char* name) {
        s += fmt::format("${} << EOD\n", name);
        for (const vec2& p : pts) s += fmt::format("{},{}\n", (p[0] + d[0]) * 1e3, (p[1] + d[1]) * 1e3);  // comma: the plots read CSV
        s += "EOD\n";
      };
      poly(Case::punch_outline(), shift, "punch");
      poly(Case::die_outline(), vec2::Zero(), "die");
      return s;
    } else {
      return "";
    }
  }

  // One panel per shape (side by side when `columns`, else stacked), all on the same axes.
  void shapes_png(const std::string& png, const std::string& title, const std::vector<std::string>& labels,
                  const std::string& extra, bool columns, const std::string& unit_suffix = "") const {
    static constexpr const char* colors[] = {"dark-violet", "web-blue", "dark-orange", "forest-green", "gray40"};
    std::vector<std::string> panels;
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for (const auto& l : labels) {
      const auto file = dir_ / ("shape_" + l + ".csv");
      if (!std::filesystem::exists(file)) continue;
      std::ifstream in(file);
      std::string line;
      std::getline(in, line);
      double x, y;
      char comma;
      while (std::getline(in, line)) {
        std::stringstream ss(line);
        if (!(ss >> x >> comma >> y)) continue;
        lo[0] = std::min(lo[0], x), hi[0] = std::max(hi[0], x), lo[1] = std::min(lo[1], y), hi[1] = std::max(hi[1], y);
      }
      std::string plot = fmt::format("plot {} skip 1 using 1:2 with lines lw 0.8 lc rgb '{}' notitle",
                                     io::detail::gnuplot_quote(file.string()), colors[panels.size() % 5]);
      if (!extra.empty()) plot += ", $punch with lines lw 3 lc rgb 'black' notitle, $die with lines lw 3 lc rgb 'gray30' notitle";
      panels.push_back(fmt::format("set title {}\n{}\n", io::detail::gnuplot_quote(l + unit_suffix), plot));
    }
    if (panels.empty()) return;
    if constexpr (std::is_same_v<Case, cases::wheel_forging>) {  // show the die wall and the punch
      hi[0] = std::max(hi[0], 36.0);
      hi[1] = std::max(hi[1], (38e-3 - params_.stroke_m) * 1e3 + 4.0);
      lo[0] = std::min(lo[0], -1.0);
    }
    const double pad = 0.04 * std::max(hi[0] - lo[0], hi[1] - lo[1]);
    std::string script = extra + fmt::format(
        "set datafile separator ','\nset size ratio -1\nset xlabel 'r or x (mm)'\nset ylabel 'z or y (mm)'\nset grid\n"
        "set xrange [{}:{}]\nset yrange [{}:{}]\nset multiplot layout {},{} title {}\n",
        lo[0] - pad, hi[0] + pad, lo[1] - pad, hi[1] + pad, columns ? 1 : panels.size(), columns ? panels.size() : 1,
        io::detail::gnuplot_quote(title));
    for (const auto& p : panels) script += p;
    script += "unset multiplot\n";
    const int n = static_cast<int>(panels.size());
    const int width = n == 1 ? 900 : columns ? 450 * n : 900, height = n == 1 ? 700 : columns ? 900 : 330 * n;
    io::gnuplot_png(dir_ / png, script, {.width = width, .height = height});
  }

  void history_png(const std::string& png, const std::string& title, const std::string& xlabel,
                   const std::string& xscale, const std::string& ylabel, const std::string& column,
                   double yscale = 1.0) const {
    const auto file = (dir_ / "history.csv").string();
    const int index = column_index(file, column);
    if (index < 0) return;
    const std::string script = fmt::format(
        "set datafile separator ','\nset title {}\nset xlabel {}\nset ylabel {}\nset grid\nset key off\n"
        "plot {} skip 1 using ($1*{}):(${}*{}) with lines lw 2\n",
        io::detail::gnuplot_quote(title), io::detail::gnuplot_quote(xlabel), io::detail::gnuplot_quote(ylabel),
        io::detail::gnuplot_quote(file), xscale.substr(2), index, yscale);
    io::gnuplot_png(dir_ / png, script);
  }

  // 1-based column of `name` in the header of a CSV file, or -1.
  static int column_index(const std::string& file, const std::string& name) {
    std::ifstream in(file);
    std::string header;
    std::getline(in, header);
    std::stringstream ss(header);
    std::string cell;
    for (int i = 1; std::getline(ss, cell, ','); ++i)
      if (cell == name) return i;
    return -1;
  }

  std::filesystem::path dir_;
  typename Case::parameters params_;
  std::vector<shape_time> times_;
  std::vector<std::string> written_;
  std::size_t next_ = 0;
};

}  // namespace rkpm::runner
