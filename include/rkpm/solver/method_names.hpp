#pragma once
// method_names: a method's kernel, correction and quadrature rule by the policies' names (the
// lists of solver/policies.hpp), as a command line, a case file or Python gives them; and the
// configuration name config<...>::name() would give, so that messages, summary.json and
// checkpoints name a run-time method exactly as its typed twin. Checking the names costs no
// model builder (solver/make_model.hpp builds the model).

#include <string>
#include <string_view>
#include <vector>

#include <boost/hana.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <rkpm/core/error.hpp>
#include <rkpm/solver/policies.hpp>

namespace rkpm {

// The `name` of each policy in a Hana list of types, in list order.
template <class Types>
std::vector<std::string> policy_names(Types types) {
  std::vector<std::string> names;
  boost::hana::for_each(types, [&](auto t) { names.emplace_back(decltype(t)::type::name); });
  return names;
}

struct method_names {
  std::string kernel{kernel::cubic_spline::name};
  std::string correction{correction::linear::name};
  std::string quadrature{quadrature::q2::name};

  std::string describe() const {
    return fmt::format("kernel '{}', correction '{}', quadrature '{}'", kernel, correction, quadrature);
  }
  // Refuses, in one line with the choices, a name that is in none of the lists.
  void check() const {
    check_one("kernel", kernel, policy_names(policies::kernels));
    check_one("correction", correction, policy_names(policies::corrections));
    check_one("quadrature", quadrature, policy_names(policies::all_quadratures));
  }
  // config<K, C, Q, G, M, Ct>::name() for the named K, C, Q.
  template <class G, class M, class Ct>
  std::string configuration_name() const {
    return fmt::format("{}-{}-{}-{}-{}-{}", kernel, correction, quadrature, G::name, M::name, Ct::name);
  }

 private:
  static void check_one(std::string_view what, const std::string& name, const std::vector<std::string>& choices) {
    for (const auto& c : choices)
      if (c == name) return;
    fail("unknown {} '{}'; the choices are {}", what, name, fmt::join(choices, ", "));
  }
};

// Quadrature points a rule named `rule` makes on a mesh of `cells` cells and `nodes` nodes
// (for estimates before the model is built): a cell rule's points per cell times the cells; a
// nodal rule one point per node without stabilization, one per part of each smoothing cell (4
// per cell) with it (quadrature/scni.hpp).
inline double quadrature_point_count(std::string_view rule, index_t cells, index_t nodes) {
  double points = -1.0;
  boost::hana::for_each(policies::all_quadratures, [&](auto t) {
    using Q = typename decltype(t)::type;
    if (Q::name != rule) return;
    if constexpr (NodalRule<Q>)
      points = Q::stabilization > 0.0 ? 4.0 * double(cells) : double(nodes);
    else
      points = double(Q::points_per_cell) * double(cells);
  });
  if (points < 0.0) fail("unknown quadrature '{}'; the choices are {}", rule, fmt::join(policy_names(policies::all_quadratures), ", "));
  return points;
}

}  // namespace rkpm
