// background_mesh and make_grid_mesh: node numbering shared with make_grid_particles, signed
// cell areas by the shoelace formula against hand values, boundary nodes of a grid, and the
// validation messages.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include <rkpm/discretization/background_mesh.hpp>
#include <rkpm/discretization/particle_set.hpp>

using namespace rkpm;

TEST_CASE("grid mesh: numbering, areas, boundary") {
  const vec2 lo(-1, 2), hi(3, 3.5);
  const Eigen::Vector2i n(5, 4);
  const auto m = make_grid_mesh(lo, hi, n);
  const auto p = make_grid_particles<2>(lo, hi, n, 2.0);
  REQUIRE(static_cast<index_t>(m.node.size()) == p.size());
  for (index_t i = 0; i < p.size(); ++i) CHECK((m.node[i] - p.position[i]).norm() < 1e-14);
  CHECK(m.cells() == 4 * 3);
  for (index_t c = 0; c < m.cells(); ++c) CHECK(m.cell_area(c) == doctest::Approx(1.0 * 0.5).epsilon(1e-14));
  CHECK(m.area() == doctest::Approx(4.0 * 1.5).epsilon(1e-14));
  CHECK_NOTHROW(m.validate());
  // Boundary of a 5 x 4 node grid: 2 * 5 + 2 * 2 = 14 nodes; interior nodes are 6, 7, 8, 11, 12, 13.
  const auto b = m.boundary_nodes();
  CHECK(b.size() == 14);
  for (index_t i : {6, 7, 8, 11, 12, 13}) CHECK(std::find(b.begin(), b.end(), i) == b.end());
  CHECK(std::is_sorted(b.begin(), b.end()));
}

TEST_CASE("shoelace area of a general quadrilateral and orientation") {
  background_mesh m;
  m.node = {vec2(0, 0), vec2(4, 0), vec2(3, 2), vec2(0, 3)};
  m.cell = {{0, 1, 2, 3}};
  // Split into triangles (0,1,2) and (0,2,3): 4 + 4.5.
  CHECK(m.cell_area(0) == doctest::Approx(8.5).epsilon(1e-15));
  m.cell = {{0, 3, 2, 1}};
  CHECK(m.cell_area(0) == doctest::Approx(-8.5).epsilon(1e-15));
  CHECK_THROWS_WITH_AS(m.validate(), doctest::Contains("counter-clockwise"), error);
  m.cell = {{0, 1, 2, 7}};
  CHECK_THROWS_WITH_AS(m.validate(), doctest::Contains("node 7"), error);
  m.cell.clear();
  CHECK_THROWS_WITH_AS(m.validate(), doctest::Contains("no cells"), error);
  CHECK_THROWS_WITH_AS(make_grid_mesh(vec2(0, 0), vec2(1, 1), Eigen::Vector2i(1, 3)), doctest::Contains("at least 2"),
                       error);
}

// boundary_edges() (counted in a sorted array since the map was the solver set-up's memory
// peak): on a 4 x 4-cell grid with the middle 2 x 2 cells removed, the outer square has 16
// edges and the hole 8, each an edge of exactly one cell, traversed as its cell traverses it.
TEST_CASE("boundary edges of a grid with a hole") {
  auto m = make_grid_mesh(vec2(0, 0), vec2(4, 4), Eigen::Vector2i(5, 5));
  std::erase_if(m.cell, [&](const auto& c) {
    const vec2 centre = 0.25 * (m.node[c[0]] + m.node[c[1]] + m.node[c[2]] + m.node[c[3]]);
    return centre[0] > 1 && centre[0] < 3 && centre[1] > 1 && centre[1] < 3;
  });
  REQUIRE(m.cells() == 12);
  const auto edges = m.boundary_edges();
  CHECK(edges.size() == 16 + 8);
  int outer = 0, hole = 0;
  for (const auto& [a, b] : edges) {
    const vec2 mid = 0.5 * (m.node[a] + m.node[b]);
    const bool on_outer = mid[0] == 0 || mid[0] == 4 || mid[1] == 0 || mid[1] == 4;
    const bool on_hole = std::max(std::abs(mid[0] - 2), std::abs(mid[1] - 2)) == 1;
    outer += on_outer;
    hole += on_hole;
    // The cell that has this side traverses it a -> b.
    int cells_with_side = 0;
    for (const auto& c : m.cell)
      for (int k = 0; k < 4; ++k) {
        cells_with_side += (c[k] == a && c[(k + 1) % 4] == b);
        CHECK_FALSE((c[k] == b && c[(k + 1) % 4] == a));
      }
    CHECK(cells_with_side == 1);
  }
  CHECK(outer == 16);
  CHECK(hole == 8);
}
