#pragma once
// A PNG of one per-particle field on the deformed body (docs/method.md section 9.4), drawn by
// gnuplot (io/gnuplot.hpp): every quad cell of a snapshot (io/vtu_cells.hpp) filled with the
// mean of the field at its four nodes, particles that are vertex cells as dots of their value,
// a colour bar, and the tools as thick lines. tools/view/rkpm_view.py draws a written snapshot
// with the same gnuplot commands (field_figure_preamble below).
//
//   io::field_png("final_plastic_strain.png", x, cells, eps_p, tools,
//                 {.title = "taylor_bar at 80 us", .label = "equivalent plastic strain"});

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iterator>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/io/gnuplot.hpp>
#include <rkpm/io/vtu_cells.hpp>

namespace rkpm::io {

struct field_figure_options {
  std::string title;
  std::string label;    // the colour bar's
  double scale = 1e3;   // positions are drawn in mm
  int width = 900, height = 800;
};

// The gnuplot set-up shared with tools/view/rkpm_view.py: text as written (no _ subscripts), equal axes, a viridis-like palette,
// cells filled without borders (a fine mesh would be black with them).
inline std::string field_figure_preamble(const std::string& title, const std::string& label) {
  return fmt::format(
      "set termoption noenhanced\nset title {}\nset size ratio -1\nset xlabel 'r or x (mm)'\nset ylabel 'z or y (mm)'\nset cblabel {}\n"
      "set palette defined (0 '#440154', 0.25 '#3b528b', 0.5 '#21908d', 0.75 '#5dc963', 1 '#fde725')\n"
      "set style fill solid 1.0 noborder\nset key off\nset clip two\n",
      gnuplot_quote(title), gnuplot_quote(label));
}

// points  #points positions (m); cells on them (vtu_cells, or a cell_layout, which holds no
// arrays: io/vtu_cells.hpp); values  #points; tools  polylines (m).
// The cells go to gnuplot as text one polygon at a time, never held as rows: at 10^6 cells the
// rows would take 140 MB, a tenth of the solver's footprint.
template <class Cells>
void field_png(const std::filesystem::path& png, const std::vector<vec2>& points, const Cells& cells,
               const std::vector<double>& values, const std::vector<std::vector<vec2>>& tools,
               const field_figure_options& options) {
  if (values.size() != points.size())
    fail("field_png '{}': {} values for {} points", png.string(), values.size(), points.size());
  const auto begin_of = [&](std::size_t c) { return c == 0 ? std::int64_t{0} : cell_end(cells, c - 1); };
  // The axes: the cells' points with a margin; tools are clipped to it.
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  bool polygons = false, dots = false;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    (cell_type(cells, c) == vtk_vertex ? dots : polygons) = true;
    for (std::int64_t k = begin_of(c); k < cell_end(cells, c); ++k)
      for (int d = 0; d < 2; ++d) {
        const double x = points[cell_point(cells, k)][d] * options.scale;
        lo[d] = std::min(lo[d], x), hi[d] = std::max(hi[d], x);
      }
  }
  if (!polygons && !dots) fail("field_png '{}': no cells to draw", png.string());
  const double pad = 0.05 * std::max(hi[0] - lo[0], hi[1] - lo[1]);
  gnuplot_figure fig(png, {.width = options.width, .height = options.height});
  fig << field_figure_preamble(options.title, options.label)
      << fmt::format("set xrange [{}:{}]\nset yrange [{}:{}]\nplot ", lo[0] - pad, hi[0] + pad, lo[1] - pad,
                     hi[1] + pad);
  std::vector<std::string> plots;  // one '-' each, sent below in the same order
  if (polygons) plots.emplace_back("'-' using 1:2:3 with polygons fillcolor palette");
  if (dots) plots.emplace_back("'-' using 1:2:3 with points pt 7 ps 0.4 lc palette");
  for (std::size_t t = 0; t < tools.size(); ++t) plots.emplace_back("'-' using 1:2 with lines lw 3 lc rgb 'black'");
  fig << fmt::format("{}\n", fmt::join(plots, ", "));
  // Inline data: rows "x y value", a blank line after each polygon, "e" at the end of each '-'.
  std::string rows;
  const auto row = [&](std::int64_t p, double value) {
    fmt::format_to(std::back_inserter(rows), "{:.7g} {:.7g} {:.7g}\n", points[p][0] * options.scale,
                   points[p][1] * options.scale, value);
    if (rows.size() >= (std::size_t{1} << 16)) {
      fig << rows;
      rows.clear();
    }
  };
  if (polygons) {  // each filled with the mean of the field at its nodes
    for (std::size_t c = 0; c < cells.size(); ++c) {
      if (cell_type(cells, c) == vtk_vertex) continue;
      double mean = 0.0;
      for (std::int64_t k = begin_of(c); k < cell_end(cells, c); ++k) mean += values[cell_point(cells, k)];
      mean /= static_cast<double>(cell_end(cells, c) - begin_of(c));
      for (std::int64_t k = begin_of(c); k < cell_end(cells, c); ++k) row(cell_point(cells, k), mean);
      rows += "\n";
    }
    rows += "e\n";
  }
  if (dots) {
    for (std::size_t c = 0; c < cells.size(); ++c)
      if (cell_type(cells, c) == vtk_vertex) row(cell_point(cells, begin_of(c)), values[cell_point(cells, begin_of(c))]);
    rows += "e\n";
  }
  fig << rows;
  for (const auto& tool : tools) {
    std::vector<std::pair<double, double>> line;
    for (const vec2& v : tool) line.emplace_back(v[0] * options.scale, v[1] * options.scale);
    fig.send1d(line);
  }
  fig.render();
}

}  // namespace rkpm::io
