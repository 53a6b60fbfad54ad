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
#include <limits>
#include <string>
#include <tuple>
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

// points  #points positions (m); cells on them; values  #points; tools  polylines (m).
inline void field_png(const std::filesystem::path& png, const std::vector<vec2>& points, const vtu_cells& cells,
                      const std::vector<double>& values, const std::vector<std::vector<vec2>>& tools,
                      const field_figure_options& options) {
  if (values.size() != points.size())
    fail("field_png '{}': {} values for {} points", png.string(), values.size(), points.size());
  using row = std::tuple<double, double, double>;
  std::vector<std::vector<row>> polygons;
  std::vector<row> dots;
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  auto at = [&](std::int64_t p, double value) {
    const double x = points[p][0] * options.scale, y = points[p][1] * options.scale;
    lo[0] = std::min(lo[0], x), hi[0] = std::max(hi[0], x), lo[1] = std::min(lo[1], y), hi[1] = std::max(hi[1], y);
    return row{x, y, value};
  };
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const std::int64_t end = cells.offsets[c], begin = c == 0 ? 0 : cells.offsets[c - 1];
    if (cells.types[c] == vtk_vertex) {
      dots.push_back(at(cells.connectivity[begin], values[cells.connectivity[begin]]));
      continue;
    }
    double mean = 0.0;
    for (std::int64_t k = begin; k < end; ++k) mean += values[cells.connectivity[k]];
    mean /= static_cast<double>(end - begin);
    std::vector<row> polygon;
    for (std::int64_t k = begin; k < end; ++k) polygon.push_back(at(cells.connectivity[k], mean));
    polygons.push_back(std::move(polygon));
  }
  if (polygons.empty() && dots.empty()) fail("field_png '{}': no cells to draw", png.string());
  // The axes: the body with a margin; tools are clipped to it.
  const double pad = 0.05 * std::max(hi[0] - lo[0], hi[1] - lo[1]);
  gnuplot_figure fig(png, {.width = options.width, .height = options.height});
  fig << field_figure_preamble(options.title, options.label)
      << fmt::format("set xrange [{}:{}]\nset yrange [{}:{}]\nplot ", lo[0] - pad, hi[0] + pad, lo[1] - pad,
                     hi[1] + pad);
  std::vector<std::string> plots;  // one '-' each, sent below in the same order
  if (!polygons.empty()) plots.emplace_back("'-' using 1:2:3 with polygons fillcolor palette");
  if (!dots.empty()) plots.emplace_back("'-' using 1:2:3 with points pt 7 ps 0.4 lc palette");
  for (std::size_t t = 0; t < tools.size(); ++t) plots.emplace_back("'-' using 1:2 with lines lw 3 lc rgb 'black'");
  fig << fmt::format("{}\n", fmt::join(plots, ", "));
  if (!polygons.empty()) fig.send2d(polygons);
  if (!dots.empty()) fig.send1d(dots);
  for (const auto& tool : tools) {
    std::vector<std::pair<double, double>> line;
    for (const vec2& v : tool) line.emplace_back(v[0] * options.scale, v[1] * options.scale);
    fig.send1d(line);
  }
  fig.render();
}

}  // namespace rkpm::io
