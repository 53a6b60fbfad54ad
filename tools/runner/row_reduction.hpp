#pragma once
// History rows on several processes without the whole state (ranks.hpp, docs/method.md
// section 9.8). A row reads the time, the case's measures, the tools' impulses, the energies and
// the companions' reports. All but the measures are totals that every rank holds alike; the
// measures of a case that offers
//   Case::measure_maxima(solver)  std::array<double, N>: maxima (minima negated) over the
//                                 solver's own particles (model().own.particles) and its points
//   Case::measure_sums(solver, parameters)  (optional) std::array<exact_sum, M>: sums over the
//                                 solver's own particles and own points (for_each_owned_point)
//   Case::measure_from(maxima[, sums], solver, parameters, mean_tool_force)  the measures from
//                                 them and from the totals
// with measure() = measure_from(measure_maxima(s)[, measure_sums(s, p)], ...) come from what
// each rank takes over its part: one MPI_MAX combines the maxima on rank 0 (the points' ghost
// copies hold their owners' states, and a maximum of finite values does not depend on the order
// it is taken in; a signed zero aside: -0 and +0 compare equal, so an extreme that is exactly
// zero may keep either sign, the cases' are not), one MPI_SUM the sums' limbs (core/exact_sum.hpp:
// exact, so in no order either). The row has one process's bits. A case without them, or with
// companions, gathers the whole state for its rows (mirror_state).

#include <algorithm>
#include <array>
#include <concepts>
#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <rkpm/core/exact_sum.hpp>
#include <rkpm/core/types.hpp>

namespace rkpm::runner {

// What a rank gives a row: its part's maxima and sums, combined over the ranks.
struct row_reduction {
  std::vector<double> maxima;
  std::vector<exact_sum> sums;
  bool empty() const { return maxima.empty() && sums.empty(); }
};

template <class Case, class Solver>
concept MeasuredBySums = requires(const Solver& s, const typename Case::parameters& p) {
  { Case::measure_sums(s, p) };
};

template <class Case, class Solver>
concept MeasuredByReduction =
    requires(const Solver& s, const typename Case::parameters& p, const std::vector<vec2>& f) {
      { Case::measure_maxima(s) };
    } &&
    (MeasuredBySums<Case, Solver>
         ? requires(const Solver& s, const typename Case::parameters& p, const std::vector<vec2>& f) {
             { Case::measure_from(Case::measure_maxima(s), Case::measure_sums(s, p), s, p, f) }
                 -> std::same_as<std::vector<std::pair<std::string, double>>>;
           }
         : requires(const Solver& s, const typename Case::parameters& p, const std::vector<vec2>& f) {
             { Case::measure_from(Case::measure_maxima(s), s, p, f) }
                 -> std::same_as<std::vector<std::pair<std::string, double>>>;
           });

// What a run on several processes reduces: the case's maxima and sums over the solver's part
// (empty for a case that has none).
template <class Case, class Solver>
std::function<row_reduction(const Solver&)> row_reduction_of(const typename Case::parameters& p) {
  if constexpr (MeasuredByReduction<Case, Solver>)
    return [p](const Solver& s) {
      row_reduction r;
      const auto m = Case::measure_maxima(s);
      r.maxima.assign(m.begin(), m.end());
      if constexpr (MeasuredBySums<Case, Solver>) {
        const auto sums = Case::measure_sums(s, p);
        r.sums.assign(sums.begin(), sums.end());
      }
      return r;
    };
  else
    return {};
}

// A history row's measures: with `reduced` (row_reduction_of's over the ranks, so of the case's
// lengths), from the whole model's maxima and sums and the totals `s` holds (a part of the
// model); with none, from `s`, the whole model (Case::measure).
template <class Case, class Solver>
std::vector<std::pair<std::string, double>> row_measures(const row_reduction& reduced, const Solver& s,
                                                          const typename Case::parameters& p,
                                                          const std::vector<vec2>& mean_tool_force) {
  if constexpr (MeasuredByReduction<Case, Solver>) {
    if (!reduced.empty()) {
      decltype(Case::measure_maxima(s)) m{};
      std::copy(reduced.maxima.begin(), reduced.maxima.end(), m.begin());
      if constexpr (MeasuredBySums<Case, Solver>) {
        decltype(Case::measure_sums(s, p)) sums{};
        std::copy(reduced.sums.begin(), reduced.sums.end(), sums.begin());
        return Case::measure_from(m, sums, s, p, mean_tool_force);
      } else {
        return Case::measure_from(m, s, p, mean_tool_force);
      }
    }
  }
  return Case::measure(s, p, mean_tool_force);
}

}  // namespace rkpm::runner
