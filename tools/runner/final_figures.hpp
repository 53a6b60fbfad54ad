#pragma once
// The runner's figures of a run's end state, drawn on the deformed cells with the tools
// (io/field_figure.hpp): final_plastic_strain.png, and final_temperature.png when the points
// have a temperature.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <rkpm/core/types.hpp>

#include <fmt/format.h>

#include <rkpm/io/field_figure.hpp>

namespace rkpm::runner {

// What the end-state figures draw: every particle's position, its equivalent plastic strain and
// temperature (NaN without one) projected from the points, the tools' vertices, the time.
struct end_state_fields {
  std::vector<vec2> x;
  std::vector<double> plastic_strain, temperature;
  std::vector<std::vector<vec2>> tools;
  double time = 0.0;
};

// final_plastic_strain.png: the equivalent plastic strain on the deformed cells at the run's
// end, with the tools (io/field_figure.hpp). final_temperature.png likewise, when every particle
// has a temperature.
inline void end_state_pngs(const std::filesystem::path& dir, const std::string& name, const end_state_fields& f,
                           const io::cell_layout& cells) {
  io::field_png(dir / "final_plastic_strain.png", f.x, cells, f.plastic_strain, f.tools,
                {.title = fmt::format("{}: equivalent plastic strain at t = {:.4g} us", name, f.time * 1e6),
                 .label = "equivalent plastic strain"});
  if (!f.temperature.empty() && std::ranges::all_of(f.temperature, [](double v) { return std::isfinite(v); }))
    io::field_png(dir / "final_temperature.png", f.x, cells, f.temperature, f.tools,
                  {.title = fmt::format("{}: temperature at t = {:.4g} us", name, f.time * 1e6),
                   .label = "temperature (K)"});
}

// The fields at the solver's particles (of a part: right at its owned particles).
template <class Solver>
end_state_fields end_state_of(const Solver& s) {
  end_state_fields f;
  f.x = s.particle_positions();
  f.plastic_strain = s.template project_to_particles<double>(
      [&](index_t q) { return static_cast<double>(s.point_states()[q].equivalent_plastic_strain); });
  if constexpr (requires { s.point_states()[0].temperature; })
    f.temperature = s.template project_to_particles<double>(
        [&](index_t q) { return static_cast<double>(s.point_states()[q].temperature); });
  for (const auto& tool : s.contact().tools()) f.tools.push_back(tool.vertices(s.time()));
  f.time = s.time();
  return f;
}

template <class Solver>
void final_plastic_strain_png(const std::filesystem::path& dir, const std::string& name, const Solver& s,
                              const io::cell_layout& cells) {
  end_state_pngs(dir, name, end_state_of(s), cells);
}

}  // namespace rkpm::runner
