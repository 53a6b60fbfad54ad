// The case files' materials, j2_plasticity<case_file::hardening_law> with J2's state (j2_material)
// and with Johnson-Cook's (material_type) (case_material.hpp), give bit for bit the stresses and
// states of j2_plasticity<law> for every law of material::hardening::laws, along a path that yields, unloads and yields again (the linear law
// keeps its closed-form return); and with no yield it is the Hencky law of material::elastic up
// to round-off. Each law of the list is also read from a case file's material by its
// parameters() and comes out with the constants given.
#include <doctest/doctest.h>

#include <boost/hana.hpp>
#include <cmath>
#include <string>
#include <type_traits>
#include <vector>

#include <rkpm/material/elastic.hpp>
#include <rkpm/material/j2_plasticity.hpp>

#include "tools/runner/case_file/case_material.hpp"
#include "tools/runner/case_file/read_material.hpp"

#include "support/error_message.hpp"
#include "support/tensors.hpp"

namespace test_unit_case_file_hardening_law {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;
using runner::case_file::hardening_law;

namespace {

const material::elastic_constants aluminium{71e9, 0.3, 2700.0};

template <class Typed, class File>
void check_identical(const Typed& typed, const File& file) {
  auto a = typed.initial_state();
  auto b = file.initial_state();
  for (const mat3& F : test::stretch_shear_path()) {
    const mat3 ta = typed.kirchhoff_stress(F, a);
    const mat3 tb = file.kirchhoff_stress(F, b);
    CHECK(ta == tb);
    CHECK(a.equivalent_plastic_strain == b.equivalent_plastic_strain);
    CHECK(a.plastic_work == b.plastic_work);
    CHECK(a.elastic_left_cauchy_green == b.elastic_left_cauchy_green);
  }
  CHECK(a.equivalent_plastic_strain > 0.01);  // the path did yield
}

// A law of the list with the typical constants its parameters() show (their leading number),
// scaled by `scale` so that two calls give different laws.
template <class Law>
Law example_law(double scale = 1.0) {
  Law h{};
  for (const auto& p : Law::parameters()) h.*p.value = scale * std::stod(std::string(p.example));
  return h;
}

}  // namespace

TEST_CASE("every hardening law of the list: bit for bit j2_plasticity<law>") {
  boost::hana::for_each(material::hardening::laws, [](auto law) {
    using law_type = typename decltype(law)::type;
    CAPTURE(law_type::name);
    const law_type h = example_law<law_type>();
    check_identical(material::j2_plasticity<law_type>(aluminium, h),
                    runner::case_file::material_type(aluminium, hardening_law::of(h)));
    check_identical(material::j2_plasticity<law_type>(aluminium, h),
                    runner::case_file::j2_material(aluminium, hardening_law::of(h)));
  });
}

TEST_CASE("a case file of J2 bodies keeps J2's state per point, Johnson-Cook's only with a Johnson-Cook body") {
  static_assert(std::is_same_v<runner::case_file::j2_material::state_type, material::j2_state>);
  static_assert(std::is_same_v<runner::case_file::material_type::state_type, material::johnson_cook_state>);
  CHECK(sizeof(material::j2_state) == 96);  // what the runner's footprint at 10^6 particles counts on
  CHECK(sizeof(material::johnson_cook_state) > sizeof(material::j2_state));
}

TEST_CASE("every hardening law of the list is read from a case file's material with its constants") {
  boost::hana::for_each(material::hardening::laws, [](auto law) {
    using law_type = typename decltype(law)::type;
    CAPTURE(law_type::name);
    const law_type h = example_law<law_type>(1.5);
    runner::json m = {{"law", "j2"}, {"youngs_modulus_Pa", 71e9}, {"poisson_ratio", 0.3}, {"density_kg_m3", 2700},
              {"hardening", std::string(law_type::name)}};
    for (const auto& p : law_type::parameters()) m[std::string(p.key)] = h.*p.value;
    runner::case_file::diagnostics d("test.json");
    const auto read = runner::case_file::detail::read_material(d, m, "/bodies/0/material");
    CHECK_NOTHROW(d.throw_if_any());
    REQUIRE(std::holds_alternative<law_type>(read.flow_law.law));
    const law_type& got = std::get<law_type>(read.flow_law.law);
    for (const auto& p : law_type::parameters()) CHECK(got.*p.value == h.*p.value);
    // A missing constant is named; a negative one is refused with its bound.
    for (const auto& p : law_type::parameters()) {
      CAPTURE(p.key);
      runner::json missing = m;
      missing.erase(std::string(p.key));
      runner::case_file::diagnostics dm("test.json");
      (void)runner::case_file::detail::read_material(dm, missing, "/bodies/0/material");
      const std::string why_missing = test::error_message([&] { dm.throw_if_any(); });
      CHECK(test::contains(why_missing, "missing field '" + std::string(p.key) + "'"));
      runner::json negative = m;
      negative[std::string(p.key)] = -1.0;
      runner::case_file::diagnostics dn("test.json");
      (void)runner::case_file::detail::read_material(dn, negative, "/bodies/0/material");
      const std::string why_negative = test::error_message([&] { dn.throw_if_any(); });
      CHECK(test::contains(why_negative, "/bodies/0/material/" + std::string(p.key)));
      CHECK(test::contains(why_negative, p.bound == material::hardening::lower_bound::positive ? "must be positive"
                                                                                              : "must not be negative"));
    }
  });
}

TEST_CASE("linear hardening: bit for bit j2_plasticity<hardening::linear>") {
  const material::hardening::linear h{132e6, 300e6};
  check_identical(material::j2_plasticity<material::hardening::linear>(aluminium, h),
                  runner::case_file::material_type(aluminium, hardening_law::of(h)));
}

TEST_CASE("the case file's linear law takes the closed-form return, as hardening::linear does") {
  // j2_plasticity calls radial_return unqualified: the case file's overload must be found (with
  // the library's signature) and hand a linear law to the closed form, not to Newton.
  const hardening_law law = hardening_law::of(material::hardening::linear{132e6, 300e6});
  const double three_mu = 3.0 * aluminium.shear_modulus(), q = 2.0 * law.flow_stress(0.1);
  const auto r = radial_return(law, q, three_mu, 0.1, 1e-12, 50, law.flow_stress(0.1));
  CHECK(r.iterations == 0);
  CHECK(r.increment == (q - law.flow_stress(0.1)) / (three_mu + 300e6));
}

TEST_CASE("power-law hardening: bit for bit j2_plasticity<hardening::power_law>") {
  const material::hardening::power_law h{576.79e6, 0.01658, 0.3593};
  check_identical(material::j2_plasticity<material::hardening::power_law>(aluminium, h),
                  runner::case_file::material_type(aluminium, hardening_law::of(h)));
}

TEST_CASE("no yield: the Hencky law of material::elastic up to round-off") {
  const material::elastic elastic(aluminium);
  const runner::case_file::material_type file(aluminium, hardening_law::no_yield());
  material::elastic_state a;
  auto b = file.initial_state();
  for (const mat3& F : test::stretch_shear_path()) {
    const mat3 ta = elastic.kirchhoff_stress(F, a);
    const mat3 tb = file.kirchhoff_stress(F, b);
    CHECK((ta - tb).norm() <= 1e-12 * ta.norm());
    CHECK(b.equivalent_plastic_strain == 0.0);
  }
}

TEST_CASE("a hardening law is checked as the library's") {
  CHECK_THROWS_AS(runner::case_file::material_type(aluminium, hardening_law::of(material::hardening::linear{-1.0, 0.0})),
                  rkpm::error);
  CHECK_THROWS_AS(runner::case_file::material_type(
                      aluminium, hardening_law::of(material::hardening::power_law{576.79e6, 0.0, 0.3})),
                  rkpm::error);
}

}  // namespace test_unit_case_file_hardening_law
