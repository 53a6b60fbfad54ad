#pragma once
// The policies rkpm_run offers on its command line, taken from the library's lists
// (rkpm/solver/policies.hpp) rather than typed again: every kernel, correction and quadrature
// there, and the enforcement of each particle-to-segment contact there (the runner pairs each
// with Coulomb friction; a coefficient of 0 is frictionless). Option values and the names in
// summary.json are the policies' `name`.

#include <string>
#include <vector>

#include <boost/hana.hpp>

#include <rkpm/solver/method_names.hpp>
#include <rkpm/solver/policies.hpp>

namespace rkpm::runner {

namespace hana = boost::hana;

inline constexpr auto kernels = policies::kernels;
inline constexpr auto corrections = policies::corrections;
// The paper's rules and those beyond it (q2_split, q2_tri, the VCI-corrected rules, SCNI): the
// runner chooses the rule at run time, so offering them all costs no solver instantiation.
inline constexpr auto quadratures = policies::all_quadratures;
inline constexpr auto enforcements = [] {
  constexpr auto has_enforcement =
      hana::is_valid([](auto t) -> hana::type<typename decltype(t)::type::enforcement_type> { return {}; });
  return hana::transform(hana::filter(policies::contacts, has_enforcement),
                         [](auto t) { return hana::type_c<typename decltype(t)::type::enforcement_type>; });
}();

// The rules beyond the paper that `paper` runs beside Q2 and Q4 for its report's last section:
// the other two readings of the two-point cell, VCI on Q2 and Q4, and stabilized nodal
// integration (the rest of policies::extended_quadratures are variants of these).
inline constexpr auto report_rules = hana::tuple_t<quadrature::q2_split, quadrature::q2_tri, quadrature::q2_vci,
                                                   quadrature::q4_vci, quadrature::scni<>>;
inline std::vector<std::string> report_rule_names() {
  std::vector<std::string> names;
  hana::for_each(report_rules, [&](auto t) { names.emplace_back(decltype(t)::type::name); });
  return names;
}

// The paper's method, the default of every run: cubic kernel, linear correction, Q2, the
// paper's contact enforcement.
using paper_kernel = kernel::cubic_spline;
using paper_correction = correction::linear;
using paper_quadrature = quadrature::q2;
using paper_enforcement = contact::enforcement::paper;

}  // namespace rkpm::runner
