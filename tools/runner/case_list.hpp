#pragma once
// The cases rkpm_run offers, listed once: `rkpm_run CASE`, `rkpm_run paper --cases`, the help
// and the dispatch all read this list. Each case type gives its name, description and
// parameters (cases/*.hpp); run_case<Case> is compiled in run_CASE.cpp, one translation unit
// per case so that they build in parallel.

#include <string>
#include <vector>

#include <boost/hana.hpp>

#include "cases/block_forging.hpp"
#include "cases/rod_on_rod.hpp"
#include "cases/taylor_bar.hpp"
#include "cases/wheel_forging.hpp"
#include "outcome.hpp"
#include "request.hpp"

namespace rkpm::runner {

inline constexpr auto case_types =
    boost::hana::tuple_t<cases::taylor_bar, cases::block_forging, cases::wheel_forging, cases::rod_on_rod>;

// Runs one case as the request says (parameters from --set, --end-time); dispatch.hpp.
template <class Case>
run_outcome run_case(const run_request& r);

inline std::vector<std::string> case_names() {
  std::vector<std::string> names;
  boost::hana::for_each(case_types, [&](auto t) { names.emplace_back(decltype(t)::type::name); });
  return names;
}

// Runs the case the request names (one of case_names(), which the parser checked).
inline run_outcome run_named_case(const run_request& r) {
  run_outcome out;
  bool found = false;
  boost::hana::for_each(case_types, [&](auto t) {
    using Case = typename decltype(t)::type;
    if (r.case_name == Case::name) {
      out = run_case<Case>(r);
      found = true;
    }
  });
  if (!found) fail("unknown case '{}'", r.case_name);
  return out;
}

}  // namespace rkpm::runner
