// "law": "rankine" in a case file (tools/runner/case_file/read_material.hpp, case_material.hpp;
// docs/method.md section 4.7): cases/brittle_bar.json loads into the runner's damage-carrying
// material, whose updates are material::rankine_fracture's bit for bit; the crack band follows
// the kernel's window at the body's support (107), at every resolution, unless given; every key
// is checked with one line naming its pointer and the fix, and a band too wide for the law (103)
// names the body's material.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/kernel/cubic_spline.hpp>
#include <rkpm/kernel/quartic_spline.hpp>
#include <rkpm/material/rankine_fracture.hpp>

#include "support/case_files.hpp"
#include "support/tensors.hpp"
#include "tools/runner/case_file/build_problem.hpp"

namespace test_unit_case_file_rankine {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;
using test::case_json;
using test::contains;
using test::load_error;
using test::reports;

namespace {

using contact_t = contact::particle_to_segment<contact::enforcement::paper, contact::friction::coulomb>;

case_json brittle_bar() { return test::paper_case_document("brittle_bar"); }

// The load error of the file with its material changed by `change`: one line at `pointer` that
// says `fix`.
template <class Change>
void one_error(Change change, const std::string& pointer, const std::string& fix) {
  case_json doc = brittle_bar();
  change(doc["bodies"][0]["material"]);
  const std::string e = load_error(doc);
  CAPTURE(e);
  CHECK(reports(e, pointer, fix));
  CHECK(std::count(e.begin(), e.end(), '\n') == 0);
}

}  // namespace

TEST_CASE("cases/brittle_bar.json: a Rankine body's points update as material::rankine_fracture's, bit for bit") {
  const auto description = test::load_document(brittle_bar());
  CHECK(runner::case_file::uses_johnson_cook_state(description));
  const auto& m = description.bodies[0].material;
  REQUIRE(m.rankine);
  CHECK((m.rankine->tensile_strength == 10e6 && m.rankine->fracture_energy == 500.0 && !m.rankine->band_width));

  // The band (107): 3/4 of the support radius for the cubic kernel, 2 x 0.5 mm at resolution 1,
  // half that at resolution 2; 4/5 for the quartic; the file's own when given.
  for (const int resolution : {1, 2}) {
    const auto p = runner::case_file::build_problem<contact_t>(description, resolution);
    REQUIRE(p.material.rankine() != nullptr);
    CHECK(p.body_materials.empty());
    CHECK(p.material.opens_cracks());
    CHECK(!runner::case_file::updates_in_lanes(p.material));
    const double support = 2.0 * 0.5e-3 / resolution;
    CHECK(p.material.rankine()->band_width() ==
          doctest::Approx(material::rankine_fracture::band_width_of_support<kernel::cubic_spline>(support)).epsilon(1e-12));
    CHECK(p.material.rankine()->band_width() == doctest::Approx(0.75 * support).epsilon(1e-3));
  }
  {
    case_json doc = brittle_bar();
    doc["method"]["kernel"] = "quartic";
    const auto p = runner::case_file::build_problem<contact_t>(test::load_document(doc), 1);
    CHECK(p.material.rankine()->band_width() == doctest::Approx(0.8 * 1e-3).epsilon(1e-3));
    doc["bodies"][0]["material"]["band_width_m"] = 0.6e-3;
    CHECK(runner::case_file::build_problem<contact_t>(test::load_document(doc), 1).material.rankine()->band_width() ==
          0.6e-3);
  }
  const std::string e = test::error_message(
      [&] { runner::case_file::build_problem<contact_t, runner::case_file::j2_material>(description, 1); });
  CHECK(contains(e, "a body with a temperature or a damage (rankine) was given a material without room for its state"));

  // Point by point on a path that loads past the tensile strength, unloads, and reloads until the
  // point fails: the runner's material is the typed one, stress and state.
  const auto file = runner::case_file::build_problem<contact_t>(description, 1).material;
  const material::rankine_fracture& typed = *file.rankine();
  auto a = typed.initial_state();
  auto b = file.initial_state();
  CHECK((b.damage == 0.0 && b.plastic_work == 0.0 && std::isnan(b.temperature)));
  bool failed_on_the_path = false;
  for (const mat3& F : test::stretch_shear_path()) {
    const mat3 ta = typed.kirchhoff_stress(F, a), tb = file.kirchhoff_stress(F, b);
    CHECK(ta == tb);
    CHECK(file.current_kirchhoff_stress(F, b) == typed.current_kirchhoff_stress(F, a));
    const auto r = runner::case_file::rankine_state_of(b);
    CHECK((r.kappa == a.kappa && r.damage == a.damage && r.plastic_work == a.plastic_work &&
           r.crack_normal == a.crack_normal && b.equivalent_plastic_strain == 0.0));
    CHECK(b.failed() == a.failed());
    CHECK(b.previous_deformation == block_matrix::of(F));  // the total F a re-reference takes as F_r
    failed_on_the_path = failed_on_the_path || b.failed();
  }
  CHECK(failed_on_the_path);
  CHECK(a.plastic_work == doctest::Approx(500.0 / typed.band_width()));  // W_d = G_c / h once failed (106)
  CHECK(vec2(b.crack_normal).norm() == doctest::Approx(1.0));
}

TEST_CASE("rankine keys: each mistake one line with its pointer and fix") {
  CHECK(load_error(brittle_bar()) == "");
  const std::string at = "/bodies/0/material/";
  one_error([](case_json& m) { m.erase("tensile_strength_Pa"); }, "/bodies/0/material",
            "missing field 'tensile_strength_Pa'");
  one_error([](case_json& m) { m.erase("fracture_energy_J_m2"); }, "/bodies/0/material",
            "missing field 'fracture_energy_J_m2'");
  one_error([](case_json& m) { m["fracture_energy_J_m2"] = -5; }, at + "fracture_energy_J_m2", "must be positive");
  one_error([](case_json& m) { m["tensile_strength_Pa"] = 0; }, at + "tensile_strength_Pa", "must be positive");
  one_error([](case_json& m) { m["band_width_m"] = 0; }, at + "band_width_m", "must be positive");
  one_error([](case_json& m) { m["yield_stress_Pa"] = 1e8; }, at + "yield_stress_Pa", "unknown field 'yield_stress_Pa'");
  one_error([](case_json& m) { m["tensile_strength_Pa"] = "strong"; }, at + "tensile_strength_Pa", "expected a number");

  // A band wider than 2 G_c E / sigma_t^2 (103) is refused when the body is built, at its material.
  case_json doc = brittle_bar();
  doc["bodies"][0]["material"]["band_width_m"] = 1.0;
  const std::string e = test::error_message(
      [&] { runner::case_file::build_problem<contact_t>(test::load_document(doc), 1); });
  CAPTURE(e);
  CHECK(contains(e, "/bodies/0/material"));
  CHECK(contains(e, "too wide"));
}

}  // namespace test_unit_case_file_rankine
