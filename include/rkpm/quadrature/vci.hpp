#pragma once
// vci<Rule>: a cell rule with variationally consistent integration (Chen, Hillman, Rueter
// 2013, IJNME 95:387; docs/method.md section 3.5). The points and weights are Rule's; the
// test-function gradients at them are corrected once, in the reference configuration, so that
// the integration constraint (docs/method.md (19a)) holds exactly for every particle,
// which makes the linear patch test pass. The correction itself is computed by
// discretization/integration_constraint.hpp when build_discrete_model sees a CorrectedRule.
//   q2_vci  "q2+vci"    the paper's cost with a consistent force
//   q4_vci  "q4+vci"
//   vci<q2_split>, vci<q2_tri>  "q2_split+vci", "q2_tri+vci"
// EdgePoints: Gauss-Legendre points per boundary edge for the boundary integral of N_I n.

#include <string_view>

#include <rkpm/concepts/quadrature.hpp>
#include <rkpm/core/joined_name.hpp>
#include <rkpm/quadrature/cell_rules.hpp>
#include <rkpm/quadrature/shaped_rules.hpp>

namespace rkpm::quadrature {

namespace detail {
inline constexpr std::string_view vci_name = "vci";
}  // namespace detail

template <CellRule Rule, int EdgePoints = 5>
struct vci {
  static_assert(EdgePoints >= 2 && EdgePoints <= 6, "vci<Rule, EdgePoints>: 2 to 6 Gauss points per boundary edge");
  using cell_rule = Rule;
  static constexpr bool corrects_test_gradients = true;
  static constexpr int points_per_cell = Rule::points_per_cell;
  static constexpr int edge_points = EdgePoints;
  static constexpr std::string_view name = joined_name<Rule::name, detail::vci_name>::value;
};

using q2_vci = vci<q2>;
using q4_vci = vci<q4>;

}  // namespace rkpm::quadrature
