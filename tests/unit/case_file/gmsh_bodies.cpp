// Case-file bodies meshed by Gmsh (tools/runner/case_file/gmsh_bodies.hpp):
//   - a polygon is meshed at spacing / resolution; its edges edge_k carry constraints and
//     extents; a rectangle given as a polygon is the grid of the same spacing (as sets);
//   - a mesh file (made here by the gmsh executable from tests/data/gmsh/rectangle.geo) is
//     used as it is, its physical curves name the edges; a tool inside it, an unknown group, a
//     resolution above 1 and a file Gmsh cannot read are refused at their pointers.
#include <doctest/doctest.h>

#include <cstdlib>
#include <numeric>
#include <set>

#include <rkpm/contact/particle_to_segment.hpp>

#include "support/case_files.hpp"
#include "tools/runner/case_file/build_problem.hpp"

namespace test_unit_case_file_gmsh_bodies {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;
using test::case_json;
using test::contains;

namespace {

using contact_t = contact::particle_to_segment<contact::enforcement::paper, contact::friction::coulomb>;

// The block forging file with its body replaced by `shape`, its constraints and histories on
// `edge`, and its tools moved apart so that they clear any body below y = 0.5.
case_json block_with(const case_json& shape, const std::string& edge) {
  case_json doc = test::paper_case_document("block_forging");
  doc["bodies"][0]["shape"] = shape;
  doc["bodies"][0]["constraints"] = {{{"edge", edge}, {"velocity_m_s", {0, 0}}}};
  doc["histories"] = {{{"name", "edge_width_mm"}, {"extent", {{"body", "block"}, {"of", "width_x"}, {"on_edge", edge}}}}};
  return doc;
}

double total(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }

// The block [x0, x0 + 0.5] x [0, 0.5] as 11 x 11 nodes, written to the scratch folder.
std::filesystem::path rectangle_msh(double x0, const std::string& name) {
  const auto msh = test::case_scratch() / name;
  const std::string command = fmt::format(
      R"("{}" -2 -format msh41 -setnumber x0 {} -setnumber x1 {} -setnumber y0 0 -setnumber y1 0.5 )"
      R"(-setnumber nx 11 -setnumber ny 11 "{}/rectangle.geo" -o "{}" > "{}.log" 2>&1)",
      RKPM_TEST_GMSH_EXECUTABLE, x0, x0 + 0.5, RKPM_TEST_GMSH_DATA_DIR, msh.string(), msh.string());
  REQUIRE(std::system(command.c_str()) == 0);
  return msh;
}

}  // namespace

TEST_CASE("a polygon body: meshed at spacing / resolution, edges edge_k") {
  // An L: the block less its upper right quarter.
  const case_json L = {{"polygon", {{"vertices_m", {{-0.25, 0}, {0.25, 0}, {0.25, 0.25}, {0, 0.25}, {0, 0.5}, {-0.25, 0.5}}},
                                    {"spacing_m", 0.05}}}};
  const auto c = test::load_document(block_with(L, "edge_0"));
  const auto p1 = runner::case_file::build_problem<contact_t>(c, 1);
  const auto p2 = runner::case_file::build_problem<contact_t>(c, 2);
  CHECK(total(p1.particles.volume) == doctest::Approx(0.1875).epsilon(1e-12));
  CHECK(p1.mesh.area() == doctest::Approx(0.1875).epsilon(1e-12));
  CHECK(p2.particles.size() > 3 * p1.particles.size());
  // The bottom edge: its particles, each held in x and y.
  std::set<index_t> bottom;
  for (index_t I = 0; I < p1.particles.size(); ++I)
    if (std::abs(p1.particles.position[I].y()) <= 1e-12) bottom.insert(I);
  CHECK(bottom.size() >= 11);
  CHECK(p1.constraints.size() == 2 * bottom.size());
  for (const auto& k : p1.constraints) CHECK(bottom.count(k.particle) == 1);
}

TEST_CASE("a rectangle given as a polygon is the grid of the same spacing") {
  const case_json square = {{"polygon", {{"vertices_m", {{-0.25, 0}, {0.25, 0}, {0.25, 0.5}, {-0.25, 0.5}}},
                                         {"spacing_m", 0.025}}}};
  const auto p = runner::case_file::build_problem<contact_t>(test::load_document(block_with(square, "edge_3")), 1);
  const auto grid = test::paper_case_document("block_forging");
  const auto g = runner::case_file::build_problem<contact_t>(test::load_document(grid), 1);
  REQUIRE(p.particles.size() == g.particles.size());
  CHECK(p.mesh.cells() == g.mesh.cells());
  CHECK(total(p.particles.volume) == doctest::Approx(total(g.particles.volume)).epsilon(1e-12));
  CHECK(p.constraints.size() == 2 * 21);  // the left edge, x and y
}

TEST_CASE("a mesh file body: used as given, its physical curves are its edges") {
  const auto msh = rectangle_msh(-0.25, "rect.msh");
  case_json doc = block_with({{"mesh", {{"file", msh.filename().string()}}}}, "bottom");
  const auto c = test::load_document(doc);
  const auto p = runner::case_file::build_problem<contact_t>(c, 1);
  CHECK(p.particles.size() == 121);
  CHECK(p.mesh.cells() == 100);
  CHECK(p.constraints.size() == 2 * 11);
  for (const auto& k : p.constraints) CHECK(p.particles.position[k.particle].y() == doctest::Approx(0.0));
  const auto edge = runner::case_file::particles_on_edge(c.bodies[0], p.particles.position, "top");
  CHECK(edge.size() == 11);

  CHECK(contains(test::error_message([&] { runner::case_file::build_problem<contact_t>(c, 2); }),
                 "case.json: /bodies/0/shape/mesh/file: a mesh file is used as it is, so resolution 2 cannot refine it"));
  doc["bodies"][0]["constraints"][0]["edge"] = "botom";
  CHECK(contains(test::load_error(doc), "/bodies/0/constraints/0/edge: body 'block' has no edge 'botom'; did you "
                                        "mean 'bottom'? (its edges are: bottom, left, right, top)"));
  doc["bodies"][0]["constraints"][0]["edge"] = "bottom";
  doc["tools"][1]["polyline_m"] = {{0.65, 0.45}, {-0.65, 0.45}};
  CHECK(contains(test::load_error(doc), "/tools/1/polyline_m: tool 'top_tool' starts inside body 'block': its "
                                        "segment 0"));
  doc["tools"][1]["polyline_m"] = {{0.65, 0.5}, {0.1, 0.5}, {0.1, 0.3}};
  CHECK(contains(test::load_error(doc), "/tools/1/polyline_m/2: tool 'top_tool' starts inside body 'block': vertex 2"));
  // Axisymmetric, from r = 0: u_r = 0 on the axis is imposed already.
  doc["tools"][1]["polyline_m"] = {{0.65, 0.5}, {-0.65, 0.5}};
  doc["geometry"] = "axisymmetric";
  doc["bodies"][0]["shape"]["mesh"]["file"] = rectangle_msh(0.0, "rect_axis.msh").filename().string();
  doc["bodies"][0]["constraints"][0]["edge"] = "left";
  CHECK(contains(test::load_error(doc), "/bodies/0/constraints/0/velocity_m_s: edge 'left' lies on the axis"));
  test::write_case_text("not a mesh", "junk.msh");
  doc["bodies"][0]["shape"]["mesh"]["file"] = "junk.msh";
  CHECK(contains(test::load_error(doc), "case.json: /bodies/0/shape/mesh/file: cannot read"));
}

}  // namespace test_unit_case_file_gmsh_bodies
