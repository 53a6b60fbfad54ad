#pragma once
// The PNG figures of each case, drawn by gnuplot from the run's own arrays (io/gnuplot.hpp):
//   taylor_bar     fig4_shape.png (initial and final section), fig5_radius.png, fig6_height.png
//                  (the paper's figures 4, 5 and 6)
//   block_forging  shapes.png (0, 20, 40 and 60% compression), tool_force.png (force vs stroke)
//   wheel_forging  shape.png (final shape with punch and die), punch_force.png
//   rod_on_rod     shape.png (initial and final sections), radius.png, height.png (both rods)
// figure_recorder<Case>::observe writes the deformed cells to shape_LABEL.csv when the run passes
// each shape time (for the user's own plots too) and keeps only their bounding box: plot() has
// gnuplot read the files after the run (a shape held in memory would cost 120 B per cell, as
// much as a tenth of the solver at 10^6 particles), and draws the history the run recorded.

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include <rkpm/core/error.hpp>
#include <rkpm/io/gnuplot.hpp>

#include "case_traits.hpp"
#include "history_table.hpp"

#include "cases/block_forging.hpp"
#include "cases/rod_on_rod.hpp"
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

  // Whether observe() at time t would record a shape (last: the run's end).
  bool due(double t, bool last) const { return next_ < times_.size() && (t >= times_[next_].time * (1.0 - 1e-9) || last); }

  // `x` and `mesh`: every particle's position and the whole mesh, when `s` is one process's
  // part of a run set up in parts (ranks.hpp), else null (the solver's own).
  template <class Solver>
  void observe(const Solver& s, const std::vector<vec2>* x = nullptr, const background_mesh* mesh = nullptr) {
    const bool last = s.time() >= s.options().end_time * (1.0 - 1e-12);
    while (due(s.time(), last)) {
      // A shape time beyond a run that stopped early is not drawn.
      if (!(last && times_[next_].time > s.time() * (1.0 + 1e-9))) {
        if (x && mesh)
          record_shape(s, *x, *mesh, times_[next_].label);
        else
          record_shape(s, s.particle_positions(), s.model().mesh, times_[next_].label);
      }
      ++next_;
    }
  }

  // Shape times passed so far (each drawn, or skipped when beyond a run that stopped early).
  std::size_t recorded() const { return next_; }

  // After a restart: the first `count` shapes, from the shape_LABEL.csv files of the folder
  // `from` the run wrote before (copied into this run's folder when it is another).
  void restore(const std::filesystem::path& from, std::size_t count) {
    namespace fs = std::filesystem;
    for (next_ = 0; next_ < count && next_ < times_.size(); ++next_) {
      const std::string file = "shape_" + times_[next_].label + ".csv";
      if (!fs::exists(from / file)) continue;
      if (fs::absolute(from) != fs::absolute(dir_))
        fs::copy_file(from / file, dir_ / file, fs::copy_options::overwrite_existing);
      shape sh{times_[next_].label, dir_ / file};
      std::ifstream in(sh.csv);
      std::string line;
      std::getline(in, line);  // header
      while (std::getline(in, line)) {
        if (line.empty()) {
          sh.cells = true;  // outlines are separated by blank lines
          continue;
        }
        const auto comma = line.find(',');
        sh.extend(std::stod(line.substr(0, comma)), std::stod(line.substr(comma + 1)));
      }
      shapes_.push_back(std::move(sh));
    }
  }

  void plot(const history_table& history) const {
    if constexpr (is_file_case<Case>) {  // the shapes with the tools, and the file's histories over time
      shapes_png("shape.png", params_.name + ": initial and final section", "", true);
      for (const auto& h : params_.histories)
        history_png("history_" + h.name + ".png", params_.name + ": " + h.name, "time (us)", h.name,
                    history.series("time_s", 1e6, h.name, 1.0));
    } else if constexpr (std::is_same_v<Case, cases::taylor_bar>) {
      shapes_png("fig4_shape.png", "Taylor bar: initial and final section (r, z)", "", true);
      history_png("fig5_radius.png", "Taylor bar: radius of the impact face", "time (us)", "radius (mm)",
                  history.series("time_s", 1e6, "radius_mm", 1.0));
      history_png("fig6_height.png", "Taylor bar: height", "time (us)", "height (mm)",
                  history.series("time_s", 1e6, "height_mm", 1.0));
    } else if constexpr (std::is_same_v<Case, cases::block_forging>) {
      shapes_png("shapes.png", "block forging: section at 0, 20, 40 and 60% compression", "% compression", false);
      history_png("tool_force.png", "block forging: top tool force per metre", "stroke (mm)", "force (MN/m)",
                  history.series("time_s", 2.0 * params_.tool_velocity_m_s * 1e3, "tool_force_N_per_m", 1e-6));
    } else if constexpr (std::is_same_v<Case, cases::rod_on_rod>) {
      shapes_png("shape.png", "rod on rod: initial and final sections of both rods (r, z)", "", true);
      history_png("radius.png", "rod on rod: radius of each rod's impact face", "time (us)", "radius (mm)",
                  {{"lower rod", history.series("time_s", 1e6, "lower_final_radius_mm", 1.0)},
                   {"upper rod", history.series("time_s", 1e6, "upper_final_radius_mm", 1.0)}});
      history_png("height.png", "rod on rod: height of each rod", "time (us)", "height (mm)",
                  {{"lower rod", history.series("time_s", 1e6, "lower_final_height_mm", 1.0)},
                   {"upper rod", history.series("time_s", 1e6, "upper_final_height_mm", 1.0)}});
    } else {
      shapes_png("shape.png", "wheel forging: final section with punch and die", "", true);
      history_png("punch_force.png", "wheel forging: punch force", "stroke (mm)", "force (kN)",
                  history.series("time_s", params_.tool_velocity_m_s * 1e3, "punch_force_N", 1e-3));
    }
  }

 private:
  using polyline = std::vector<std::pair<double, double>>;  // (x, y) in mm

  struct shape {
    std::string label;
    std::filesystem::path csv;    // shape_LABEL.csv, x_mm,y_mm: what gnuplot draws
    bool cells = false;           // closed outlines of the cells (blank-line separated), else particles
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};  // bounding box in mm
    std::vector<polyline> tools;  // case files: the tools at the shape's time

    void extend(double x, double y) {
      lo[0] = std::min(lo[0], x), hi[0] = std::max(hi[0], x);
      lo[1] = std::min(lo[1], y), hi[1] = std::max(hi[1], y);
    }
  };

  // shape_LABEL.csv: x_mm,y_mm, the deformed background cells (their nodes are the particles in
  // the paper's cases) as one closed outline per cell followed by a blank line, else the particles.
  template <class Solver>
  void record_shape(const Solver& s, const std::vector<vec2>& x, const background_mesh& mesh, const std::string& label) {
    shape sh{label, dir_ / ("shape_" + label + ".csv")};
    sh.cells = mesh.node.size() == x.size();
    std::ofstream out(sh.csv);
    out << "x_mm,y_mm\n";
    const auto row = [&](const vec2& p) {
      sh.extend(p[0] * 1e3, p[1] * 1e3);
      out << fmt::format("{},{}\n", p[0] * 1e3, p[1] * 1e3);
    };
    if (!sh.cells) {
      for (const vec2& p : x) row(p);
    } else {
      for (const auto& c : mesh.cell) {
        for (int k = 0; k <= 4; ++k) row(x[c[k % 4]]);
        out << "\n";
      }
    }
    if (!out) fail("could not write {}: check the disk space and permissions of the output folder", sh.csv.string());
    if constexpr (is_file_case<Case>)
      for (const auto& tool : s.contact().tools()) {
        polyline line;
        for (const vec2& v : tool.vertices(s.time())) line.emplace_back(v[0] * 1e3, v[1] * 1e3);
        sh.tools.push_back(std::move(line));
      }
    shapes_.push_back(std::move(sh));
  }

  // The wheel case's punch (at the end of the stroke) and die, in mm.
  static std::vector<polyline> tools_at_end(const typename Case::parameters& p) {
    if constexpr (std::is_same_v<Case, cases::wheel_forging>) {
      auto mm = [](const std::vector<vec2>& pts, const vec2& d) {
        polyline out;
        for (const vec2& q : pts) out.emplace_back((q[0] + d[0]) * 1e3, (q[1] + d[1]) * 1e3);
        return out;
      };
      return {mm(Case::punch_outline(), vec2(0.0, -p.stroke_m)), mm(Case::die_outline(), vec2::Zero())};
    } else {
      return {};
    }
  }

  // One panel per recorded shape (side by side when `columns`, else stacked), all on the same
  // axes; the wheel's panels also show the tools.
  void shapes_png(const std::string& png, const std::string& title, const std::string& unit_suffix,
                  bool columns) const {
    static constexpr const char* colors[] = {"dark-violet", "web-blue", "dark-orange", "forest-green", "gray40"};
    if (shapes_.empty()) return;
    const auto end_tools = tools_at_end(params_);
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for (const auto& sh : shapes_)
      for (int d = 0; d < 2; ++d) lo[d] = std::min(lo[d], sh.lo[d]), hi[d] = std::max(hi[d], sh.hi[d]);
    if constexpr (std::is_same_v<Case, cases::wheel_forging>) {  // show the die wall and the punch
      hi[0] = std::max(hi[0], 36.0);
      hi[1] = std::max(hi[1], (38e-3 - params_.stroke_m) * 1e3 + 4.0);
      lo[0] = std::min(lo[0], -1.0);
    }
    const double pad = 0.04 * std::max(hi[0] - lo[0], hi[1] - lo[1]);
    const int n = static_cast<int>(shapes_.size());
    const int width = n == 1 ? 900 : columns ? 450 * n : 900, height = n == 1 ? 700 : columns ? 900 : 330 * n;
    io::gnuplot_figure fig(dir_ / png, {.width = width, .height = height});
    // clip two: a tool segment with both ends outside the axes (a long wall) is still drawn.
    fig << fmt::format("set size ratio -1\nset clip two\nset xlabel 'r or x (mm)'\nset ylabel 'z or y (mm)'\nset grid\n"
                       "set xrange [{}:{}]\nset yrange [{}:{}]\nset multiplot layout {},{} title {}\n",
                       lo[0] - pad, hi[0] + pad, lo[1] - pad, hi[1] + pad, columns ? 1 : n, columns ? n : 1,
                       io::gnuplot_quote(title));
    for (std::size_t k = 0; k < shapes_.size(); ++k) {
      const shape& sh = shapes_[k];
      const auto& tools = sh.tools.empty() ? end_tools : sh.tools;
      fig << fmt::format("set title {}\nplot {} skip 1 using 1:2 '%lf,%lf' with {} lc rgb '{}' notitle",
                         io::gnuplot_quote(sh.label + unit_suffix), io::gnuplot_quote(sh.csv.string()),
                         sh.cells ? "lines lw 0.8" : "points pt 7 ps 0.3", colors[k % 5]);
      for (std::size_t t = 0; t < tools.size(); ++t)
        fig << fmt::format(", '-' using 1:2 with lines lw 3 lc rgb '{}' notitle", t == 0 ? "black" : "gray30");
      fig << "\n";
      for (const auto& tool : tools) fig.send1d(tool);
    }
    fig << "unset multiplot\n";
    fig.render();
  }

  using series_type = std::vector<std::pair<double, double>>;
  void history_png(const std::string& png, const std::string& title, const std::string& xlabel,
                   const std::string& ylabel, const series_type& series) const {
    history_png(png, title, xlabel, ylabel, std::vector<std::pair<std::string, series_type>>{{"", series}});
  }
  // Several labelled curves on one plot (a key when they have labels).
  void history_png(const std::string& png, const std::string& title, const std::string& xlabel,
                   const std::string& ylabel, const std::vector<std::pair<std::string, series_type>>& curves) const {
    if (curves.empty() || curves.front().second.empty()) return;
    io::gnuplot_figure fig(dir_ / png);
    fig << fmt::format("set title {}\nset xlabel {}\nset ylabel {}\nset grid\nset key {}\nplot ",
                       io::gnuplot_quote(title), io::gnuplot_quote(xlabel), io::gnuplot_quote(ylabel),
                       curves.front().first.empty() ? "off" : "top right");
    for (std::size_t k = 0; k < curves.size(); ++k)
      fig << fmt::format("{}'-' using 1:2 with lines lw 2 title {}", k ? ", " : "",
                         io::gnuplot_quote(curves[k].first));
    fig << "\n";
    for (const auto& [label, series] : curves) fig.send1d(series);
    fig.render();
  }

  std::filesystem::path dir_;
  typename Case::parameters params_;
  std::vector<shape_time> times_;
  std::vector<shape> shapes_;
  std::size_t next_ = 0;
};

}  // namespace rkpm::runner
