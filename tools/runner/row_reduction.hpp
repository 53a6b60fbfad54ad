#pragma once
// History rows on several processes without the whole state (ranks.hpp, docs/method.md
// section 9.8). A row reads the time, the case's measures, the tools' impulses, the energies and
// the companions' reports. All but the measures are totals that every rank holds alike; the
// measures of a case that offers
//   Case::measure_maxima(solver[, parameters])  std::array<double, N> (or a vector): maxima
//                                 (minima negated) over the solver's own particles
//                                 (model().own.particles) and its points
//   Case::measure_sums(solver, parameters)  (optional) std::array<exact_sum, M> (or a vector):
//                                 sums over the solver's own particles and own points
//                                 (for_each_owned_point)
//   Case::measure_nearest(solver, parameters)  (optional, with measure_sums) a vector of
//                                 nearest_value: per value at the particle nearest a point (a
//                                 case file's probe), the part's own particle nearest it
//   Case::measure_from(maxima[, sums[, nearest]], solver, parameters, mean_tool_force)  the
//                                 measures from them and from the totals
// with measure() = measure_from(measure_maxima(s)[, measure_sums(s, p)], ...) come from what
// each rank takes over its part: one MPI_MAX combines the maxima on rank 0 (the points' ghost
// copies hold their owners' states, and a maximum of finite values does not depend on the order
// it is taken in; a signed zero aside: -0 and +0 compare equal, so an extreme that is exactly
// zero may keep either sign, the cases' are not), one MPI_SUM the sums' limbs (core/exact_sum.hpp:
// exact, so in no order either), one reduction by the smallest (distance, global index) the
// nearest values (a choice, no arithmetic: the whole model's nearest particle, ties to the
// smallest index, as one process's loop finds it). The row has one process's bits. A case without them, or with
// companions, gathers the whole state for its rows (mirror_state).

#include <algorithm>
#include <array>
#include <concepts>
#include <cstddef>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <rkpm/core/exact_sum.hpp>
#include <rkpm/core/types.hpp>

namespace rkpm::runner {

// A value at the particle nearest a point, from a part: the squared distance (in the reference
// configuration) of the part's own particle nearest it, that particle's global index and the
// value there; none (infinite distance) from a part without one.
struct nearest_value {
  double distance2 = std::numeric_limits<double>::infinity();
  double index = std::numeric_limits<double>::infinity();  // a global index: exact below 2^53
  double value = 0.0;
  // Nearer, or as near with a smaller index: the one process's first nearest particle.
  bool before(const nearest_value& o) const {
    return distance2 < o.distance2 || (distance2 == o.distance2 && index < o.index);
  }
};

// What a rank gives a row: its part's maxima, sums and nearest values, combined over the ranks.
struct row_reduction {
  std::vector<double> maxima;
  std::vector<exact_sum> sums;
  std::vector<nearest_value> nearest;
  bool empty() const { return maxima.empty() && sums.empty() && nearest.empty(); }
};

// The case's maxima over the solver's part, with the parameters when it takes them.
template <class Case, class Solver>
auto measure_maxima_of(const Solver& s, const typename Case::parameters& p) {
  if constexpr (requires { Case::measure_maxima(s, p); })
    return Case::measure_maxima(s, p);
  else
    return Case::measure_maxima(s);
}

template <class Case, class Solver>
concept MeasuredBySums = requires(const Solver& s, const typename Case::parameters& p) {
  { Case::measure_sums(s, p) };
};

template <class Case, class Solver>
concept MeasuredByNearest = requires(const Solver& s, const typename Case::parameters& p) {
  { Case::measure_nearest(s, p) };
};

template <class Case, class Solver>
concept MeasuredByReduction =
    requires(const Solver& s, const typename Case::parameters& p) { Case::measure_maxima(s); } ||
    requires(const Solver& s, const typename Case::parameters& p) { Case::measure_maxima(s, p); };

// A fixed-size array or a vector of `Value`s from the combined values.
template <class Values, class Value>
Values values_from(const std::vector<Value>& combined) {
  Values out{};
  if constexpr (requires { out.assign(combined.begin(), combined.end()); })
    out.assign(combined.begin(), combined.end());
  else
    std::copy(combined.begin(), combined.end(), out.begin());
  return out;
}

// What a run on several processes reduces: the case's maxima and sums over the solver's part
// (empty for a case that has none).
template <class Case, class Solver>
std::function<row_reduction(const Solver&)> row_reduction_of(const typename Case::parameters& p) {
  if constexpr (MeasuredByReduction<Case, Solver>) {
    return [p](const Solver& s) {
      row_reduction r;
      const auto m = measure_maxima_of<Case>(s, p);
      r.maxima.assign(m.begin(), m.end());
      if constexpr (MeasuredBySums<Case, Solver>) {
        const auto sums = Case::measure_sums(s, p);
        r.sums.assign(sums.begin(), sums.end());
      }
      if constexpr (MeasuredByNearest<Case, Solver>) r.nearest = Case::measure_nearest(s, p);
      return r;
    };
  } else {
    return {};
  }
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
      const auto m = values_from<decltype(measure_maxima_of<Case>(s, p))>(reduced.maxima);
      if constexpr (MeasuredBySums<Case, Solver>) {
        const auto sums = values_from<decltype(Case::measure_sums(s, p))>(reduced.sums);
        if constexpr (MeasuredByNearest<Case, Solver>)
          return Case::measure_from(m, sums, reduced.nearest, s, p, mean_tool_force);
        else
          return Case::measure_from(m, sums, s, p, mean_tool_force);
      } else {
        return Case::measure_from(m, s, p, mean_tool_force);
      }
    }
  }
  return Case::measure(s, p, mean_tool_force);
}

}  // namespace rkpm::runner
