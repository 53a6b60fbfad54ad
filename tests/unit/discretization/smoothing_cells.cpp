// Smoothing cells of nodal integration (include/rkpm/discretization/smoothing_cells.hpp,
// docs/method.md (19d)-(19g)): the median dual cells of the mesh nodes tile the body, their
// points sit at the centroids with weights A omega(centroid) (the volume of revolution by
// Pappus), and the smoothed gradients reproduce linear fields exactly at every point, constants
// included, in both geometries and for any stabilization (the hoop term at the centroid is what
// makes the axisymmetric ones exact). A non-convex cell whose dual part would be inverted is
// reported with the node and the cell.

#include <doctest/doctest.h>

#include <numbers>

#include "support/solver_fixtures.hpp"

using namespace rkpm;

namespace {

using K = kernel::cubic_spline;
using C = correction::linear;

struct body {
  particle_set<2> particles;
  background_mesh mesh;
};

body jittered(bool on_axis) {
  const Eigen::Vector2i n(7, 6);
  const vec2 lo(on_axis ? 0.0 : 0.4, 0.1), hi(lo[0] + 1.2, 1.1);
  body b{make_grid_particles<2>(lo, hi, n, 2.0), make_grid_mesh(lo, hi, n)};
  test::distort_interior(b.particles, b.mesh, vec2(0.2, 0.2), 0.2);
  return b;
}

template <class G>
void check_tiling(const body& b) {
  const smoothing_cells s = make_smoothing_cells(b.mesh);
  CHECK(s.parts() == 4 * b.mesh.cells());
  for (bool per_part : {false, true}) {
    const nodal_points np = make_nodal_points<G>(s, per_part);
    CHECK(np.points.size() == (per_part ? s.parts() : static_cast<index_t>(b.mesh.node.size())));
    double area = 0.0, exact = 0.0;
    for (index_t q = 0; q < np.points.size(); ++q) area += np.points.weight[q];
    for (index_t c = 0; c < b.mesh.cells(); ++c) {
      const auto& n = b.mesh.cell[c];
      const cell_point p = quadrature::detail::polygon_centroid<4>(
          {b.mesh.node[n[0]], b.mesh.node[n[1]], b.mesh.node[n[2]], b.mesh.node[n[3]]});
      exact += p.area * G::weight_factor(p.position);
    }
    CHECK(area == doctest::Approx(exact).epsilon(1e-13));
  }
}

template <class G>
void check_linear(const body& b, double beta) {
  const discrete_model m = build_nodal_model<K, C, G>(b.particles, b.mesh, beta, 3);
  mat2 A;
  A << 0.3, -0.7, 0.45, 0.2;
  const vec2 a(0.11, -0.05);
  std::vector<vec2> d(m.particle_count());
  for (index_t I = 0; I < m.particle_count(); ++I) d[I] = A * m.particles.position[I] + a;
  double worst = 0.0;
  for (index_t q = 0; q < m.point_count(); ++q) {
    mat2 H = mat2::Zero();
    vec2 u = vec2::Zero();
    for (index_t e = m.at_points.offset[q]; e < m.at_points.offset[q + 1]; ++e) {
      H += d[m.at_points.neighbor[e]] * m.at_points.grad[e].transpose();
      u += m.at_points.N[e] * d[m.at_points.neighbor[e]];
    }
    worst = std::max(worst, (H - A).cwiseAbs().maxCoeff());
    worst = std::max(worst, (u - A * m.points.position[q] - a).cwiseAbs().maxCoeff());
  }
  CAPTURE(G::name);
  CAPTURE(beta);
  CHECK(worst < 1e-12);
}

}  // namespace

TEST_CASE("smoothing cells tile the body; points at the centroids weigh its volume") {
  check_tiling<geometry::plane_strain>(jittered(false));
  check_tiling<geometry::axisymmetric>(jittered(true));
}

TEST_CASE("smoothed gradients reproduce linear fields at every point, any stabilization") {
  test::run_serially();
  for (double beta : {0.0, 0.3, 1.0}) {
    check_linear<geometry::plane_strain>(jittered(false), beta);
    check_linear<geometry::axisymmetric>(jittered(true), beta);
  }
}

TEST_CASE("a cell too far from convex is reported with its node") {
  // A dart: valid (area 4, counter-clockwise) but with a reflex corner at (1, 1), beyond which
  // the cell's centre lies, so that corner's part is inverted.
  background_mesh m;
  m.node = {vec2(0, 0), vec2(4, 0), vec2(1, 1), vec2(0, 4)};
  m.cell = {{0, 1, 2, 3}};
  const smoothing_cells s = make_smoothing_cells(m);
  CHECK_THROWS_WITH_AS(make_nodal_points<geometry::plane_strain>(s, true),
                       doctest::Contains("not convex enough for nodal integration"), error);
}
