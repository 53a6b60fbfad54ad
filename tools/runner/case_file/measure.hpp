#pragma once
// measure(solver, case, mean_tool_force): the case file's histories evaluated on a solver at
// its current time, in the file's order, as (name, value) pairs like the typed cases'
// measure(). The arithmetic is theirs (a maximum over the same particles, a gap as reference
// gap plus relative displacement, a force as the runner's mean over the last output
// interval), so that the paper case files give the typed cases' numbers bit for bit. With
// several bodies each measure that names a body looks at that body's particles or points only.
//   mean_tool_force  #tools list of the tools' reactions averaged over the last interval (N
//                    or N/m, as the runner passes them to every case's measure)
// measure() is measure_from() of the maxima, sums and nearest values measure_parts.hpp takes
// over the solver's own particles and points, which on several processes combine over the
// ranks first.

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include <rkpm/core/exact_sum.hpp>
#include <rkpm/core/types.hpp>

#include "build_problem.hpp"
#include "case_description.hpp"
#include "measure_parts.hpp"

namespace rkpm::runner::case_file {

namespace detail {

// Index of the tool called `name` among the solver's tools (the file's order).
template <class Solver>
std::size_t tool_index(const Solver& s, const std::string& name) {
  const auto& tools = s.contact().tools();
  for (std::size_t k = 0; k < tools.size(); ++k)
    if (tools[k].name() == name) return k;
  fail("case file: the solver has no tool '{}' (was it built from this case file?)", name);
}

// A history that every rank holds whole: the tools' and the contact's totals.
template <class Solver>
double total(const Solver& s, const history_kind& kind, const std::vector<vec2>& mean_tool_force) {
  return std::visit(
      [&](const auto& h) -> double {
        using H = std::decay_t<decltype(h)>;
        if constexpr (std::is_same_v<H, tool_gap_history>) {
          const auto& from = s.contact().tools()[tool_index(s, h.from)];
          const auto& to = s.contact().tools()[tool_index(s, h.to)];
          double top = to.reference_vertices().front()[h.component];
          double bottom = from.reference_vertices().front()[h.component];
          for (const vec2& v : to.reference_vertices()) top = std::min(top, v[h.component]);
          for (const vec2& v : from.reference_vertices()) bottom = std::max(bottom, v[h.component]);
          const double t = s.time();
          return (top - bottom) + (to.displacement(t)[h.component] - from.displacement(t)[h.component]);
        } else if constexpr (std::is_same_v<H, tool_force_history>) {
          const std::size_t k = tool_index(s, h.tool);
          const double f = k < mean_tool_force.size() ? mean_tool_force[k][h.component] : 0.0;
          return h.absolute ? std::abs(f) : f;
        } else if constexpr (std::is_same_v<H, tool_displacement_history>) {
          return s.contact().tools()[tool_index(s, h.tool)].displacement(s.time())[h.component];
        } else if constexpr (std::is_same_v<H, max_penetration_history>) {
          return s.max_penetration();
        } else {
          fail("case file: a history over a body's particles or points is measured by measure_parts.hpp");
        }
      },
      kind);
}

}  // namespace detail

// The row from the maxima, sums and nearest values of measure_parts.hpp (over the whole model,
// or combined over the ranks' parts) and the totals `s` holds.
template <class Solver>
std::vector<std::pair<std::string, double>> measure_from(const std::vector<double>& maxima,
                                                         const std::vector<exact_sum>& sums,
                                                         const std::vector<nearest_value>& nearest, const Solver& s,
                                                         const case_description& c,
                                                         const std::vector<vec2>& mean_tool_force) {
  std::vector<std::pair<std::string, double>> out;
  out.reserve(c.histories.size());
  std::size_t m = 0, k = 0, n = 0;
  for (const auto& h : c.histories) {
    double value = 0.0;
    if (const auto* e = std::get_if<extent_history>(&h.kind)) {
      const double hi = maxima[m], lo = -maxima[m + 1];
      value = maxima[m + 2] == 0.0 ? 0.0 : e->of.starts_with("max") ? hi : e->of.starts_with("min") ? lo : hi - lo;
      m += 3;
    } else if (std::holds_alternative<probe_history>(h.kind)) {
      value = nearest[n++].value;
    } else if (std::holds_alternative<max_plastic_strain_history>(h.kind)) {
      value = maxima[m++];
    } else if (std::holds_alternative<max_temperature_history>(h.kind)) {
      value = maxima[m] == detail::none ? std::numeric_limits<double>::quiet_NaN() : maxima[m];
      ++m;
    } else if (std::holds_alternative<momentum_history>(h.kind)) {
      value = sums[k++].value();
    } else if (std::holds_alternative<volume_change_history>(h.kind)) {
      value = sums[k + 1].value() / sums[k].value() - 1.0;
      k += 2;
    } else if (std::holds_alternative<failed_fraction_history>(h.kind)) {
      const double chosen = sums[k].value(), failed = sums[k + 1].value();
      value = chosen > 0.0 ? failed / chosen : 0.0;
      k += 2;
    } else {  // the tools' and the contact's: totals every rank holds
      value = detail::total(s, h.kind, mean_tool_force);
    }
    out.emplace_back(h.name, value * h.scale);
  }
  return out;
}

template <class Solver>
std::vector<std::pair<std::string, double>> measure(const Solver& s, const case_description& c,
                                                    const std::vector<vec2>& mean_tool_force) {
  return measure_from(measure_maxima(s, c), measure_sums(s, c), measure_nearest(s, c), s, c, mean_tool_force);
}

}  // namespace rkpm::runner::case_file
