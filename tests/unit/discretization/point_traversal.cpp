// point_traversal (discretization/point_traversal.hpp) on a real table: the shape functions of a
// 61 x 41 particle grid at its Q2 points (2,400 cells, 4,800 points, 38 tiles). The tiles partition the
// points; no two tiles of one parallel colour share a particle (what lets the force loop
// scatter a colour's tiles at once without atomics); the colouring is not trivial (several
// colours with several tiles each, so the check has pairs to check); for_each_tile visits every
// point once, colour by colour, on one thread and on two.

#include <doctest/doctest.h>

#include <algorithm>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include <rkpm/correction/polynomial_bases.hpp>
#include <rkpm/discretization/point_traversal.hpp>
#include <rkpm/discretization/quadrature_points.hpp>
#include <rkpm/discretization/shape_table.hpp>
#include <rkpm/geometry/plane_strain.hpp>
#include <rkpm/kernel/cubic_spline.hpp>
#include <rkpm/quadrature/cell_rules.hpp>

namespace {

using namespace rkpm;

struct grid_table {
  particle_set<2> particles;
  shape_table<2> table;
  grid_table() {
    const vec2 lo(0.0, 0.0), hi(6e-3, 4e-3);
    const Eigen::Vector2i n(61, 41);
    particles = make_grid_particles<2>(lo, hi, n, 2.0);
    const quadrature_points points = make_quadrature_points<quadrature::q2, geometry::plane_strain>(make_grid_mesh(lo, hi, n));
    const neighbor_search<2> search(particles);
    const rk_shape_functions<kernel::cubic_spline, correction::linear, 2> rk(default_max_moment_condition);
    table = build_shape_table<kernel::cubic_spline, correction::linear, 2>(search, points.position, rk);
  }
};

}  // namespace

TEST_CASE("point traversal: tiles of one colour share no particle, on a table with many tiles and colours") {
  const grid_table g;
  const index_t np = g.table.points();
  const point_traversal t = make_point_traversal(g.table, g.particles.size());
  REQUIRE(np == 4800);
  REQUIRE(t.tiles() == (np + traversal_tile_points - 1) / traversal_tile_points);
  REQUIRE(t.tile_start.back() == np);

  // Every tile in exactly one colour.
  std::vector<int> listed(t.tiles(), 0);
  for (index_t k : t.tile) ++listed[k];
  CHECK(std::ranges::all_of(listed, [](int c) { return c == 1; }));

  // No particle is a neighbour of points in two tiles of one parallel colour.
  std::vector<index_t> owner(g.particles.size());
  index_t pairs_checked = 0, shared = 0;
  for (index_t c = 0; c < t.serial_from; ++c) {
    std::ranges::fill(owner, -1);
    for (index_t k = t.colour_start[c]; k < t.colour_start[c + 1]; ++k) {
      const index_t tile = t.tile[k];
      for (index_t e = g.table.offset[t.tile_start[tile]]; e < g.table.offset[t.tile_start[tile + 1]]; ++e) {
        index_t& o = owner[g.table.neighbor[e]];
        if (o != -1 && o != tile && shared++ == 0)
          MESSAGE("tiles " << o << " and " << tile << " of colour " << c << " share particle " << g.table.neighbor[e]);
        o = tile;
      }
      pairs_checked += k - t.colour_start[c];
    }
  }
  CHECK(shared == 0);
  // The check is not empty: several parallel colours, and colours with several tiles.
  CHECK(t.serial_from == t.colours());
  CHECK(t.colours() >= 3);
  index_t fullest = 0;
  for (index_t c = 0; c < t.colours(); ++c) fullest = std::max(fullest, t.colour_start[c + 1] - t.colour_start[c]);
  CHECK(fullest >= 4);
  CHECK(pairs_checked >= t.tiles());

  // for_each_tile: every point once, a colour's tiles before the next colour's.
  const auto visits = [&](int threads) {
#ifdef _OPENMP
    omp_set_num_threads(threads);
#endif
    std::vector<int> seen(np, 0);
    std::vector<index_t> colour_of_tile(t.tiles());
    for (index_t c = 0; c < t.colours(); ++c)
      for (index_t k = t.colour_start[c]; k < t.colour_start[c + 1]; ++k) colour_of_tile[t.tile[k]] = c;
    std::vector<index_t> done(t.colours(), 0);  // tiles finished per colour
    bool in_order = true;
    t.for_each_tile([&](index_t tile, index_t first, index_t last) {
      const index_t c = colour_of_tile[tile];
      for (index_t q = first; q < last; ++q) ++seen[q];
#pragma omp critical(test_traversal_order)
      {
        in_order = in_order && first == t.tile_start[tile] && last == t.tile_start[tile + 1];
        for (index_t b = 0; b < c; ++b) in_order = in_order && done[b] == t.colour_start[b + 1] - t.colour_start[b];
        ++done[c];
      }
    });
    CHECK(in_order);
    return std::ranges::all_of(seen, [](int s) { return s == 1; });
  };
  CHECK(visits(1));
  CHECK(visits(2));
}
