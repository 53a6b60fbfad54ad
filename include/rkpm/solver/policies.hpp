#pragma once
// The shipped policies of each family as Boost.Hana type lists, the cartesian product of
// all combinations, and a pairwise covering set (docs/method.md section 9.2).
//
// Every solver type costs compile time, and the full product is 2 x 2 x 3 x 2 x 4 x 4 = 384
// configurations. The tests instantiate `covering_configs`: 16 configurations in which every
// pair of policies from two different families appears at least once (generated and checked
// below at compile time). The runner instantiates only what its option strings can reach.

#include <array>
#include <boost/hana.hpp>
#include <cstddef>
#include <type_traits>

#include <rkpm/core/pairwise_covering.hpp>
#include <rkpm/contact/enforcement.hpp>
#include <rkpm/contact/friction.hpp>
#include <rkpm/contact/none.hpp>
#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/material/elastic.hpp>
#include <rkpm/material/j2_plasticity.hpp>
#include <rkpm/material/johnson_cook.hpp>
#include <rkpm/material/zerilli_armstrong.hpp>
#include <rkpm/solver/config.hpp>

namespace rkpm::policies {

namespace hana = boost::hana;

inline constexpr auto kernels = hana::tuple_t<kernel::cubic_spline, kernel::quartic_spline>;
inline constexpr auto corrections = hana::tuple_t<correction::linear, correction::quadratic>;
inline constexpr auto quadratures = hana::tuple_t<quadrature::q2, quadrature::q4, quadrature::q9>;
// Rules beyond the paper (docs/method.md sections 3.4-3.5), kept out of `quadratures` (and so
// out of the product, the covering set and the runner's compiled table) until the runner
// chooses them: the two other readings of the two-point cell, the VCI-corrected rules and
// stabilized conforming nodal integration (section 3.6), with its stabilization and without
// (scni_plain, to show what the stabilization does; both share one builder).
inline constexpr auto extended_quadratures =
    hana::tuple_t<quadrature::q2_split, quadrature::q2_tri, quadrature::q2_vci, quadrature::q4_vci,
                  quadrature::vci<quadrature::q2_split>, quadrature::vci<quadrature::q2_tri>, quadrature::scni<>,
                  quadrature::scni_plain>;
// Every rule the toolkit ships. The tests run each covering row below again with every rule of
// extended_quadratures in its place (test::check_combination_with_every_rule): the rows hold
// every policy of the other families, so each extended rule meets each of them, at no extra
// instantiation (the solver type does not depend on the rule).
inline constexpr auto all_quadratures = hana::concat(quadratures, extended_quadratures);
inline constexpr auto geometries = hana::tuple_t<geometry::plane_strain, geometry::axisymmetric>;
// One material of each kind of update: path-independent, J2 with a closed-form return, J2 with
// the Newton return of a rate- and temperature-dependent law on its own step curve and a state
// that grows (temperature, damage: Johnson-Cook), and J2 with the general rate-dependent Newton
// return and a temperature (Zerilli-Armstrong). J2 with power-law or Voce hardening shares the
// solver's code with these; it is tested by its own material tests and case files instead of
// four more solver instantiations (docs/method.md section 9.2).
inline constexpr auto materials =
    hana::tuple_t<material::elastic, material::j2_plasticity<material::hardening::linear>, material::johnson_cook,
                  material::zerilli_armstrong>;
inline constexpr auto contacts =
    hana::tuple_t<contact::none,
                  contact::particle_to_segment<contact::enforcement::paper, contact::friction::coulomb>,
                  contact::particle_to_segment<contact::enforcement::effective_mass, contact::friction::coulomb>,
                  contact::particle_to_segment<contact::enforcement::penalty, contact::friction::frictionless>>;

// In config's parameter order.
inline constexpr auto families = hana::make_tuple(kernels, corrections, quadratures, geometries, materials, contacts);
inline constexpr std::size_t family_count = 6;
inline constexpr std::array<std::size_t, family_count> family_sizes = {
    hana::length(kernels), hana::length(corrections), hana::length(quadratures),
    hana::length(geometries), hana::length(materials), hana::length(contacts)};

// config<...> from a hana tuple of hana::type_c<policy>.
inline constexpr auto to_config = [](auto types) {
  return hana::unpack(types, [](auto... t) { return hana::type_c<config<typename decltype(t)::type...>>; });
};

// Every combination (288 types; instantiating them all is what the covering set avoids). A
// template whose product depends on its parameter, so that only a file calling it pays for the
// product (a lambda, or a template over `families` itself, is instantiated in every file that
// includes this header: about 3 s of each compile).
template <class Families = std::remove_const_t<decltype(families)>>
constexpr auto all_configs() {
  return hana::transform(hana::cartesian_product(Families{}), to_config);
}

// Rows of policy indices (one per family, config order) covering every cross-family pair,
// generated at compile time from the family sizes (core/pairwise_covering.hpp): a policy added
// to a list enters the covering set with no table to retype.
inline constexpr auto covering_table = pairwise_covering(family_sizes);
inline constexpr std::array<std::array<std::size_t, family_count>, covering_table.count> covering_rows = [] {
  std::array<std::array<std::size_t, family_count>, covering_table.count> rows{};
  for (std::size_t r = 0; r < rows.size(); ++r) rows[r] = covering_table.rows[r];
  return rows;
}();

template <std::size_t Rows>
constexpr bool covers_every_pair(const std::array<std::array<std::size_t, family_count>, Rows>& rows,
                                 const std::array<std::size_t, family_count>& sizes) {
  for (std::size_t a = 0; a < family_count; ++a)
    for (std::size_t b = a + 1; b < family_count; ++b)
      for (std::size_t x = 0; x < sizes[a]; ++x)
        for (std::size_t y = 0; y < sizes[b]; ++y) {
          bool found = false;
          for (const auto& r : rows) found = found || (r[a] == x && r[b] == y);
          if (!found) return false;
        }
  return true;
}
static_assert(covers_every_pair(covering_rows, family_sizes),
              "covering_rows must contain every pair of policies from two different families");

// The covering set as a hana tuple of config types.
inline constexpr auto covering_configs = [] {
  return hana::unpack(hana::make_range(hana::size_c<0>, hana::size_c<covering_rows.size()>), [](auto... r) {
    auto row = [](auto i) {
      constexpr std::size_t row_index = decltype(i)::value;
      return to_config(hana::make_tuple(
          families[hana::size_c<0>][hana::size_c<covering_rows[row_index][0]>],
          families[hana::size_c<1>][hana::size_c<covering_rows[row_index][1]>],
          families[hana::size_c<2>][hana::size_c<covering_rows[row_index][2]>],
          families[hana::size_c<3>][hana::size_c<covering_rows[row_index][3]>],
          families[hana::size_c<4>][hana::size_c<covering_rows[row_index][4]>],
          families[hana::size_c<5>][hana::size_c<covering_rows[row_index][5]>]));
    };
    return hana::make_tuple(row(r)...);
  });
}();

}  // namespace rkpm::policies
