// The Quadrature concept (include/rkpm/concepts/quadrature.hpp) at compile time: the shipped
// reference rules, shaped rules, VCI-corrected rules and nodal rules (scni) are accepted as
// what they are, and
// types missing what the builder calls, or claiming two kinds at once, are rejected. The run-time
// case checks the composed names and that config<> and make_quadrature_points take every kind.

#include <doctest/doctest.h>

#include <array>
#include <string_view>

#include <rkpm/concepts/quadrature.hpp>
#include <rkpm/discretization/quadrature_points.hpp>
#include <rkpm/geometry/axisymmetric.hpp>
#include <rkpm/geometry/plane_strain.hpp>
#include <rkpm/quadrature/cell_rules.hpp>
#include <rkpm/quadrature/shaped_rules.hpp>
#include <rkpm/quadrature/vci.hpp>
#include <rkpm/quadrature/scni.hpp>
#include <rkpm/solver/config.hpp>
#include <rkpm/solver/policies.hpp>

using namespace rkpm;

namespace {

struct no_name {
  static constexpr int points_per_cell = 1;
  static constexpr std::array<std::array<double, 3>, 1> rule{{{0.0, 0.0, 4.0}}};
};
struct count_mismatch {  // says 2 points, lists 1
  static constexpr std::string_view name = "mismatch";
  static constexpr int points_per_cell = 2;
  static constexpr std::array<std::array<double, 3>, 1> rule{{{0.0, 0.0, 4.0}}};
};
struct shaped_wrong_count {  // says 3 points, places 2
  static constexpr std::string_view name = "shaped3";
  static constexpr int points_per_cell = 3;
  static std::array<cell_point, 2> cell_points(const std::array<vec2, 4>&) { return {}; }
};
struct shaped_wrong_input {  // takes three corners
  static constexpr std::string_view name = "triangle";
  static constexpr int points_per_cell = 1;
  static std::array<cell_point, 1> cell_points(const std::array<vec2, 3>&) { return {}; }
};
struct both_kinds {  // a reference rule and a shaped rule at once: ambiguous
  static constexpr std::string_view name = "both";
  static constexpr int points_per_cell = 1;
  static constexpr std::array<std::array<double, 3>, 1> rule{{{0.0, 0.0, 4.0}}};
  static std::array<cell_point, 1> cell_points(const std::array<vec2, 4>&) { return {}; }
};
struct corrected_without_rule {
  static constexpr std::string_view name = "lonely";
  static constexpr int points_per_cell = 2;
  static constexpr bool corrects_test_gradients = true;
};
struct corrected_count_mismatch {
  using cell_rule = quadrature::q4;
  static constexpr std::string_view name = "q4?";
  static constexpr int points_per_cell = 2;
  static constexpr bool corrects_test_gradients = true;
};
struct corrected_switched_off {
  using cell_rule = quadrature::q2;
  static constexpr std::string_view name = "q2-";
  static constexpr int points_per_cell = 2;
  static constexpr bool corrects_test_gradients = false;
};

struct nodal_switched_off {  // says it does not smooth: nothing would build its gradients
  static constexpr std::string_view name = "nodal-";
  static constexpr bool smooths_gradients = false;
  static constexpr double stabilization = 0.5;
  static constexpr int edge_points = 3;
};
struct nodal_without_stabilization {
  static constexpr std::string_view name = "nodal?";
  static constexpr bool smooths_gradients = true;
  static constexpr int edge_points = 3;
};
struct nodal_out_of_range {  // Beta = 2 would amplify the sub-cell differences
  static constexpr std::string_view name = "nodal2";
  static constexpr bool smooths_gradients = true;
  static constexpr double stabilization = 2.0;
  static constexpr int edge_points = 3;
};
struct nodal_and_cell {  // a nodal rule with points per cell as well: ambiguous
  static constexpr std::string_view name = "nodal+q1";
  static constexpr int points_per_cell = 1;
  static constexpr std::array<std::array<double, 3>, 1> rule{{{0.0, 0.0, 4.0}}};
  static constexpr bool smooths_gradients = true;
  static constexpr double stabilization = 0.5;
  static constexpr int edge_points = 3;
};

}  // namespace

// Shipped rules, each of exactly one kind.
static_assert(ReferenceCellRule<quadrature::q1> && ReferenceCellRule<quadrature::q2>);
static_assert(ReferenceCellRule<quadrature::q4> && ReferenceCellRule<quadrature::q9>);
static_assert(ShapedCellRule<quadrature::q2_split> && !ReferenceCellRule<quadrature::q2_split>);
static_assert(ShapedCellRule<quadrature::q2_tri> && !ReferenceCellRule<quadrature::q2_tri>);
static_assert(CorrectedRule<quadrature::q2_vci> && !CellRule<quadrature::q2_vci>);
static_assert(CorrectedRule<quadrature::q4_vci> && CorrectedRule<quadrature::vci<quadrature::q2_tri>>);
static_assert(!CorrectedRule<quadrature::q2> && !CorrectedRule<quadrature::q2_split>);
static_assert(Quadrature<quadrature::q2> && Quadrature<quadrature::q2_split> && Quadrature<quadrature::q2_vci>);
static_assert(Quadrature<quadrature::vci<quadrature::q2_split, 3>>);
static_assert(std::is_same_v<cell_rule_of_t<quadrature::q2_vci>, quadrature::q2>);
static_assert(std::is_same_v<cell_rule_of_t<quadrature::q2_tri>, quadrature::q2_tri>);
static_assert(NodalRule<quadrature::scni<>> && NodalRule<quadrature::scni_plain> && Quadrature<quadrature::scni<>>);
static_assert(!CellRule<quadrature::scni<>> && !CorrectedRule<quadrature::scni<>>);
static_assert(!NodalRule<quadrature::q2> && !NodalRule<quadrature::q2_vci> && !NodalRule<quadrature::q2_tri>);

// Rejected: what the builder calls is missing, inconsistent or ambiguous.
static_assert(!Quadrature<no_name>);
static_assert(!Quadrature<count_mismatch>);
static_assert(!Quadrature<shaped_wrong_count>);
static_assert(!Quadrature<shaped_wrong_input>);
static_assert(ReferenceCellRule<both_kinds> && ShapedCellRule<both_kinds> && !Quadrature<both_kinds>);
static_assert(!Quadrature<corrected_without_rule>);
static_assert(!Quadrature<corrected_count_mismatch>);
static_assert(!Quadrature<corrected_switched_off>);
static_assert(!Quadrature<int>);
static_assert(!Quadrature<nodal_switched_off>);
static_assert(!Quadrature<nodal_without_stabilization>);
static_assert(!Quadrature<nodal_out_of_range>);
static_assert(ReferenceCellRule<nodal_and_cell> && !NodalRule<nodal_and_cell>);
// make_quadrature_points places cell rules only; a nodal rule's points come from its cells.
template <class Q>
concept cell_points_for = requires(const background_mesh& m) { make_quadrature_points<Q, geometry::plane_strain>(m); };
static_assert(cell_points_for<quadrature::q4> && !cell_points_for<quadrature::scni<>>);
// A corrected rule cannot wrap something that is not a cell rule (vci<Rule> is constrained).
template <class R>
concept wraps = requires { typename quadrature::vci<R>; };
static_assert(!wraps<no_name> && !wraps<both_kinds> && wraps<quadrature::q9>);

// The extended list stays apart from the runner's list.
static_assert(boost::hana::length(policies::extended_quadratures) == boost::hana::size_c<8>);
static_assert(!boost::hana::contains(policies::quadratures, boost::hana::type_c<quadrature::q2_vci>));
static_assert(boost::hana::contains(policies::extended_quadratures, boost::hana::type_c<quadrature::scni<>>));

TEST_CASE("names of the rules beyond the paper, and config<> takes them") {
  CHECK(quadrature::q2_split::name == "q2_split");
  CHECK(quadrature::q2_tri::name == "q2_tri");
  CHECK(quadrature::q2_vci::name == "q2+vci");
  CHECK(quadrature::q4_vci::name == "q4+vci");
  CHECK(quadrature::vci<quadrature::q2_split>::name == "q2_split+vci");
  CHECK(quadrature::vci<quadrature::q2_tri>::name == "q2_tri+vci");
  CHECK(quadrature::scni<>::name == "scni");
  CHECK(quadrature::scni_plain::name == "scni_plain");
  CHECK(config<>::with_quadrature<quadrature::scni<>>::name() == "cubic-linear-scni-plane_strain-j2+linear-none");
  CHECK(config<>::with_quadrature<quadrature::q2_vci>::name() == "cubic-linear-q2+vci-plane_strain-j2+linear-none");
  const background_mesh m = make_grid_mesh(vec2(0, 0), vec2(2, 1), Eigen::Vector2i(3, 2));
  CHECK(make_quadrature_points<quadrature::q2_vci, geometry::plane_strain>(m).size() == 4);
  CHECK(make_quadrature_points<quadrature::q2_tri, geometry::axisymmetric>(m).size() == 4);
}
