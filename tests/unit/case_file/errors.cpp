// Case files (tools/runner/case_file/load_case_file.hpp): every mistake is reported before
// anything is built, one line each naming the file, the JSON pointer of the field and the fix.
// Each test breaks the paper's Taylor bar file in one way (or a few, to see them all listed).
#include <doctest/doctest.h>

#include <algorithm>
#include <string>

#include "support/case_files.hpp"

namespace test_unit_case_file_errors {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;
using test::case_json;
using test::contains;
using test::reports;
using test::load_error;

namespace {

case_json taylor() { return test::paper_case_document("taylor_bar"); }

std::size_t lines(const std::string& message) {
  return message.empty() ? 0 : 1 + std::count(message.begin(), message.end(), '\n');
}

case_json polygon_taylor(const case_json& vertices) {
  case_json doc = taylor();
  doc["bodies"][0]["shape"] = {{"polygon", {{"vertices_m", vertices}, {"spacing_m", 1e-3}}}};
  doc["histories"][0]["extent"]["on_edge"] = "edge_0";
  return doc;
}

}  // namespace

TEST_CASE("the paper case files load as they are") {
  for (const char* name : {"taylor_bar", "block_forging", "wheel_forging"})
    CHECK(load_error(test::paper_case_document(name)) == "");
}

TEST_CASE("unreadable files and JSON syntax errors name the file and the place") {
  const std::string missing = test::error_message([] { runner::case_file::load_case_file("no/such/case.json"); });
  CHECK(contains(missing, "no/such/case.json: cannot read the case file (no such file)"));
  const auto path = test::write_case_text("{\"name\": \"x\",\n \"geometry\": }");
  const std::string syntax = test::error_message([&] { runner::case_file::load_case_file(path); });
  CHECK(contains(syntax, "case.json: not valid JSON: parse error at line 2"));
  const auto twice = test::write_case_text(taylor().dump(2).replace(1, 0, "\"end_time_s\": 1e-6,"));
  const std::string duplicate = test::error_message([&] { runner::case_file::load_case_file(twice); });
  CHECK(reports(duplicate, "/end_time_s", "given twice in this object; keep one"));
}

TEST_CASE("misspelt, unknown and missing fields: the closest known key is suggested") {
  case_json doc = taylor();
  auto& m = doc["bodies"][0]["material"];
  m["youngs_modulus_pa"] = m["youngs_modulus_Pa"];
  m.erase("youngs_modulus_Pa");
  doc["end_time"] = doc["end_time_s"];
  doc.erase("end_time_s");
  doc["tools"][0]["colour"] = "red";
  doc.erase("geometry");
  const std::string e = load_error(doc);
  CHECK(reports(e, "/bodies/0/material/youngs_modulus_pa", "did you mean 'youngs_modulus_Pa'?"));
  CHECK(reports(e, "/end_time", "did you mean 'end_time_s'?"));
  CHECK(reports(e, "/tools/0/colour", "unknown field 'colour'; the fields here are: name, polyline_m"));
  CHECK(reports(e, "(top level)", "missing field 'geometry'; add \"geometry\": \"plane_strain\""));
  // The misspelt keys are not reported missing a second time.
  CHECK(!contains(e, "missing field 'youngs_modulus_Pa'"));
  CHECK(!contains(e, "missing field 'end_time_s'"));
  CHECK(lines(e) == 4);
}

TEST_CASE("wrong types and values out of range") {
  case_json doc = taylor();
  auto& m = doc["bodies"][0]["material"];
  m["density_kg_m3"] = "heavy";
  m["youngs_modulus_Pa"] = 0;
  m["poisson_ratio"] = 0.5;
  m["yield_stress_Pa"] = -1;
  doc["bodies"][0]["shape"]["rectangle"]["particles"] = {21, 2.5};
  doc["support_factor"] = -2;
  doc["end_time_s"] = case_json::array({1});
  const std::string e = load_error(doc);
  CHECK(reports(e, "/bodies/0/material/density_kg_m3", "expected a number, got a string \"heavy\"; give e.g. 8930"));
  CHECK(reports(e, "/bodies/0/material/youngs_modulus_Pa", "0 must be positive; give e.g. 117e9"));
  CHECK(reports(e, "/bodies/0/material/poisson_ratio", "outside the open range (-1, 0.5)"));
  CHECK(reports(e, "/bodies/0/material/yield_stress_Pa", "-1 must be positive"));
  CHECK(reports(e, "/bodies/0/shape/rectangle/particles/1", "expected a whole number (a count), got the number 2.5"));
  CHECK(reports(e, "/support_factor", "must be positive"));
  CHECK(reports(e, "/end_time_s", "expected a number, got an array"));
  m["poisson_ratio"] = -1.0;
  CHECK(reports(load_error(doc), "/bodies/0/material/poisson_ratio", "outside the open range (-1, 0.5)"));
  case_json poly = polygon_taylor({{0, 0}, {1e-2, 0}, {0, 1e-2}});
  poly["bodies"][0]["shape"]["polygon"]["spacing_m"] = 0;
  CHECK(reports(load_error(poly), "/bodies/0/shape/polygon/spacing_m", "0 must be positive"));
  case_json layers = taylor();
  layers["bodies"][0]["slaves"] = {{"layers", 0}};
  CHECK(reports(load_error(layers), "/bodies/0/slaves/layers", "give at least 1"));
  layers["bodies"][0]["slaves"] = {{"layers", 2.5}};
  CHECK(reports(load_error(layers), "/bodies/0/slaves/layers", "whole number"));
}

TEST_CASE("unknown policy, law and choice names list the choices") {
  case_json doc = taylor();
  doc["method"]["quadrature"] = "q3";
  doc["method"]["kernel"] = "gaussian";
  doc["geometry"] = "axisymetric";
  doc["bodies"][0]["material"]["law"] = "elastoplastic";
  doc["tools"][0]["body_side"] = "above";
  const std::string e = load_error(doc);
  CHECK(reports(e, "/method/quadrature", "unknown quadrature 'q3'; did you mean 'q2'? (the choices are: q2, q4, q9"));
  CHECK(reports(e, "/method/kernel", "the choices are: cubic, quartic"));
  CHECK(reports(e, "/geometry", "did you mean 'axisymmetric'?"));
  CHECK(reports(e, "/bodies/0/material/law", "the choices are: elastic, j2"));
  CHECK(reports(e, "/tools/0/body_side", "the choices are: left, right"));
  // An elastic material has no yield stress.
  case_json elastic = taylor();
  elastic["bodies"][0]["material"]["law"] = "elastic";
  CHECK(reports(load_error(elastic), "/bodies/0/material/yield_stress_Pa", "unknown field 'yield_stress_Pa'"));
}

TEST_CASE("unknown edge, body and tool names") {
  case_json doc = taylor();
  doc["bodies"][0]["constraints"] = {{{"edge", "botom"}, {"velocity_m_s", {nullptr, 0}}}};
  doc["histories"][0]["extent"]["body"] = "rod";
  doc["histories"].push_back({{"name", "wall_force_N"}, {"tool_force", {{"tool", "wal"}}}});
  const std::string e = load_error(doc);
  CHECK(reports(e, "/bodies/0/constraints/0/edge", "body 'bar' has no edge 'botom'; did you mean 'bottom'?"));
  CHECK(reports(e, "/histories/0/extent/body", "no body 'rod'; the bodies are: bar"));
  CHECK(reports(e, "/histories/4/tool_force/tool", "no tool 'wal'; did you mean 'wall'?"));
}

TEST_CASE("bodies without area: degenerate rectangle, flat, crossed or clockwise polygon, r < 0") {
  case_json doc = taylor();
  doc["bodies"][0]["shape"]["rectangle"]["upper_right_m"] = {3.2e-3, 0};
  CHECK(reports(load_error(doc), "/bodies/0/shape/rectangle", "has no area"));
  const std::string at = "/bodies/0/shape/polygon/vertices_m";
  CHECK(reports(load_error(polygon_taylor({{0, 0}, {1e-2, 0}, {2e-2, 0}})), at, "no area"));
  CHECK(reports(load_error(polygon_taylor({{0, 0}, {1e-2, 1e-2}, {1e-2, 0}, {0, 1e-2}})), at,
                "the polygon crosses itself: edge_0 meets edge_2"));
  CHECK(reports(load_error(polygon_taylor({{0, 0}, {0, 1e-2}, {1e-2, 0}})), at,
                "the polygon is clockwise; give its vertices counter-clockwise"));
  CHECK(load_error(polygon_taylor({{0, 0}, {1e-2, 0}, {0, 1e-2}})) == "");
  CHECK(reports(load_error(polygon_taylor({{-1e-3, 0}, {1e-2, 0}, {0, 1e-2}})), "/bodies/0/shape",
                "the body reaches r = -0.001 < 0"));
}

TEST_CASE("a tool that starts inside the body; touching is allowed") {
  case_json doc = taylor();
  doc["tools"][0]["polyline_m"] = {{-3.2e-3, 1e-3}, {1e-3, 1e-3}};
  CHECK(reports(load_error(doc), "/tools/0/polyline_m/1", "tool 'wall' starts inside body 'bar': vertex 1"));
  doc["tools"][0]["polyline_m"] = {{-3.2e-3, 1e-3}, {25.6e-3, 1e-3}};
  CHECK(reports(load_error(doc), "/tools/0/polyline_m", "its segment 0 (vertices 0 to 1) crosses the body"));
  // Along the top edge and around the corner: touches only.
  doc["tools"][0]["polyline_m"] = {{-1e-3, 32.4e-3}, {3.2e-3, 32.4e-3}, {3.2e-3, 40e-3}};
  doc["tools"][0]["body_side"] = "right";
  CHECK(load_error(doc) == "");
}

TEST_CASE("a mesh file that does not exist") {
  case_json doc = taylor();
  doc["bodies"][0]["shape"] = {{"mesh", {{"file", "plate.msh"}}}};
  CHECK(reports(load_error(doc), "/bodies/0/shape/mesh/file", "mesh file 'plate.msh' does not exist"));
}

TEST_CASE("constraints, tool motions and histories that cannot mean anything") {
  case_json doc = taylor();
  doc["bodies"][0]["constraints"] = {{{"edge", "top"}, {"velocity_m_s", {nullptr, nullptr}}},
                                     {{"edge", "left"}, {"velocity_m_s", {0, nullptr}}}};
  doc["tools"][0]["motion"] = {{"type", "velocity_table"}, {"table", {{1e-6, 0, 1}, {1e-6, 0, 2}}}};
  doc["histories"][1]["tool_gap"] = {{"from", "wall"}, {"to", "wall"}};
  doc["histories"][2]["name"] = "radius_mm";
  const std::string e = load_error(doc);
  CHECK(reports(e, "/bodies/0/constraints/0/velocity_m_s", "both components are null, so this constrains nothing"));
  CHECK(reports(e, "/tools/0/motion/table/0/0", "start it at 0"));
  CHECK(reports(e, "/tools/0/motion/table/1/0", "give the rows in increasing time"));
  CHECK(reports(e, "/histories/1", "give exactly one kind of measure (found extent, tool_gap)"));
  CHECK(reports(e, "/histories/2/name", "the name 'radius_mm' is already taken"));
  // On the axis u_r = 0 is imposed already.
  case_json axis = taylor();
  axis["bodies"][0]["constraints"] = {{{"edge", "left"}, {"velocity_m_s", {0, nullptr}}}};
  CHECK(reports(load_error(axis), "/bodies/0/constraints/0/velocity_m_s", "lies on the axis"));
  case_json penalty = taylor();
  penalty["method"]["contact"] = "penalty";
  penalty["contact"].erase("penalty_stiffness_N_m");
  CHECK(reports(load_error(penalty), "/contact", "add \"penalty_stiffness_N_m\""));
}

TEST_CASE("--set overrides: a field the file has, a JSON value or a string") {
  using runner::case_file::override_list;
  const auto c = test::load_document(taylor(), override_list{{"/bodies/0/material/yield_stress_Pa", "3e8"},
                                                             {"/method/quadrature", "q4"},
                                                             {"/tools/0/polyline_m/1", "[3e-2, 0]"}});
  CHECK(std::get<material::hardening::linear>(c.bodies[0].material.flow_law.law).yield_stress == 3e8);
  CHECK(c.method.quadrature == "q4");
  CHECK(c.tools[0].polyline[1] == vec2(3e-2, 0.0));
  CHECK(c.document["bodies"][0]["material"]["yield_stress_Pa"] == 3e8);
  const std::string e = load_error(taylor(), override_list{{"/bodies/0/material/yeild_stress_Pa", "3e8"},
                                                           {"/bodies/2/name", "x"},
                                                           {"end_time_s", "1"},
                                                           {"/end_time_s/x", "1"}});
  CHECK(reports(e, "--set /bodies/0/material/yeild_stress_Pa",
                "/bodies/0/material has no field 'yeild_stress_Pa'; did you mean 'yield_stress_Pa'?"));
  CHECK(reports(e, "--set /bodies/2/name", "/bodies is a list of 1 entries; give an index from 0 to 0"));
  CHECK(reports(e, "--set end_time_s", "a JSON pointer starting with '/'"));
  CHECK(reports(e, "--set /end_time_s/x", "/end_time_s is the number 8e-05 and has no field 'x'"));
  // A value of the wrong kind is found by the checks, at its pointer.
  CHECK(reports(load_error(taylor(), override_list{{"/end_time_s", "soon"}}), "/end_time_s",
                "expected a number, got a string \"soon\""));
}

}  // namespace test_unit_case_file_errors

namespace test_unit_case_file_errors {

TEST_CASE("re-referencing keys: read, and refused with the fix when they cannot mean anything") {
  case_json doc = taylor();
  doc["rereference"] = {{"max_stretch", 1.8}};
  CHECK(test::load_document(doc).rereference.max_stretch == 1.8);
  doc["rereference"] = {{"every_steps", 50}};
  CHECK(test::load_document(doc).rereference.every_steps == 50);
  doc["rereference"] = {{"max_stretch", 0.9}};
  CHECK(reports(load_error(doc), "/rereference/max_stretch", "is not above 1"));
  doc["rereference"] = {{"every_steps", 0}};
  CHECK(reports(load_error(doc), "/rereference/every_steps", "give at least 1"));
  doc["rereference"] = case_json::object();
  CHECK(reports(load_error(doc), "/rereference", "give \"max_stretch\""));
  doc["rereference"] = {{"every_steps", 50}, {"rebalance_above", 1.25}};
  CHECK(test::load_document(doc).rereference.rebalance_above == 1.25);
  doc["rereference"] = {{"every_steps", 50}};
  CHECK(test::load_document(doc).rereference.rebalance_above == rereference_policy{}.rebalance_above);
  doc["rereference"] = {{"every_steps", 50}, {"rebalance_above", 0.9}};
  CHECK(reports(load_error(doc), "/rereference/rebalance_above", "is below 1"));
  doc["rereference"] = {{"max_strech", 1.8}};
  CHECK(contains(load_error(doc), "max_stretch"));
}

}  // namespace test_unit_case_file_errors

namespace test_unit_case_file_errors {

TEST_CASE("mass scaling keys: read, and refused with the fix when they cannot mean anything") {
  case_json doc = taylor();
  doc["mass_scaling"] = {{"factor", 100.0}};
  CHECK(test::load_document(doc).mass_scaling.factor == 100.0);
  doc["mass_scaling"] = {{"target_dt_s", 2e-6}, {"max_kinetic_to_internal", 0.1}};
  const auto read = test::load_document(doc).mass_scaling;
  CHECK(read.target_time_step == 2e-6);
  CHECK(read.max_kinetic_to_internal == 0.1);
  doc["mass_scaling"] = {{"factor", 0.5}};
  CHECK(reports(load_error(doc), "/mass_scaling/factor", "is below 1"));
  doc["mass_scaling"] = {{"target_dt_s", -1.0}};
  CHECK(reports(load_error(doc), "/mass_scaling/target_dt_s", "is not positive"));
  doc["mass_scaling"] = {{"factor", 10.0}, {"max_kinetic_to_internal", 0.0}};
  CHECK(reports(load_error(doc), "/mass_scaling/max_kinetic_to_internal", "is not positive"));
  doc["mass_scaling"] = {{"factor", 10.0}, {"target_dt_s", 1e-6}};
  CHECK(reports(load_error(doc), "/mass_scaling", "not both"));
  doc["mass_scaling"] = case_json::object();
  CHECK(reports(load_error(doc), "/mass_scaling", "give \"factor\""));
  doc["mass_scaling"] = {{"factr", 100.0}};
  CHECK(contains(load_error(doc), "factor"));
}

}  // namespace test_unit_case_file_errors

namespace test_unit_case_file_errors {

TEST_CASE("heat keys: read, and refused with the fix when they cannot mean anything") {
  case_json doc = taylor();
  doc["heat"] = {{"bodies", {{"bar", {{"conductivity_W_mK", 400.0}}}}},
                 {"tools", {{"wall", 300.0}}},
                 {"conductance_W_m2K", 1e4},
                 {"edges", case_json::array({{{"body", "bar"}, {"edge", "right"},
                                              {"convection", {{"h_W_m2K", 30.0}, {"ambient_K", 300.0}}}}})}};
  const auto read = test::load_document(doc).heat;
  CHECK(read.enabled);
  CHECK(read.bodies.at("bar").conductivity == 400.0);
  CHECK(read.tool_temperature.at("wall") == 300.0);
  CHECK(read.edges.at(0).kind == "convection");
  CHECK(read.edges.at(0).film_coefficient == 30.0);
  case_json bad = doc;
  bad["heat"]["bodies"]["bar"]["conductivity_W_mK"] = -1.0;
  CHECK(reports(load_error(bad), "/heat/bodies/bar/conductivity_W_mK", "is negative"));
  bad = doc;
  bad["heat"]["bodies"]["bar"]["taylor_quinney"] = 1.5;
  CHECK(reports(load_error(bad), "/heat/bodies/bar/taylor_quinney", "is not a fraction"));
  bad = doc;
  bad["heat"]["tools"]["wall"] = -5.0;
  CHECK(reports(load_error(bad), "/heat/tools/wall", "temperature in kelvin"));
  bad = doc;
  bad["heat"].erase("conductance_W_m2K");
  CHECK(reports(load_error(bad), "/heat", "conductance_W_m2K"));
  bad = doc;
  bad["heat"]["edges"][0]["temperature_K"] = 500.0;
  CHECK(reports(load_error(bad), "/heat/edges/0", "give one of"));
  bad = doc;
  bad["heat"]["friction_heat_to_body"] = 2.0;
  CHECK(reports(load_error(bad), "/heat/friction_heat_to_body", "is not a fraction"));
  bad = doc;
  bad["heat"]["bodys"] = 1;
  CHECK(contains(load_error(bad), "bodies"));
  // Expressions: k(T) and c_p(T) of the temperature, a tool's temperature of the time.
  case_json varying = doc;
  varying["heat"]["bodies"]["bar"] = {{"conductivity_W_mK", "30 + 0.01 * (T - 300)"},
                                      {"specific_heat_J_kgK", "2 * 300"}};
  varying["heat"]["tools"]["wall"] = "473 + 1000 * t";
  const auto h = test::load_document(varying).heat;
  CHECK(h.bodies.at("bar").conductivity_of_T == "30 + 0.01 * (T - 300)");
  CHECK(h.bodies.at("bar").specific_heat == 600.0);  // names no variable: the number
  CHECK(h.bodies.at("bar").specific_heat_of_T.empty());
  CHECK(h.tool_temperature_of_t.at("wall") == "473 + 1000 * t");
  bad = varying;
  bad["heat"]["bodies"]["bar"]["conductivity_W_mK"] = "30 + q * T";
  CHECK(reports(load_error(bad), "/heat/bodies/bar/conductivity_W_mK", "'q'"));
  bad = varying;
  bad["heat"]["tools"]["wall"] = "473 + T";  // a tool's temperature is of t, not T
  CHECK(reports(load_error(bad), "/heat/tools/wall", "'T'"));
}

}  // namespace test_unit_case_file_errors
