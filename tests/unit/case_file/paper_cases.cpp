// The paper case files (cases/*.json) build, field by field and exactly, the problems of the
// typed cases (cases/*.hpp) with their default parameters: particles, volumes, supports, cells,
// tools (vertices, side, depth, motion at a few times), constraints, initial velocity,
// material constants and hardening, contact numbers and slaves; at resolution 1 and 2.
// No solver is built here (tests/unit/case_file/taylor_bar_run.cpp runs one).
#include <doctest/doctest.h>

#include <rkpm/contact/particle_to_segment.hpp>

#include "cases/block_forging.hpp"
#include "cases/taylor_bar.hpp"
#include "cases/wheel_forging.hpp"
#include "support/case_files.hpp"
#include "tools/runner/case_file/build_problem.hpp"

namespace test_unit_case_file_paper_cases {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

namespace {

using contact_t = contact::particle_to_segment<contact::enforcement::penalty, contact::friction::coulomb>;

template <class TypedMaterial>
void check_material(const TypedMaterial& typed, const runner::case_file::material_type& file) {
  CHECK(file.constants().youngs_modulus == typed.constants().youngs_modulus);
  CHECK(file.constants().poisson_ratio == typed.constants().poisson_ratio);
  CHECK(file.constants().density == typed.constants().density);
  for (double eps : {0.0, 0.01, 0.3, 2.0}) {
    CHECK(file.hardening().flow_stress(eps) == typed.hardening().flow_stress(eps));
    CHECK(file.hardening().slope(eps) == typed.hardening().slope(eps));
  }
}

void check_tools(const std::vector<contact::rigid_tool>& typed, const std::vector<contact::rigid_tool>& file,
                 double end_time) {
  REQUIRE(file.size() == typed.size());
  for (std::size_t k = 0; k < typed.size(); ++k) {
    CAPTURE(typed[k].name());
    CHECK(file[k].name() == typed[k].name());
    CHECK(file[k].reference_vertices() == typed[k].reference_vertices());
    CHECK(file[k].body_side() == typed[k].body_side());
    CHECK(file[k].max_depth() == typed[k].max_depth());
    CHECK(file[k].reach() == typed[k].reach());
    for (double t : {0.0, 0.1 * end_time, 0.37 * end_time, end_time}) {
      CHECK(file[k].displacement(t) == typed[k].displacement(t));
      CHECK(file[k].velocity(t) == typed[k].velocity(t));
    }
  }
}

template <class Case>
void check_same_problem(const std::string& file_name, int resolution) {
  CAPTURE(file_name);
  CAPTURE(resolution);
  const typename Case::parameters params;
  const auto typed = Case::template build<contact_t>(params, resolution);
  const auto description = runner::case_file::load_case_file(test::paper_case_file(file_name));
  const auto file = runner::case_file::build_problem<contact_t>(description, resolution);

  CHECK(description.end_time == Case::end_time(params));
  CHECK(description.geometry == Case::geometry_type::name);
  CHECK(file.particles.position == typed.particles.position);
  CHECK(file.particles.volume == typed.particles.volume);
  CHECK(file.particles.support == typed.particles.support);
  CHECK(file.mesh.node == typed.mesh.node);
  CHECK(file.mesh.cell == typed.mesh.cell);
  check_material(typed.material, file.material);
  check_tools(typed.contact.tools(), file.contact.tools(), Case::end_time(params));
  CHECK(file.contact.friction().coefficient == typed.contact.friction().coefficient);
  CHECK(file.contact.enforcement().stiffness == typed.contact.enforcement().stiffness);
  REQUIRE(file.constraints.size() == typed.constraints.size());
  for (std::size_t r = 0; r < typed.constraints.size(); ++r) {
    CHECK(file.constraints[r].particle == typed.constraints[r].particle);
    CHECK(file.constraints[r].direction == typed.constraints[r].direction);
  }
  REQUIRE(bool(file.initial_velocity) == bool(typed.initial_velocity));
  if (typed.initial_velocity)
    for (const vec2& X : {typed.particles.position.front(), typed.particles.position.back(), vec2(1e-3, 2e-3)})
      CHECK(file.initial_velocity(X) == typed.initial_velocity(X));
  CHECK(file.body_force == typed.body_force);
  CHECK(file.slave_particles == typed.slave_particles);
}

}  // namespace

TEST_CASE("taylor_bar.json builds the typed Taylor bar") {
  check_same_problem<cases::taylor_bar>("taylor_bar", 1);
  check_same_problem<cases::taylor_bar>("taylor_bar", 2);
}

TEST_CASE("block_forging.json builds the typed block forging") {
  check_same_problem<cases::block_forging>("block_forging", 1);
  check_same_problem<cases::block_forging>("block_forging", 2);
}

TEST_CASE("wheel_forging.json builds the typed wheel forging") {
  check_same_problem<cases::wheel_forging>("wheel_forging", 1);
  check_same_problem<cases::wheel_forging>("wheel_forging", 2);
}

TEST_CASE("edge constraints: the particles of the edge, once per corner, held or moving") {
  auto doc = test::paper_case_document("block_forging");
  doc["bodies"][0]["constraints"] = {{{"edge", "bottom"}, {"velocity_m_s", {0, 0}}},
                                     {{"edge", "left"}, {"velocity_m_s", {0, nullptr}}},
                                     {{"edge", "top"}, {"velocity_m_s", {nullptr, -2.5}}}};
  const auto p = runner::case_file::build_problem<contact_t>(test::load_document(doc), 1);
  // 21 x 21 grid: bottom 21 x 2, left 20 more in x (the corner once), top 21 in y.
  REQUIRE(p.constraints.size() == 42 + 20 + 21);
  for (const auto& c : p.constraints) {
    const vec2 X = p.particles.position[c.particle];
    if (X.y() == 0.0) CHECK(!c.velocity);  // held
    else if (c.direction == 1) CHECK((X.y() == 0.5 && c.velocity(0.3) == -2.5));
    else CHECK((X.x() == -0.25 && !c.velocity));
  }
  doc["bodies"][0]["constraints"][1]["velocity_m_s"] = {1.0, nullptr};
  const std::string e = test::error_message(
      [&] { runner::case_file::build_problem<contact_t>(test::load_document(doc), 1); });
  CHECK(test::contains(e, "case.json: /bodies/0/constraints/1/velocity_m_s: edges 'bottom' and 'left' prescribe "
                          "different x velocities"));
}

TEST_CASE("a velocity table: linear velocity, its exact integral, constant after the last row") {
  auto doc = test::paper_case_document("block_forging");
  doc["tools"][1]["motion"] = {{"type", "velocity_table"}, {"table", {{0, 0, -10}, {1e-3, 0, -20}, {2e-3, 4, -20}}}};
  const auto p = runner::case_file::build_problem<contact_t>(test::load_document(doc), 1);
  const auto& tool = p.contact.tools()[1];
  CHECK(tool.velocity(0.5e-3).y() == doctest::Approx(-15.0));
  CHECK(tool.displacement(1e-3).y() == doctest::Approx(-15e-3));
  CHECK(tool.displacement(1.5e-3).x() == doctest::Approx(0.5 * 0.5e-3 * 2.0));
  CHECK(tool.displacement(3e-3).y() == doctest::Approx(-15e-3 - 20e-3 - 20e-3));
  CHECK(tool.velocity(5e-3) == vec2(4.0, -20.0));
  CHECK(tool.displacement(0.0) == vec2::Zero());
}

TEST_CASE("the runner's material: J2's state unless a body carries a temperature") {
  auto doc = test::paper_case_document("taylor_bar");
  CHECK(!runner::case_file::uses_johnson_cook_state(test::load_document(doc)));
  const auto j2 = runner::case_file::build_problem<contact_t, runner::case_file::j2_material>(test::load_document(doc), 1);
  CHECK(j2.material.hardening().yields());
  doc["bodies"][0]["material"] = {{"law", "johnson_cook"}, {"youngs_modulus_Pa", 124e9}, {"poisson_ratio", 0.34},
                                  {"density_kg_m3", 8960}, {"A_Pa", 90e6}, {"B_Pa", 292e6}, {"n", 0.31},
                                  {"C", 0.025}, {"reference_strain_rate_1_s", 1.0}, {"m", 1.09},
                                  {"room_temperature_K", 294}, {"melt_temperature_K", 1356},
                                  {"specific_heat_J_kgK", 383}};
  const auto description = test::load_document(doc);
  CHECK(runner::case_file::uses_johnson_cook_state(description));
  CHECK(runner::case_file::build_problem<contact_t>(description, 1).material.johnson_cook() != nullptr);
  const std::string e = test::error_message(
      [&] { runner::case_file::build_problem<contact_t, runner::case_file::j2_material>(description, 1); });
  CHECK(test::contains(e, "a body with a temperature or a damage (johnson_cook) was given a material without room for its state"));
}

TEST_CASE("elastic maps to J2 that never yields") {
  auto doc = test::paper_case_document("taylor_bar");
  auto& m = doc["bodies"][0]["material"];
  m = {{"law", "elastic"}, {"youngs_modulus_Pa", 117e9}, {"poisson_ratio", 0.35}, {"density_kg_m3", 8930}};
  const auto p = runner::case_file::build_problem<contact_t>(test::load_document(doc), 1);
  CHECK(!p.material.hardening().yields());
  CHECK(std::isinf(p.material.hardening().flow_stress(1.0)));
}

}  // namespace test_unit_case_file_paper_cases
