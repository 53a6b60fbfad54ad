// read_gmsh_body and mesh_polygon against independent numbers. The gmsh executable meshes the
// .geo files of tests/data/gmsh into a scratch directory (ASCII and binary format 4.1):
// - a structured rectangle gives make_grid_particles' particles and make_grid_mesh's cells (as
//   sets, matched by position), the same lumped volumes of a discrete model, and its four sides;
// - a plate with a hole (clockwise from Gmsh) gives counter-clockwise cells whose area is the
//   plate's less the circular segments cut by the hole's chords, and groups that cover its boundary;
// - ASCII and binary files give the same body;
// - every refused mesh says which file and what to do.
// mesh_polygon: a rectangle in either orientation is the grid; a pentagon, a triangle and a dart are
// covered by quadrilaterals exactly (straight edges), with their edges as groups.

#include <doctest/doctest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include <rkpm/correction/polynomial_bases.hpp>
#include <rkpm/discretization/background_mesh.hpp>
#include <rkpm/discretization/particle_set.hpp>
#include <rkpm/geometry/plane_strain.hpp>
#include <rkpm/io/gmsh_mesh.hpp>
#include <rkpm/kernel/cubic_spline.hpp>
#include <rkpm/quadrature/cell_rules.hpp>
#include <rkpm/solver/discrete_model.hpp>

#include "support/error_message.hpp"

namespace test_unit_io_gmsh_mesh {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

namespace fs = std::filesystem;
using rkpm::index_t;
using rkpm::vec2;
using rkpm::io::gmsh_body;

namespace {

// The scratch directory, removed at exit.
const fs::path& scratch() {
  struct dir {
    fs::path path = fs::temp_directory_path() / fmt::format("rkpm_test_gmsh_{}", ::getpid());
    dir() { fs::create_directories(path); }
    ~dir() {
      std::error_code ec;
      fs::remove_all(path, ec);
    }
  };
  static const dir d;
  return d.path;
}

// scratch()/out, made by `gmsh <options> tests/data/gmsh/<geo> -o out`.
fs::path run_gmsh(const std::string& geo, const std::string& options, const std::string& out) {
  const fs::path msh = scratch() / out, log = scratch() / (out + ".log");
  const std::string command = fmt::format(R"("{}" {} "{}" -o "{}" > "{}" 2>&1)", RKPM_TEST_GMSH_EXECUTABLE,
                                          options, (fs::path(RKPM_TEST_GMSH_DATA_DIR) / geo).string(),
                                          msh.string(), log.string());
  if (std::system(command.c_str()) != 0 || !fs::exists(msh)) {
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    FAIL("gmsh failed: " << command << "\n" << text.str());
  }
  return msh;
}

// The rectangle of rectangle.geo: [0.1, 0.37] x [-0.2, 0.5], 10 x 8 nodes.
const vec2 rect_lo(0.1, -0.2), rect_hi(0.37, 0.5);
const Eigen::Vector2i rect_counts(10, 8);
const char* const rectangle_options =
    "-2 -setnumber x0 0.1 -setnumber y0 -0.2 -setnumber x1 0.37 -setnumber y1 0.5 -setnumber nx 10 -setnumber ny 8";
const double support_factor = 2.0;

// Made once per program: ASCII or binary MSH 4.1.
const fs::path& rectangle_msh(bool binary) {
  static const fs::path ascii =
      run_gmsh("rectangle.geo", fmt::format("{} -format msh41", rectangle_options), "rectangle.msh");
  static const fs::path bin =
      run_gmsh("rectangle.geo", fmt::format("{} -format msh41 -bin", rectangle_options), "rectangle_bin.msh");
  return binary ? bin : ascii;
}

const char* const plate_options = "-2 -setnumber L 1 -setnumber r 0.4 -setnumber h 0.05";

bool close(double a, double b, double rel) { return std::abs(a - b) <= rel * std::max(std::abs(a), std::abs(b)); }

// For each particle of `expected`, the particle of `body` at its position (within tol).
std::vector<index_t> match(const rkpm::particle_set<2>& expected, const rkpm::particle_set<2>& body, double tol) {
  std::vector<index_t> at(expected.size(), -1);
  for (index_t i = 0; i < expected.size(); ++i)
    for (index_t j = 0; j < body.size(); ++j)
      if ((expected.position[i] - body.position[j]).lpNorm<Eigen::Infinity>() <= tol) at[i] = j;
  return at;
}

// The body equals the grid body on [lo, hi] with counts nodes: particles matched by position,
// volumes, supports, and cells as node sets.
void check_is_grid(const gmsh_body& body, const vec2& lo, const vec2& hi, const Eigen::Vector2i& counts, double rel) {
  const auto grid = rkpm::make_grid_particles<2>(lo, hi, counts, support_factor);
  const auto cells = rkpm::make_grid_mesh(lo, hi, counts);
  REQUIRE(body.particles.size() == grid.size());
  REQUIRE(body.mesh.node.size() == cells.node.size());
  REQUIRE(body.mesh.cells() == cells.cells());
  const double extent = (hi - lo).maxCoeff();
  const auto at = match(grid, body.particles, rel * extent);
  REQUIRE(std::count(at.begin(), at.end(), -1) == 0);
  for (index_t i = 0; i < grid.size(); ++i) {
    CHECK(body.mesh.node[at[i]] == body.particles.position[at[i]]);
    CHECK(close(body.particles.volume[at[i]], grid.volume[i], rel));
    CHECK(close(body.particles.support[at[i]][0], grid.support[i][0], rel));
    CHECK(close(body.particles.support[at[i]][1], grid.support[i][1], rel));
  }
  std::set<std::array<rkpm::stored_index, 4>> expected, got;
  for (auto c : cells.cell) {
    for (auto& n : c) n = at[n];
    std::sort(c.begin(), c.end());
    expected.insert(c);
  }
  for (index_t c = 0; c < body.mesh.cells(); ++c) {
    CHECK(body.mesh.cell_area(c) > 0.0);
    auto sorted = body.mesh.cell[c];
    std::sort(sorted.begin(), sorted.end());
    got.insert(sorted);
  }
  CHECK(got == expected);
}

// Every node of the group lies on the segment a-b; its edges join nodes of the group.
void check_group_on(const gmsh_body& body, const std::string& name, const vec2& a, const vec2& b, std::size_t nodes) {
  INFO("group " << name);
  REQUIRE(body.node_groups.count(name) == 1);
  const auto& group = body.node_groups.at(name);
  CHECK(group.size() == nodes);
  CHECK(body.edge_groups.at(name).size() == nodes - 1);
  CHECK(std::is_sorted(group.begin(), group.end()));
  const vec2 t = (b - a).normalized();
  for (index_t i : group) {
    const vec2 d = body.particles.position[i] - a;
    CHECK(std::abs(d[0] * t[1] - d[1] * t[0]) <= 1e-12 * (b - a).norm());
  }
  for (const auto& e : body.edge_groups.at(name))
    for (index_t n : e) CHECK(std::binary_search(group.begin(), group.end(), n));
}

// The same body up to the 16 significant digits of Gmsh's ASCII files (binary keeps all 17).
void check_same(const gmsh_body& a, const gmsh_body& b) {
  CHECK(a.mesh.cell == b.mesh.cell);
  CHECK(a.node_groups == b.node_groups);
  CHECK(a.edge_groups == b.edge_groups);
  REQUIRE(a.particles.size() == b.particles.size());
  for (index_t i = 0; i < a.particles.size(); ++i) {
    CHECK((a.particles.position[i] - b.particles.position[i]).norm() <= 1e-15 * a.particles.position[i].norm());
    CHECK(close(a.particles.volume[i], b.particles.volume[i], 1e-13));
    CHECK((a.particles.support[i] - b.particles.support[i]).norm() <= 1e-13 * a.particles.support[i].norm());
  }
}

}  // namespace

TEST_CASE("structured rectangle: the grid body, its sides, ASCII = binary") {
  const auto body = rkpm::io::read_gmsh_body(rectangle_msh(false), support_factor);
  check_is_grid(body, rect_lo, rect_hi, rect_counts, 1e-12);
  // Node tags start with Gmsh's corner points: the compact numbering keeps tag order.
  CHECK(body.particles.position[0] == rect_lo);
  CHECK((body.particles.position[2] - rect_hi).norm() <= 1e-15);
  CHECK(body.node_groups.size() == 4);
  check_group_on(body, "bottom", rect_lo, vec2(rect_hi[0], rect_lo[1]), 10);
  check_group_on(body, "right", vec2(rect_hi[0], rect_lo[1]), rect_hi, 8);
  check_group_on(body, "top", rect_hi, vec2(rect_lo[0], rect_hi[1]), 10);
  check_group_on(body, "left", vec2(rect_lo[0], rect_hi[1]), rect_lo, 8);
  check_same(body, rkpm::io::read_gmsh_body(rectangle_msh(true), support_factor));
}

TEST_CASE("structured rectangle: the discrete model's lumped volumes are the grid's") {
  using namespace rkpm;
  auto build = [](particle_set<2> p, background_mesh m) {
    return build_discrete_model<kernel::cubic_spline, correction::linear, quadrature::q4, geometry::plane_strain>(
        std::move(p), std::move(m));
  };
  const auto body = io::read_gmsh_body(rectangle_msh(true), support_factor);
  const auto from_gmsh = build(body.particles, body.mesh);
  const auto grid = make_grid_particles<2>(rect_lo, rect_hi, rect_counts, support_factor);
  const auto from_grid = build(grid, make_grid_mesh(rect_lo, rect_hi, rect_counts));
  const auto at = match(grid, body.particles, 1e-12);
  for (index_t i = 0; i < grid.size(); ++i)
    CHECK(close(from_gmsh.lumped_volume[at[i]], from_grid.lumped_volume[i], 1e-12));
}

TEST_CASE("plate with a hole: counter-clockwise cells, area, groups, ASCII = binary") {
  const double L = 1.0, r = 0.4;
  const auto msh = run_gmsh("plate_with_hole.geo", fmt::format("{} -format msh41", plate_options), "plate.msh");
  const auto body = rkpm::io::read_gmsh_body(msh, 1.5);
  for (index_t c = 0; c < body.mesh.cells(); ++c) CHECK(body.mesh.cell_area(c) > 0.0);
  double volume = 0.0;
  for (double v : body.particles.volume) volume += v;
  CHECK(close(volume, body.mesh.area(), 1e-12));
  // The hole's nodes are on the circle; the mesh leaves out the circular segments of its chords:
  // area = L^2 - sum over hole segments of r^2 sin(dphi) / 2, and about L^2 - pi r^2 / 4.
  double inscribed = 0.0;
  for (const auto& [a, b] : body.edge_groups.at("hole")) {
    const vec2 &p = body.particles.position[a], &q = body.particles.position[b];
    CHECK(std::abs(p.norm() - r) <= 1e-12);
    inscribed += 0.5 * std::abs(p[0] * q[1] - p[1] * q[0]);
  }
  CHECK(close(volume, L * L - inscribed, 1e-12));
  const double exact = L * L - M_PI * r * r / 4;
  CHECK(volume > exact);
  CHECK(close(volume, exact, 1e-3));
  // Groups: the five boundary curves, which cover the boundary of the cells.
  CHECK(body.node_groups.size() == 5);
  // Straight sides of length / h segments (h = 0.05).
  check_group_on(body, "bottom", vec2(r, 0), vec2(L, 0), 13);
  check_group_on(body, "right", vec2(L, 0), vec2(L, L), 21);
  check_group_on(body, "top", vec2(L, L), vec2(0, L), 21);
  check_group_on(body, "left", vec2(0, L), vec2(0, r), 13);
  CHECK(body.node_groups.at("hole").size() == body.edge_groups.at("hole").size() + 1);
  std::set<index_t> on_groups;
  for (const auto& [name, nodes] : body.node_groups) on_groups.insert(nodes.begin(), nodes.end());
  const auto boundary = body.mesh.boundary_nodes();
  CHECK(on_groups == std::set<index_t>(boundary.begin(), boundary.end()));
  const auto bin =
      run_gmsh("plate_with_hole.geo", fmt::format("{} -format msh41 -bin", plate_options), "plate_bin.msh");
  check_same(body, rkpm::io::read_gmsh_body(bin, 1.5));
  // MSH 2.2 too (the format of older tools).
  const auto msh22 = run_gmsh("plate_with_hole.geo", fmt::format("{} -format msh22", plate_options), "plate22.msh");
  check_same(body, rkpm::io::read_gmsh_body(msh22, 1.5));
}

TEST_CASE("refused meshes name the file and the fix") {
  using rkpm::test::contains;
  using rkpm::test::error_message;
  auto read = [](const fs::path& p) { return error_message([&] { rkpm::io::read_gmsh_body(p, 2.0); }); };
  const fs::path missing = scratch() / "missing.msh";
  std::string m = read(missing);
  CHECK(contains(m, "'" + missing.string() + "' does not exist"));
  CHECK(contains(m, "gmsh -2 body.geo"));

  // Not MSH files: text, a .geo script (which Gmsh would parse), a truncated mesh.
  const fs::path text = scratch() / "not_a_mesh.msh";
  std::ofstream(text) << "this is not a mesh\n";
  const fs::path geo = fs::path(RKPM_TEST_GMSH_DATA_DIR) / "rectangle.geo";
  for (const fs::path& p : {text, geo}) {
    m = read(p);
    CHECK(contains(m, "cannot read '" + p.string() + "' as a Gmsh mesh (it does not begin with $MeshFormat)"));
    CHECK(contains(m, "give a .msh file written by Gmsh"));
  }
  const fs::path truncated = scratch() / "truncated.msh";
  {
    std::ifstream in(rectangle_msh(false));
    std::string whole((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(truncated) << whole.substr(0, whole.size() / 3);
  }
  m = read(truncated);
  CHECK(contains(m, "cannot read '" + truncated.string() + "' as a Gmsh mesh ("));
  CHECK(contains(m, "give a .msh file written by Gmsh"));

  // -1 saves only the curves.
  const fs::path curves = run_gmsh("rectangle.geo", "-1 -format msh41", "curves.msh");
  m = read(curves);
  CHECK(contains(m, "'" + curves.string() + "' has no 2D elements: mesh its surfaces (gmsh -2"));
  CHECK(contains(m, "Physical Surface"));

  const fs::path triangles = run_gmsh("triangles.geo", "-2 -format msh41", "triangles.msh");
  m = read(triangles);
  CHECK(contains(m, "'" + triangles.string() + "' has "));
  CHECK(contains(m, " triangles: rkpm needs quadrilateral cells; recombine them (Recombine Surface{...}; "
                    "or Mesh.RecombineAll = 1; in the .geo) and mesh again"));

  const fs::path second = run_gmsh("rectangle.geo", "-2 -order 2 -format msh41", "second_order.msh");
  m = read(second);
  CHECK(contains(m, "'" + second.string() + "' has second-order elements (Quadrilateral 9)"));
  CHECK(contains(m, "Mesh.ElementOrder = 1"));

  const fs::path tilted = run_gmsh("tilted.geo", "-2 -format msh41", "tilted.msh");
  m = read(tilted);
  CHECK(contains(m, "'" + tilted.string() + "': Gmsh node"));
  CHECK(contains(m, "has z != 0: rkpm bodies lie in the plane z = 0"));

  const fs::path stray = run_gmsh("stray_curve.geo", "-2 -format msh41", "stray.msh");
  m = read(stray);
  CHECK(contains(m, "'" + stray.string() + "': Gmsh node"));
  CHECK(contains(m, "is on a saved curve but in no quadrilateral"));
  CHECK(contains(m, "delete the stray curve"));

  CHECK(contains(error_message([&] { rkpm::io::read_gmsh_body(rectangle_msh(false), 0.0); }), "support factor 0"));
}

TEST_CASE("mesh_polygon: a rectangle is the grid, in either orientation") {
  // 0.9 x 0.7 at spacing 0.1: 9 x 7 cells, transfinite.
  const vec2 a(0.0, -0.2), b(0.9, -0.2), c(0.9, 0.5), d(0.0, 0.5);
  const auto ccw = rkpm::io::mesh_polygon({a, b, c, d}, 0.1, support_factor);
  check_is_grid(ccw, a, c, Eigen::Vector2i(10, 8), 1e-12);
  CHECK(ccw.node_groups.size() == 4);
  check_group_on(ccw, "edge_0", a, b, 10);
  check_group_on(ccw, "edge_1", b, c, 8);
  check_group_on(ccw, "edge_2", c, d, 10);
  check_group_on(ccw, "edge_3", d, a, 8);
  const auto cw = rkpm::io::mesh_polygon({a, d, c, b}, 0.1, support_factor);
  check_is_grid(cw, a, c, Eigen::Vector2i(10, 8), 1e-12);
  check_group_on(cw, "edge_0", a, d, 8);
  check_group_on(cw, "edge_1", d, c, 10);
}

TEST_CASE("mesh_polygon: a pentagon, a triangle, a dart; all quadrilaterals, exact area, edges") {
  const double h = 0.1;
  for (const std::vector<vec2>& polygon :
       {std::vector<vec2>{vec2(0, 0), vec2(1, 0), vec2(1.2, 0.6), vec2(0.5, 1.1), vec2(-0.1, 0.5)},
        std::vector<vec2>{vec2(0, 0), vec2(1, 0), vec2(0.3, 0.8)},
        std::vector<vec2>{vec2(0, 0), vec2(1, 0), vec2(0.4, 0.4), vec2(0, 1)}}) {  // not convex: not transfinite
    const std::size_t n = polygon.size();
    INFO(n << " vertices");
    const auto body = rkpm::io::mesh_polygon(polygon, h, 2.0);
    double area = 0.0;  // shoelace of the polygon
    for (std::size_t k = 0; k < n; ++k)
      area += 0.5 * (polygon[k][0] * polygon[(k + 1) % n][1] - polygon[(k + 1) % n][0] * polygon[k][1]);
    double volume = 0.0;
    for (double v : body.particles.volume) volume += v;
    CHECK(close(body.mesh.area(), area, 1e-12));
    CHECK(close(volume, area, 1e-12));
    for (index_t c = 0; c < body.mesh.cells(); ++c) CHECK(body.mesh.cell_area(c) > 0.0);
    // Cells of about h x h: the mean cell area within a factor 2 of h^2.
    CHECK(area / body.mesh.cells() > 0.5 * h * h);
    CHECK(area / body.mesh.cells() < 2.0 * h * h);
    REQUIRE(body.node_groups.size() == n);
    std::set<index_t> on_edges;
    for (std::size_t k = 0; k < n; ++k) {
      const vec2 &p = polygon[k], &q = polygon[(k + 1) % n];
      const auto& nodes = body.node_groups.at(fmt::format("edge_{}", k));
      check_group_on(body, fmt::format("edge_{}", k), p, q, nodes.size());
      CHECK(nodes.size() >= static_cast<std::size_t>((q - p).norm() / h));  // about length / h + 1
      CHECK(nodes.size() <= static_cast<std::size_t>(2.0 * (q - p).norm() / h) + 2);
      on_edges.insert(nodes.begin(), nodes.end());
    }
    const auto boundary = body.mesh.boundary_nodes();
    CHECK(on_edges == std::set<index_t>(boundary.begin(), boundary.end()));
  }
}

TEST_CASE("mesh_polygon: bad polygons") {
  using rkpm::test::contains;
  using rkpm::test::error_message;
  auto mesh = [](std::vector<vec2> v, double h) { return error_message([&] { rkpm::io::mesh_polygon(v, h, 2.0); }); };
  const vec2 a(0, 0), b(1, 0), c(1, 1);
  CHECK(contains(mesh({a, b}, 0.1), "2 vertices; a polygon needs at least 3"));
  CHECK(contains(mesh({a, b, c}, 0.0), "spacing 0 must be positive"));
  CHECK(contains(mesh({a, b, b, c}, 0.1), "vertex 1 is not finite or repeats the next one"));
  CHECK(contains(mesh({a, b, vec2(2, 0)}, 0.1), "zero area"));
  CHECK(contains(error_message([&] { rkpm::io::mesh_polygon({a, b, c}, 0.1, -1.0); }), "support factor -1"));
}

}  // namespace test_unit_io_gmsh_mesh
