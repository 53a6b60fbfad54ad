#pragma once
// What simulate.hpp asks of a case beyond build() and measure(), for the typed cases
// (cases/*.hpp: a static name and a parameter list) and the case files (file_case.hpp: both
// read from the file) alike.

#include <string>
#include <utility>

#include "cases/parameters.hpp"
#include "json.hpp"

namespace rkpm::runner {

template <class Case>
inline constexpr bool is_file_case = requires(const typename Case::parameters& p) { Case::name_of(p); };

// The case's name: the typed case's, or the file's "name".
template <class Case>
std::string case_name(const typename Case::parameters& p) {
  if constexpr (is_file_case<Case>)
    return Case::name_of(p);
  else
    return std::string(Case::name);
}

// The parameters as summary.json and the checkpoints record them: the typed case's list, or the
// case file's document with the command line's overrides applied.
template <class Case>
json case_parameters(const typename Case::parameters& p) {
  json out = json::object();
  if constexpr (is_file_case<Case>) {
    out = p.document;
  } else {
    for (const auto& f : Case::parameters::fields)
      cases::visit_value(f, p, [&](auto value) { out[std::string(f.name)] = value; });
  }
  return out;
}

// The penalty enforcement's stiffness (N/m): the typed case's parameter, or the case file's
// "penalty_stiffness_N_m" (0 when it gives none: the file's checks refuse penalty then).
template <class Case>
double penalty_stiffness(const typename Case::parameters& p) {
  if constexpr (is_file_case<Case>)
    return p.penalty_stiffness.value_or(0.0);
  else
    return p.penalty_stiffness_N_m;
}

// History rows and snapshots over the run: the case file's "output", else 400 and 20.
template <class Case>
std::pair<int, int> output_counts(const typename Case::parameters& p) {
  if constexpr (is_file_case<Case>)
    return {p.history_rows, p.snapshots};
  else
    return {400, 20};
}

}  // namespace rkpm::runner
