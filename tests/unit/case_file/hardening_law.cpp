// The case files' material, j2_plasticity<case_file::hardening_law> (case_material.hpp), gives
// bit for bit the stresses and states of j2_plasticity<linear> and <power_law> along a path
// that yields, unloads and yields again (the linear law keeps its closed-form return); and
// with no yield it is the Hencky law of material::elastic up to round-off.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include <rkpm/material/elastic.hpp>
#include <rkpm/material/j2_plasticity.hpp>

#include "tools/runner/case_file/case_material.hpp"

using namespace rkpm;
using runner::case_file::hardening_law;

namespace {

const material::elastic_constants aluminium{71e9, 0.3, 2700.0};

// Plane strain stretch with shear, out and back, then past the first peak (block-structured F).
std::vector<mat3> path() {
  std::vector<mat3> out;
  for (int i = 0; i <= 120; ++i) {
    const double s = i <= 40 ? i / 40.0 : i <= 70 ? 1.0 - (i - 40) / 60.0 : 0.5 + (i - 70) / 25.0;
    mat3 F = mat3::Identity();
    F(0, 0) = 1.0 + 0.08 * s;
    F(1, 1) = 1.0 / (1.0 + 0.05 * s);
    F(0, 1) = 0.06 * s;
    F(2, 2) = 1.0 + 0.01 * s;  // a hoop stretch, as in axisymmetric geometry
    out.push_back(F);
  }
  return out;
}

template <class Typed>
void check_identical(const Typed& typed, const runner::case_file::material_type& file) {
  auto a = typed.initial_state();
  auto b = file.initial_state();
  for (const mat3& F : path()) {
    const mat3 ta = typed.kirchhoff_stress(F, a);
    const mat3 tb = file.kirchhoff_stress(F, b);
    CHECK(ta == tb);
    CHECK(a.equivalent_plastic_strain == b.equivalent_plastic_strain);
    CHECK(a.plastic_work == b.plastic_work);
    CHECK(a.elastic_left_cauchy_green == b.elastic_left_cauchy_green);
  }
  CHECK(a.equivalent_plastic_strain > 0.01);  // the path did yield
}

}  // namespace

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
  for (const mat3& F : path()) {
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
