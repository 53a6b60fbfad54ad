#pragma once
// The runner's figures of a run's end state, drawn on the deformed cells with the tools
// (io/field_figure.hpp): final_plastic_strain.png, and final_temperature.png when the points
// have a temperature.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include <rkpm/io/field_figure.hpp>

namespace rkpm::runner {

// final_plastic_strain.png: the equivalent plastic strain on the deformed cells at the run's
// end, with the tools (io/field_figure.hpp); the cells entry by entry, so that the figure holds
// no arrays of them beside the solver (41 MB at 10^6 particles). final_temperature.png likewise.
template <class Solver>
void final_plastic_strain_png(const std::filesystem::path& dir, const std::string& name, const Solver& s,
                              const io::cell_layout& cells) {
  const auto eps = s.template project_to_particles<double>(
      [&](index_t q) { return static_cast<double>(s.point_states()[q].equivalent_plastic_strain); });
  std::vector<std::vector<vec2>> tools;
  for (const auto& tool : s.contact().tools()) tools.push_back(tool.vertices(s.time()));
  io::field_png(dir / "final_plastic_strain.png", s.particle_positions(), cells, eps, tools,
                {.title = fmt::format("{}: equivalent plastic strain at t = {:.4g} us", name, s.time() * 1e6),
                 .label = "equivalent plastic strain"});
  // final_temperature.png: the points' temperature (the conducted one with "heat"), when they have one.
  if constexpr (requires { s.point_states()[0].temperature; }) {
    const auto T = s.template project_to_particles<double>(
        [&](index_t q) { return static_cast<double>(s.point_states()[q].temperature); });
    if (std::ranges::all_of(T, [](double v) { return std::isfinite(v); }))
      io::field_png(dir / "final_temperature.png", s.particle_positions(), cells, T, tools,
                    {.title = fmt::format("{}: temperature at t = {:.4g} us", name, s.time() * 1e6),
                     .label = "temperature (K)"});
  }
}

}  // namespace rkpm::runner
