// particles_from_mesh: on a regular grid it gives make_grid_particles' volumes and supports; on
// two distorted cells the tributary volumes (quarter cell areas) and per-node supports (widest
// edge components of the cells around the node) equal hand values; results scale with the
// mesh (mm instead of m); the volumes add up to the mesh area; bad input is an error.

#include <doctest/doctest.h>

#include <cmath>

#include <rkpm/discretization/mesh_particles.hpp>
#include <rkpm/discretization/background_mesh.hpp>
#include <rkpm/discretization/particle_set.hpp>

using rkpm::index_t;
using rkpm::vec2;

namespace {
bool close(double a, double b, double rel) { return std::abs(a - b) <= rel * std::abs(b); }
}  // namespace

TEST_CASE("regular grid: the same volumes and supports as make_grid_particles") {
  const vec2 lo(-1.0, 2.0), hi(3.0, 3.5);
  const Eigen::Vector2i n(9, 4);
  const double s = 1.7;
  const auto grid = rkpm::make_grid_particles<2>(lo, hi, n, s);
  const auto mesh = rkpm::make_grid_mesh(lo, hi, n);
  const auto p = rkpm::particles_from_mesh(mesh, s);
  REQUIRE(p.size() == grid.size());
  CHECK_NOTHROW(p.validate());
  for (index_t i = 0; i < p.size(); ++i) {
    CHECK(p.position[i] == grid.position[i]);
    CHECK(close(p.volume[i], grid.volume[i], 1e-12));
    CHECK(close(p.support[i][0], grid.support[i][0], 1e-12));
    CHECK(close(p.support[i][1], grid.support[i][1], 1e-12));
  }
}

TEST_CASE("two distorted cells: hand values, total, scale") {
  // Cell 0: (0,0) (4,0) (3,2) (0,3), area 8.5, edges (4,0) (-1,2) (-3,1) (0,-3): widest (4, 3).
  // Cell 1: (4,0) (6,0) (6,2) (3,2), area 5 (trapezoid), edges (2,0) (0,2) (-3,0) (1,-2): widest (3, 2).
  rkpm::background_mesh mesh;
  mesh.node = {vec2(0, 0), vec2(4, 0), vec2(3, 2), vec2(0, 3), vec2(6, 0), vec2(6, 2)};
  mesh.cell = {{0, 1, 2, 3}, {1, 4, 5, 2}};
  const double s = 2.0;
  const auto p = rkpm::particles_from_mesh(mesh, s);
  REQUIRE(p.size() == 6);
  const double volume[] = {8.5 / 4, 13.5 / 4, 13.5 / 4, 8.5 / 4, 5.0 / 4, 5.0 / 4};
  const vec2 widest[] = {vec2(4, 3), vec2(4, 3), vec2(4, 3), vec2(4, 3), vec2(3, 2), vec2(3, 2)};
  double total = 0.0;
  for (index_t i = 0; i < 6; ++i) {
    CHECK(p.volume[i] == doctest::Approx(volume[i]).epsilon(1e-15));
    CHECK(p.support[i][0] == doctest::Approx(s * widest[i][0]).epsilon(1e-15));
    CHECK(p.support[i][1] == doctest::Approx(s * widest[i][1]).epsilon(1e-15));
    total += p.volume[i];
  }
  CHECK(total == doctest::Approx(mesh.area()).epsilon(1e-15));

  // The same body in millimetres: volumes x 1e6, supports x 1e3.
  auto mm = mesh;
  for (auto& x : mm.node) x *= 1e3;
  const auto q = rkpm::particles_from_mesh(mm, s);
  for (index_t i = 0; i < 6; ++i) {
    CHECK(close(q.volume[i], 1e6 * p.volume[i], 1e-14));
    CHECK(close(q.support[i][0], 1e3 * p.support[i][0], 1e-14));
    CHECK(close(q.support[i][1], 1e3 * p.support[i][1], 1e-14));
  }
}

TEST_CASE("errors: unused node, support factor, clockwise cell") {
  rkpm::background_mesh mesh;
  mesh.node = {vec2(0, 0), vec2(1, 0), vec2(1, 1), vec2(0, 1), vec2(5, 5)};
  mesh.cell = {{0, 1, 2, 3}};
  CHECK_THROWS_WITH_AS(rkpm::particles_from_mesh(mesh, 2.0),
                       doctest::Contains("node 4 at (5, 5) is a corner of no cell; remove it"), rkpm::error);
  mesh.node.pop_back();
  CHECK_NOTHROW(rkpm::particles_from_mesh(mesh, 2.0));
  CHECK_THROWS_WITH_AS(rkpm::particles_from_mesh(mesh, 0.0), doctest::Contains("support factor 0"), rkpm::error);
  mesh.cell = {{0, 3, 2, 1}};
  CHECK_THROWS_WITH_AS(rkpm::particles_from_mesh(mesh, 2.0), doctest::Contains("counter-clockwise"), rkpm::error);
}
