// Surfaces from the cells (include/rkpm/discretization/boundary_chains.hpp): chains of boundary
// nodes against what the geometry says they must be. A chain's signed polygon area is the
// area it encloses (positive for the counter-clockwise outer boundary, negative for a hole),
// every step along a chain is an edge of exactly one cell, the axis of an axisymmetric
// section is no surface, separate bodies get separate chains, and cells that touch at a
// corner only are refused.

#include <doctest/doctest.h>

#include <set>

#include "support/error_message.hpp"
#include "support/solver_fixtures.hpp"

using namespace rkpm;

namespace {

double signed_area(const background_mesh& m, const boundary_chain& c) {
  double a = 0.0;
  for (std::size_t k = 0; k < c.node.size(); ++k) {
    const vec2& p = m.node[c.node[k]];
    const vec2& q = m.node[c.node[(k + 1) % c.node.size()]];
    a += p[0] * q[1] - q[0] * p[1];
  }
  return 0.5 * a;
}

// Every segment of the chain is a boundary edge, traversed as its cell traverses it.
bool follows_boundary_edges(const background_mesh& m, const boundary_chain& c) {
  std::set<std::array<index_t, 2>> edges;
  for (const auto& e : m.boundary_edges()) edges.insert(e);
  for (index_t s = 0; s < c.segments(); ++s)
    if (!edges.contains(c.segment(s))) return false;
  return true;
}

// The grid mesh with the cells for which `keep(i, j)` is false removed.
template <class Keep>
background_mesh grid_without(const vec2& lo, const vec2& hi, const Eigen::Vector2i& n, Keep keep) {
  background_mesh m = make_grid_mesh(lo, hi, n);
  std::vector<std::array<stored_index, 4>> kept;
  for (int j = 0; j + 1 < n[1]; ++j)
    for (int i = 0; i + 1 < n[0]; ++i)
      if (keep(i, j)) kept.push_back(m.cell[j * (n[0] - 1) + i]);
  m.cell = kept;
  return m;
}

}  // namespace

TEST_CASE("a rectangle's boundary is one counter-clockwise loop through its boundary nodes") {
  const background_mesh m = make_grid_mesh(vec2(0.5, 0.0), vec2(2.5, 1.5), Eigen::Vector2i(5, 4));
  const auto chains = boundary_chains(m);
  REQUIRE(chains.size() == 1);
  CHECK(chains[0].closed);
  CHECK(chains[0].node.size() == 2 * (4 + 3));
  CHECK(chains[0].segments() == 14);
  CHECK(signed_area(m, chains[0]) == doctest::Approx(3.0).epsilon(1e-14));
  CHECK(follows_boundary_edges(m, chains[0]));
}

TEST_CASE("the axis of an axisymmetric section is no surface: one open chain from the axis round to the axis") {
  const Eigen::Vector2i n(5, 4);
  const background_mesh m = make_grid_mesh(vec2(0.0, 0.0), vec2(2.0, 1.5), n);
  const auto chains = boundary_chains(m, [&](index_t i) { return m.node[i][0] < 1e-12; });
  REQUIRE(chains.size() == 1);
  const auto& c = chains[0];
  CHECK_FALSE(c.closed);
  // The loop's 14 nodes less the 2 inside the axis edges; 11 segments: bottom, side, top.
  CHECK(c.node.size() == 12);
  CHECK(c.segments() == 4 + 3 + 4);
  CHECK(m.node[c.node.front()].isApprox(vec2(0.0, 0.0)));
  CHECK(m.node[c.node.back()].isApprox(vec2(0.0, 1.5)));
  CHECK(follows_boundary_edges(m, c));
  for (index_t s = 0; s < c.segments(); ++s) {
    const auto [a, b] = c.segment(s);
    CHECK_FALSE((m.node[a][0] < 1e-12 && m.node[b][0] < 1e-12));
  }
}

TEST_CASE("a hole is a second, clockwise loop; separate bodies have separate chains") {
  const Eigen::Vector2i n(5, 5);
  // 4 x 4 cells of size 1 less the 2 x 2 in the middle: outer area 16, hole 4.
  const background_mesh ring =
      grid_without(vec2(0, 0), vec2(4, 4), n, [](int i, int j) { return !(i >= 1 && i <= 2 && j >= 1 && j <= 2); });
  const auto chains = boundary_chains(ring);
  REQUIRE(chains.size() == 2);
  std::vector<double> areas{signed_area(ring, chains[0]), signed_area(ring, chains[1])};
  std::sort(areas.begin(), areas.end());
  CHECK(areas[0] == doctest::Approx(-4.0));
  CHECK(areas[1] == doctest::Approx(16.0));
  for (const auto& c : chains) {
    CHECK(c.closed);
    CHECK(c.body == 0);
    CHECK(follows_boundary_edges(ring, c));
  }

  // Two rectangles in one mesh (the second's nodes after the first's).
  background_mesh two = make_grid_mesh(vec2(0, 0), vec2(1, 1), Eigen::Vector2i(3, 3));
  const background_mesh upper = make_grid_mesh(vec2(0, 1.5), vec2(2, 2.5), Eigen::Vector2i(4, 3));
  const auto offset = static_cast<index_t>(two.node.size());
  two.node.insert(two.node.end(), upper.node.begin(), upper.node.end());
  for (auto c : upper.cell) {
    for (auto& i : c) i += offset;
    two.cell.push_back(c);
  }
  index_t bodies = 0;
  const auto body_of_cell = cell_bodies(two, &bodies);
  CHECK(bodies == 2);
  CHECK(std::count(body_of_cell.begin(), body_of_cell.end(), 0) == 4);
  CHECK(std::count(body_of_cell.begin(), body_of_cell.end(), 1) == 6);
  const auto both = boundary_chains(two);
  REQUIRE(both.size() == 2);
  CHECK(both[0].body != both[1].body);
  for (const auto& c : both) CHECK(signed_area(two, c) == doctest::Approx(c.body == 0 ? 1.0 : 2.0));
}

TEST_CASE("cells that touch at a corner only are refused, naming the node") {
  // Two cells of a 3 x 3 grid on one diagonal: they share node 4 and no edge.
  const background_mesh m =
      grid_without(vec2(0, 0), vec2(2, 2), Eigen::Vector2i(3, 3), [](int i, int j) { return i == j; });
  const std::string e = test::error_message([&] { boundary_chains(m); });
  CHECK(e.find("node 4 at (1, 1)") != std::string::npos);
  CHECK(e.find("touch at a corner") != std::string::npos);
}

TEST_CASE("surface layers: the nodes within k cell layers of the surface, as the grid's index distance says") {
  // On an nx x ny grid the node (i, j) lies in layer 1 + min(i, j, nx-1-i, ny-1-j): layers
  // 1..k hold nx ny - (nx - 2k)(ny - 2k) nodes, those of layer k + 1 and beyond are inside.
  const Eigen::Vector2i n(9, 7);
  const background_mesh m = make_grid_mesh(vec2(0.0, 0.0), vec2(4.0, 3.0), n);
  for (int k = 1; k <= 4; ++k) {
    CAPTURE(k);
    const auto nodes = surface_layers(m, k);
    const int inner = std::max(0, n[0] - 2 * k) * std::max(0, n[1] - 2 * k);
    CHECK(static_cast<int>(nodes.size()) == n[0] * n[1] - inner);
    for (index_t v : nodes) {
      const int i = static_cast<int>(v % n[0]), j = static_cast<int>(v / n[0]);
      CHECK(std::min({i, j, n[0] - 1 - i, n[1] - 1 - j}) < k);
    }
    CHECK(std::is_sorted(nodes.begin(), nodes.end()));
  }
  // With the axis x = 0 no surface, the layers are counted from the other three sides.
  const auto axis = surface_layers(m, 2, [&](index_t v) { return m.node[v][0] < 1e-12; });
  std::size_t expected = 0;
  for (int j = 0; j < n[1]; ++j)
    for (int i = 0; i < n[0]; ++i) {
      // The axis nodes at the top and bottom rows are ends of the open chain.
      const int depth = std::min({j, n[0] - 1 - i, n[1] - 1 - j});
      expected += depth < 2 ? 1 : 0;
    }
  CHECK(axis.size() == expected);
  CHECK(test::error_message([&] { (void)surface_layers(m, 0); }).find("at least 1") != std::string::npos);
}
