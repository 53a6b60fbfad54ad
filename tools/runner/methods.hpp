#pragma once
// The policies rkpm_run offers on its command line, taken from the library's lists
// (rkpm/solver/policies.hpp) rather than typed again: every kernel, correction and quadrature
// there, and the enforcement of each particle-to-segment contact there (the runner pairs each
// with Coulomb friction; a coefficient of 0 is frictionless). Option values and the names in
// summary.json are the policies' `name`.

#include <string>
#include <string_view>
#include <vector>

#include <boost/hana.hpp>

#include <rkpm/solver/policies.hpp>

namespace rkpm::runner {

namespace hana = boost::hana;

inline constexpr auto kernels = policies::kernels;
inline constexpr auto corrections = policies::corrections;
// The paper's rules and those beyond it (q2_split, q2_tri, the VCI-corrected rules): the runner
// chooses the rule at run time, so offering them all costs no solver instantiation.
inline constexpr auto quadratures = hana::concat(policies::quadratures, policies::extended_quadratures);
inline constexpr auto enforcements = [] {
  constexpr auto has_enforcement =
      hana::is_valid([](auto t) -> hana::type<typename decltype(t)::type::enforcement_type> { return {}; });
  return hana::transform(hana::filter(policies::contacts, has_enforcement),
                         [](auto t) { return hana::type_c<typename decltype(t)::type::enforcement_type>; });
}();

// The paper's method, the default of every run: cubic kernel, linear correction, Q2, the
// paper's contact enforcement.
using paper_kernel = kernel::cubic_spline;
using paper_correction = correction::linear;
using paper_quadrature = quadrature::q2;
using paper_enforcement = contact::enforcement::paper;

// Quadrature points per background cell of the rule called `name`, for estimates: a cell
// rule's count; a nodal rule (one point per particle, or a few with its stabilization) 4.
inline int rule_points_per_cell(std::string_view name) {
  int points = 0;
  hana::for_each(quadratures, [&](auto t) {
    using Q = typename decltype(t)::type;
    if (Q::name != name) return;
    if constexpr (requires { Q::points_per_cell; })
      points = Q::points_per_cell;
    else
      points = 4;
  });
  return points;
}

// The `name` of each policy in a Hana list of types, in list order.
template <class Types>
std::vector<std::string> policy_names(Types types) {
  std::vector<std::string> names;
  hana::for_each(types, [&](auto t) { names.emplace_back(decltype(t)::type::name); });
  return names;
}

}  // namespace rkpm::runner
