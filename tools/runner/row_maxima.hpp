#pragma once
// History rows on several processes without the whole state (ranks.hpp, docs/method.md
// section 9.8). A row reads the time, the case's measures, the tools' impulses, the energies and
// the companions' reports. All but the measures are totals that every rank holds alike; the
// measures of a case that offers
//   Case::measure_maxima(solver)  std::array<double, N>: maxima (minima negated) over the
//                                 solver's own particles (model().own.particles) and all its points
//   Case::measure_from(maxima, solver, parameters, mean_tool_force)  the measures from them and
//                                 from the totals
// with measure() = measure_from(measure_maxima(s), ...) are extremes, which each rank takes over
// its part (its owned particles; its points, whose states equal their owners', ghost copies
// included) and one MPI_MAX combines on rank 0. A maximum of finite values does not depend on
// the order it is taken in, so the row has one process's bits (a signed zero aside: -0 and +0
// compare equal, so an extreme that is exactly zero may keep either sign; the cases' are not).
// A case without them, or with companions, gathers the whole state for its rows (mirror_state).

#include <algorithm>
#include <array>
#include <concepts>
#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <rkpm/core/types.hpp>

namespace rkpm::runner {

template <class Case, class Solver>
concept MeasuredByMaxima = requires(const Solver& s, const typename Case::parameters& p, const std::vector<vec2>& f) {
  { Case::measure_maxima(s) };
  { Case::measure_from(Case::measure_maxima(s), s, p, f) } -> std::same_as<std::vector<std::pair<std::string, double>>>;
};

// The maxima function a run on several processes reduces: the case's maxima over the solver's
// part, as the reduction sends them (empty for a case that has none).
template <class Case, class Solver>
std::function<std::vector<double>(const Solver&)> row_maxima_of() {
  if constexpr (MeasuredByMaxima<Case, Solver>)
    return [](const Solver& s) {
      const auto m = Case::measure_maxima(s);
      return std::vector<double>(m.begin(), m.end());
    };
  else
    return {};
}

// A history row's measures: with `maxima` (row_maxima_of's values reduced over the ranks, so of
// the case's length), from the whole model's maxima and the totals `s` holds (a part of the
// model); with none, from `s`, the whole model (Case::measure).
template <class Case, class Solver>
std::vector<std::pair<std::string, double>> row_measures(const std::vector<double>& maxima, const Solver& s,
                                                          const typename Case::parameters& p,
                                                          const std::vector<vec2>& mean_tool_force) {
  if constexpr (MeasuredByMaxima<Case, Solver>) {
    if (!maxima.empty()) {
      decltype(Case::measure_maxima(s)) m{};
      std::copy(maxima.begin(), maxima.end(), m.begin());
      return Case::measure_from(m, s, p, mean_tool_force);
    }
  }
  return Case::measure(s, p, mean_tool_force);
}

}  // namespace rkpm::runner
