// config<>: the documented defaults, the with_* aliases rebind exactly one parameter, the
// policy lists have the lengths of the shipped families, the product has 2*2*3*2*4*4 types and
// the covering set holds 16 distinct Config types. All checks are at compile time; the one
// run-time case only makes the program a doctest executable and checks name().

#include <set>
#include <string>
#include <doctest/doctest.h>

#include <type_traits>

#include <rkpm/solver/make_solver.hpp>
#include <rkpm/solver/method_names.hpp>
#include <rkpm/solver/policies.hpp>

namespace hana = boost::hana;
using namespace rkpm;

using d = config<>;
static_assert(std::is_same_v<d::kernel_type, kernel::cubic_spline>);
static_assert(std::is_same_v<d::correction_type, correction::linear>);
static_assert(std::is_same_v<d::quadrature_type, quadrature::q2>);
static_assert(std::is_same_v<d::geometry_type, geometry::plane_strain>);
static_assert(std::is_same_v<d::material_type, material::j2_plasticity<material::hardening::linear>>);
static_assert(std::is_same_v<d::contact_type, contact::none>);

using ptc = contact::particle_to_segment<contact::enforcement::penalty, contact::friction::frictionless>;
static_assert(std::is_same_v<d::with_kernel<kernel::quartic_spline>,
                             config<kernel::quartic_spline, correction::linear, quadrature::q2, geometry::plane_strain,
                                    material::j2_plasticity<material::hardening::linear>, contact::none>>);
static_assert(std::is_same_v<d::with_correction<correction::quadratic>,
                             config<kernel::cubic_spline, correction::quadratic, quadrature::q2,
                                    geometry::plane_strain, material::j2_plasticity<material::hardening::linear>,
                                    contact::none>>);
static_assert(std::is_same_v<d::with_quadrature<quadrature::q4>,
                             config<kernel::cubic_spline, correction::linear, quadrature::q4, geometry::plane_strain,
                                    material::j2_plasticity<material::hardening::linear>, contact::none>>);
static_assert(std::is_same_v<d::with_geometry<geometry::axisymmetric>,
                             config<kernel::cubic_spline, correction::linear, quadrature::q2, geometry::axisymmetric,
                                    material::j2_plasticity<material::hardening::linear>, contact::none>>);
static_assert(std::is_same_v<d::with_material<material::elastic>,
                             config<kernel::cubic_spline, correction::linear, quadrature::q2, geometry::plane_strain,
                                    material::elastic, contact::none>>);
static_assert(std::is_same_v<d::with_contact<ptc>,
                             config<kernel::cubic_spline, correction::linear, quadrature::q2, geometry::plane_strain,
                                    material::j2_plasticity<material::hardening::linear>, ptc>>);
// Rebinding composes and the last binding of a family wins.
static_assert(std::is_same_v<d::with_quadrature<quadrature::q4>::with_quadrature<quadrature::q9>,
                             d::with_quadrature<quadrature::q9>>);
static_assert(std::is_same_v<d::with_quadrature<quadrature::q2>, d>);
// The solver and problem types follow the configuration.
static_assert(std::is_same_v<solver_for<d>, explicit_solver<geometry::plane_strain, d::material_type, contact::none>>);
static_assert(std::is_same_v<problem_for<d::with_material<material::elastic>>,
                             problem<material::elastic, contact::none>>);
static_assert(std::is_same_v<solver_for<d::with_geometry<geometry::axisymmetric>>::geometry_type,
                             geometry::axisymmetric>);

// Policy lists.
static_assert(hana::length(policies::kernels) == hana::size_c<2>);
static_assert(hana::length(policies::corrections) == hana::size_c<2>);
static_assert(hana::length(policies::quadratures) == hana::size_c<3>);
static_assert(hana::length(policies::geometries) == hana::size_c<2>);
static_assert(hana::length(policies::materials) == hana::size_c<4>);
static_assert(hana::length(policies::contacts) == hana::size_c<4>);
static_assert(policies::family_sizes == std::array<std::size_t, 6>{2, 2, 3, 2, 4, 4});
static_assert(hana::length(policies::covering_configs) == hana::size_c<16>);
static_assert(decltype(hana::length(policies::all_configs()))::value == 384);
// q1 is shipped but kept out of the lists: it is the failing reference of the spectrum test.
static_assert(!hana::contains(policies::quadratures, hana::type_c<quadrature::q1>));

// The generated covering set has the fewest rows possible, the product of the two largest
// families (4 contacts x 4 materials), and its rows map to the right types (rows 0 and 15
// spelled out: {0,0,0,0,0,0} and {1,1,0,1,3,3}).
static_assert(policies::covering_rows.size() == 4 * 4);
static_assert(policies::covering_rows[0] == std::array<std::size_t, 6>{0, 0, 0, 0, 0, 0});
static_assert(std::is_same_v<typename decltype(+policies::covering_configs[hana::size_c<0>])::type,
                             config<kernel::cubic_spline, correction::linear, quadrature::q2, geometry::plane_strain,
                                    material::elastic, contact::none>>);
static_assert(policies::covering_rows[15] == std::array<std::size_t, 6>{1, 1, 0, 1, 3, 3});
static_assert(std::is_same_v<typename decltype(+policies::covering_configs[hana::size_c<15>])::type,
                             config<kernel::quartic_spline, correction::quadratic, quadrature::q2,
                                    geometry::axisymmetric, material::zerilli_armstrong, ptc>>);
// The generator covers every pair for other family sizes too (a fifth contact, a fourth
// material, three geometries), within a few rows of the product of the two largest sizes.
static_assert(policies::covers_every_pair(
    [] {
      constexpr auto t = pairwise_covering(std::array<std::size_t, 6>{2, 2, 3, 2, 4, 5});
      std::array<std::array<std::size_t, 6>, t.count> rows{};
      for (std::size_t r = 0; r < t.count; ++r) rows[r] = t.rows[r];
      return rows;
    }(),
    std::array<std::size_t, 6>{2, 2, 3, 2, 4, 5}));
static_assert(pairwise_covering(std::array<std::size_t, 6>{2, 2, 3, 3, 4, 5}).count <= 5 * 4 + 3);
// All 16 are distinct types.
static_assert(hana::length(hana::to_set(policies::covering_configs)) == hana::size_c<16>);

// A deliberately incomplete row set is rejected by the pairwise check.
static_assert(!policies::covers_every_pair(
    std::array<std::array<std::size_t, 6>, 1>{{{0, 0, 0, 0, 0, 0}}}, policies::family_sizes));
// Dropping any one row of the shipped covering set loses some pair (the set is not padded).
constexpr bool every_row_needed() {
  constexpr std::size_t n = policies::covering_rows.size();
  for (std::size_t drop = 0; drop < n; ++drop) {
    std::array<std::array<std::size_t, 6>, n - 1> rows{};
    std::size_t k = 0;
    for (std::size_t r = 0; r < n; ++r)
      if (r != drop) rows[k++] = policies::covering_rows[r];
    if (policies::covers_every_pair(rows, policies::family_sizes)) return false;
  }
  return true;
}
static_assert(every_row_needed());

TEST_CASE("config names") {
  CHECK(d::name() == "cubic-linear-q2-plane_strain-j2+linear-none");
  CHECK(d::with_kernel<kernel::quartic_spline>::with_quadrature<quadrature::q4>::name() ==
        "quartic-linear-q4-plane_strain-j2+linear-none");
  CHECK(d::with_contact<ptc>::name() == "cubic-linear-q2-plane_strain-j2+linear-penalty+frictionless");
  // One name per configuration: file names and benchmark labels never collide.
  std::set<std::string> names;
  std::size_t count = 0;
  hana::for_each(policies::all_configs(), [&](auto c) {
    names.insert(decltype(c)::type::name());
    ++count;
  });
  CHECK(count == 384);
  CHECK(names.size() == count);
}

TEST_CASE("a method named at run time: the typed configuration's name, and every name checked") {
  // Each covering configuration named at run time gives config<...>::name() of its type (every
  // policy of every family appears in some row).
  hana::for_each(policies::covering_configs, [&](auto c) {
    using C = typename decltype(c)::type;
    const method_names m{std::string(C::kernel_type::name), std::string(C::correction_type::name),
                         std::string(C::quadrature_type::name)};
    CHECK_NOTHROW(m.check());
    CHECK(m.configuration_name<typename C::geometry_type, typename C::material_type, typename C::contact_type>() ==
          C::name());
  });
  hana::for_each(policies::extended_quadratures, [&](auto q) {
    CHECK_NOTHROW((method_names{"cubic", "linear", std::string(decltype(q)::type::name)}.check()));
  });
  const auto refused = [](const method_names& m) {
    try {
      m.check();
    } catch (const rkpm::error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK(refused({"cubik", "linear", "q2"}) == "unknown kernel 'cubik'; the choices are cubic, quartic");
  CHECK(refused({"cubic", "linear", "q3"}).find("unknown quadrature 'q3'; the choices are q2, q4, q9, q2_split") == 0);
  CHECK(refused({"cubic", "cubic", "q2"}).find("unknown correction 'cubic'") == 0);
}

TEST_CASE("quadrature points of a rule named at run time, from the rule's own counts") {
  // A 10 x 10 cell grid has 121 nodes.
  CHECK(quadrature_point_count("q2", 100, 121) == 200);
  CHECK(quadrature_point_count("q4", 100, 121) == 400);
  CHECK(quadrature_point_count("q9", 100, 121) == 900);
  CHECK(quadrature_point_count("q2+vci", 100, 121) == 200);
  CHECK(quadrature_point_count("scni_plain", 100, 121) == 121);  // one per node
  CHECK(quadrature_point_count("scni", 100, 121) == 400);        // one per quarter cell
  CHECK_THROWS_AS(quadrature_point_count("q3", 100, 121), rkpm::error);
}
