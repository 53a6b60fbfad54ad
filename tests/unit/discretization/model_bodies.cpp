// The bodies of a model (include/rkpm/discretization/model_bodies.hpp), found once from the
// cells: two grids side by side are two bodies, each particle, cell and quadrature point in the
// grid it came from; their surfaces are the grids' outlines (the axis left out in an
// axisymmetric section); particles that are not the mesh nodes have no surface of particles,
// and asking for one says why; overlapping bodies are refused (first_overlap, the test the
// case files use too).

#include <doctest/doctest.h>

#include <rkpm/discretization/model_bodies.hpp>
#include <rkpm/discretization/quadrature_points.hpp>
#include <rkpm/geometry/plane_strain.hpp>
#include <rkpm/quadrature/cell_rules.hpp>

#include "support/error_message.hpp"
#include "support/solver_fixtures.hpp"

using namespace rkpm;

namespace {

// Two grids: [0, 1] x [0, 1] (body 0) and [1, 3] x [0, 1] (body 1), touching along x = 1.
struct two_grids {
  particle_set<2> particles;
  background_mesh mesh;
  index_t first_count = 0;

  two_grids() {
    const Eigen::Vector2i n0(3, 3), n1(5, 3);
    append_body(particles, mesh, make_grid_particles<2>(vec2(0, 0), vec2(1, 1), n0, 2.0),
                make_grid_mesh(vec2(0, 0), vec2(1, 1), n0));
    first_count = particles.size();
    append_body(particles, mesh, make_grid_particles<2>(vec2(1, 0), vec2(3, 1), n1, 2.0),
                make_grid_mesh(vec2(1, 0), vec2(3, 1), n1));
  }
};

}  // namespace

TEST_CASE("model bodies: each particle, cell and point in the grid it came from") {
  const two_grids g;
  model_bodies b(g.particles.position, g.mesh, false);
  REQUIRE(b.count() == 2);
  CHECK(b.nodes_are_particles());
  for (index_t I = 0; I < g.particles.size(); ++I) CHECK(b.of_particle(I) == (I < g.first_count ? 0 : 1));
  CHECK(b.particles_of(0).size() == static_cast<std::size_t>(g.first_count));
  CHECK(b.particles_of(1).size() == static_cast<std::size_t>(g.particles.size() - g.first_count));
  for (index_t c = 0; c < g.mesh.cells(); ++c) CHECK(b.of_cell(c) == (c < 4 ? 0 : 1));

  const quadrature_points points = make_quadrature_points<quadrature::q4, geometry::plane_strain>(g.mesh);
  b.find_point_bodies(points);
  REQUIRE(b.point_body().size() == static_cast<std::size_t>(points.size()));
  for (index_t q = 0; q < points.size(); ++q) CHECK(b.of_point(q) == (points.position[q][0] < 1.0 ? 0 : 1));

  // Plane: each grid's outline is one closed chain of its own nodes, 8 and 12 boundary nodes.
  const auto& chains = b.surface("test");
  REQUIRE(chains.size() == 2);
  for (const auto& c : chains) {
    CHECK(c.closed);
    CHECK(c.node.size() == (c.body == 0 ? 8u : 12u));
    for (index_t n : c.node) CHECK(b.of_particle(n) == c.body);
  }
}

TEST_CASE("model bodies: one body keeps no table; the axis of a section is no surface") {
  const Eigen::Vector2i n(3, 4);
  const auto particles = make_grid_particles<2>(vec2(0, 0), vec2(1, 2), n, 2.0);
  const auto mesh = make_grid_mesh(vec2(0, 0), vec2(1, 2), n);
  const model_bodies b(particles.position, mesh, /*axisymmetric=*/true);
  CHECK(b.count() == 1);
  CHECK(b.particle_body().empty());
  CHECK(b.particle_body().capacity() == 0);  // let go, not only cleared
  CHECK(b.of_particle(5) == 0);
  CHECK(b.particles_of(0).size() == static_cast<std::size_t>(particles.size()));
  const auto& chains = b.surface("test");
  REQUIRE(chains.size() == 1);
  CHECK_FALSE(chains[0].closed);
  // From the axis round the outside back to the axis: 3 + 3 + 2 nodes, none inside.
  CHECK(chains[0].node.size() == 8u);
  CHECK(mesh.node[chains[0].node.front()][0] == 0.0);
  CHECK(mesh.node[chains[0].node.back()][0] == 0.0);
}

TEST_CASE("model bodies: particles that are not the nodes have no surface, and asking says why") {
  const Eigen::Vector2i n(3, 3);
  auto particles = make_grid_particles<2>(vec2(0, 0), vec2(1, 1), n, 2.0);
  particles.position[4] += vec2(0.1, 0.0);  // the middle particle off its node
  const auto mesh = make_grid_mesh(vec2(0, 0), vec2(1, 1), n);
  const model_bodies b(particles.position, mesh, false);
  CHECK(b.count() == 1);
  CHECK_FALSE(b.nodes_are_particles());
  const std::string e = test::error_message([&] { b.surface("tool vertices as slaves"); });
  CHECK(test::contains(e, "tool vertices as slaves"));
  CHECK(test::contains(e, "mesh nodes"));
}

TEST_CASE("model bodies: overlapping bodies are refused, touching ones are not") {
  two_grids g;
  CHECK(model_bodies(g.particles.position, g.mesh, false).count() == 2);
  index_t parts = 0;
  CHECK_FALSE(first_overlap(g.mesh, cell_bodies(g.mesh, &parts), parts));
  // The second grid moved 0.3 into the first (its cell centres then lie inside cells of it).
  for (index_t I = g.first_count; I < g.particles.size(); ++I) g.particles.position[I][0] -= 0.3;
  for (std::size_t k = 9; k < g.mesh.node.size(); ++k) g.mesh.node[k][0] -= 0.3;
  const auto overlap = first_overlap(g.mesh, cell_bodies(g.mesh, &parts), parts);
  REQUIRE(overlap);
  const std::string e = test::error_message([&] { model_bodies(g.particles.position, g.mesh, false); });
  CHECK(test::contains(e, "bodies 0 and 1 overlap"));
}
