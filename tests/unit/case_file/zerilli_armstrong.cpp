// "law": "zerilli_armstrong" in a case file (tools/runner/case_file/read_temperature_laws.hpp;
// docs/method.md section 4.6): cases/taylor_copper_za.json loads into the runner's
// temperature-carrying material, whose updates are material::zerilli_armstrong's bit for bit;
// every key is checked with one line naming its pointer and the fix, and each lattice takes
// exactly its own keys.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/material/zerilli_armstrong.hpp>

#include "support/case_files.hpp"
#include "support/tensors.hpp"
#include "tools/runner/case_file/build_problem.hpp"

namespace test_unit_case_file_zerilli_armstrong {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;
using test::case_json;
using test::contains;
using test::load_error;
using test::reports;

namespace {

using contact_t = contact::particle_to_segment<contact::enforcement::penalty, contact::friction::coulomb>;
using flow_type = material::hardening::zerilli_armstrong;

case_json copper_za() { return test::paper_case_document("taylor_copper_za"); }

// Armco iron's bcc constants (Zerilli & Armstrong 1987; C0 chosen here) in the copper file.
case_json iron_za() {
  case_json doc = copper_za();
  auto& m = doc["bodies"][0]["material"];
  m.erase("C2_Pa");
  m["lattice"] = "bcc";
  m["C0_Pa"] = 50e6;
  m["C1_Pa"] = 1033e6;
  m["C3_1_K"] = 0.00698;
  m["C4_1_K"] = 0.000415;
  m["C5_Pa"] = 266e6;
  m["n"] = 0.289;
  m["melt_temperature_K"] = 1811;
  return doc;
}

std::size_t lines(const std::string& message) {
  return message.empty() ? 0 : 1 + std::count(message.begin(), message.end(), '\n');
}

// The load error of the copper file with its material changed by `change`: one line at `pointer`
// that says `fix`.
template <class Change>
void one_error(case_json doc, Change change, const std::string& pointer, const std::string& fix) {
  change(doc["bodies"][0]["material"]);
  const std::string e = load_error(doc);
  CAPTURE(e);
  CHECK(reports(e, pointer, fix));
  CHECK(lines(e) == 1);
}

}  // namespace

TEST_CASE("cases/taylor_copper_za.json: Zerilli & Armstrong's copper, a material that carries a temperature") {
  const auto description = test::load_document(copper_za());
  CHECK(runner::case_file::uses_johnson_cook_state(description));
  const auto& m = description.bodies[0].material;
  REQUIRE(m.zerilli_armstrong);
  const flow_type& f = m.zerilli_armstrong->flow();
  CHECK(f.lattice == flow_type::lattice_type::fcc);
  CHECK((f.C0 == 65e6 && f.C2 == 890e6 && f.C3 == 0.0028 && f.C4 == 0.000115 && f.reference_rate == 1.0));
  CHECK(f.melt_temperature == 1356.0);
  CHECK(m.zerilli_armstrong->heating().initial_temperature == 294.0);
  CHECK(m.zerilli_armstrong->heating().taylor_quinney == 0.9);
  CHECK(m.zerilli_armstrong->constants().youngs_modulus == 124e9);

  const auto p = runner::case_file::build_problem<contact_t>(description, 1);
  REQUIRE(p.material.zerilli_armstrong() != nullptr);
  CHECK(p.material.johnson_cook() == nullptr);
  CHECK(!runner::case_file::updates_in_lanes(p.material));
  const std::string e = test::error_message(
      [&] { runner::case_file::build_problem<contact_t, runner::case_file::j2_material>(description, 1); });
  CHECK(contains(e, "a body with a temperature or a damage (zerilli_armstrong) was given a material without room for its state"));

  // Point by point, the runner's material is the typed one, bit for bit, on a path that loads,
  // unloads and reloads at a high rate, fcc and bcc.
  for (const case_json& doc : {copper_za(), iron_za()}) {
    const auto d = test::load_document(doc);
    const material::zerilli_armstrong typed = *d.bodies[0].material.zerilli_armstrong;
    const auto file = runner::case_file::build_problem<contact_t>(d, 1).material;
    auto a = typed.initial_state();
    auto b = file.initial_state();
    CHECK(b.temperature == 294.0);
    CHECK(std::isnan(b.damage));  // no damage: the snapshots leave the field out
    const double dt = 1e-7;
    int k = 0;
    for (const mat3& F : test::stretch_shear_path()) {
      const material_step step{dt, ++k * dt, a.temperature};
      const mat3 ta = typed.kirchhoff_stress(F, a, step), tb = file.kirchhoff_stress(F, b, step);
      CHECK(ta == tb);
      CHECK(file.current_kirchhoff_stress(F, b) == typed.current_kirchhoff_stress(F, a));
      CHECK((a.equivalent_plastic_strain == b.equivalent_plastic_strain && a.plastic_work == b.plastic_work &&
             a.temperature == b.temperature));
    }
    CHECK(a.equivalent_plastic_strain > 0.05);
    CHECK(a.temperature > 300.0);
  }
}

TEST_CASE("zerilli_armstrong keys: each mistake one line with its pointer and fix; each lattice its own keys") {
  CHECK(load_error(iron_za()) == "");
  const std::string at = "/bodies/0/material/";
  one_error(copper_za(), [](case_json& m) { m.erase("lattice"); }, "/bodies/0/material",
            "missing field 'lattice'; add \"lattice\": \"fcc\"");
  one_error(copper_za(), [](case_json& m) { m["lattice"] = "hcp"; }, at + "lattice",
            "unknown lattice 'hcp'");
  one_error(copper_za(), [](case_json& m) { m["C1_Pa"] = 1e9; }, at + "C1_Pa", "unknown field 'C1_Pa'");
  one_error(copper_za(), [](case_json& m) { m["n"] = 0.3; }, at + "n", "unknown field 'n'");
  one_error(iron_za(), [](case_json& m) { m["C2_Pa"] = 890e6; }, at + "C2_Pa", "unknown field 'C2_Pa'");
  one_error(iron_za(), [](case_json& m) { m.erase("n"); }, "/bodies/0/material", "missing field 'n'; add \"n\": 0.289");
  one_error(iron_za(), [](case_json& m) { m.erase("C5_Pa"); }, "/bodies/0/material", "missing field 'C5_Pa'");
  one_error(copper_za(), [](case_json& m) { m.erase("C2_Pa"); }, "/bodies/0/material",
            "missing field 'C2_Pa'; add \"C2_Pa\": 890e6");
  one_error(copper_za(), [](case_json& m) { m["C2_Pa"] = -1e6; }, at + "C2_Pa", "-1e+06 must not be negative");
  one_error(copper_za(), [](case_json& m) { m["C0_Pa"] = "high"; }, at + "C0_Pa", "expected a number");
  one_error(copper_za(), [](case_json& m) { m["C3_1_K"] = -0.001; }, at + "C3_1_K", "must not be negative");
  one_error(copper_za(), [](case_json& m) { m["C4_1_K"] = -0.001; }, at + "C4_1_K", "must not be negative");
  one_error(iron_za(), [](case_json& m) { m["n"] = 0; }, at + "n", "0 must be positive; give e.g. 0.289");
  one_error(copper_za(), [](case_json& m) { m["C0_Pa"] = 0, m["C2_Pa"] = 0; }, at + "C0_Pa",
            "C0 and C2 are both 0");
  one_error(iron_za(), [](case_json& m) { m["C0_Pa"] = 0, m["C1_Pa"] = 0, m["C5_Pa"] = 0; }, at + "C0_Pa",
            "C0, C1 and C5 are all 0");
  one_error(copper_za(), [](case_json& m) { m["reference_strain_rate_1_s"] = 0; }, at + "reference_strain_rate_1_s",
            "must be positive");
  one_error(copper_za(), [](case_json& m) { m.erase("specific_heat_J_kgK"); }, "/bodies/0/material",
            "missing field 'specific_heat_J_kgK'");
  one_error(copper_za(), [](case_json& m) { m["taylor_quinney"] = 1.5; }, at + "taylor_quinney", "outside [0, 1]");
  one_error(copper_za(), [](case_json& m) { m.erase("initial_temperature_K"); }, "/bodies/0/material",
            "missing field 'initial_temperature_K'");
  one_error(copper_za(), [](case_json& m) { m["initial_temperature_K"] = -3; }, at + "initial_temperature_K",
            "must be positive");
  one_error(copper_za(), [](case_json& m) { m["melt_temperature_K"] = 250; }, at + "melt_temperature_K",
            "not above initial_temperature_K = 294 K");
  // A Johnson-Cook key is not a Zerilli-Armstrong one.
  one_error(copper_za(), [](case_json& m) { m["A_Pa"] = 90e6; }, at + "A_Pa", "unknown field 'A_Pa'");

  // The optional keys: left out, 1 /s, 0.9 and no melt.
  case_json bare = copper_za();
  for (const char* key : {"reference_strain_rate_1_s", "taylor_quinney", "melt_temperature_K"})
    bare["bodies"][0]["material"].erase(key);
  const auto d = test::load_document(bare);
  const auto& za = *d.bodies[0].material.zerilli_armstrong;
  CHECK(za.flow().reference_rate == 1.0);
  CHECK(za.heating().taylor_quinney == 0.9);
  CHECK(std::isinf(za.flow().melt_temperature));

  // Its temperature is a history; damage it has none.
  case_json failed = copper_za();
  failed["histories"].push_back({{"name", "failed_fraction"}, {"failed_fraction", {{"body", "bar"}}}});
  const std::string e = load_error(failed);
  CHECK(reports(e, "/histories/5/failed_fraction/body", "body 'bar' has no damage"));
  CHECK(lines(e) == 1);
}

}  // namespace test_unit_case_file_zerilli_armstrong
