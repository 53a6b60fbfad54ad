// The force loop's paired rows (solver/point_forces.hpp, point_traversal::paired_rows): on a body's
// mesh the points of a cell have the same neighbours (the search is by cell), and the traversal
// then gathers and scatters two points per visit of a neighbour. The pairs are found where they
// hold (Q2 and Q4) and nowhere else (one point per cell; a table whose paired points differ),
// and f comes out with the same bits as the point-by-point traversal, in both geometries and
// with the corrected test gradients of VCI, in batches of 2, 4 and 8 points.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include <rkpm/correction/polynomial_bases.hpp>
#include <rkpm/geometry/axisymmetric.hpp>
#include <rkpm/geometry/plane_strain.hpp>
#include <rkpm/kernel/cubic_spline.hpp>
#include <rkpm/quadrature/cell_rules.hpp>
#include <rkpm/quadrature/vci.hpp>
#include <rkpm/solver/discrete_model.hpp>
#include <rkpm/solver/point_forces.hpp>

namespace paired_rows_test {

using namespace rkpm;

template <class Q, class G>
discrete_model grid_model() {
  const vec2 lo(1e-3, 0.0), hi(5e-3, 3e-3);  // off the axis, for the axisymmetric hoop term
  const Eigen::Vector2i n(17, 13);
  return build_discrete_model<kernel::cubic_spline, correction::linear, Q, G>(make_grid_particles<2>(lo, hi, n, 2.0),
                                                                             make_grid_mesh(lo, hi, n));
}

// Positions x_I = X_I + a smooth displacement, so that every point's gradient differs.
std::vector<vec2> deformed(const discrete_model& m) {
  std::vector<vec2> x(m.particle_count());
  for (index_t I = 0; I < m.particle_count(); ++I) {
    const vec2& X = m.particles.position[I];
    x[I] = X + 1e-4 * vec2(std::sin(700.0 * X[1]) + 0.3, std::cos(900.0 * X[0]) * X[1] * 300.0);
  }
  return x;
}

// f of a rule that uses every component of the gradient and the value, W points at a time.
template <class G, int W>
std::vector<vec2> forces(const discrete_model& m, const std::vector<vec2>& x) {
  std::vector<vec2> f(m.particle_count());
  assemble_point_batches<G, W>(m, x, f, [&](index_t, index_t q, int n, const point_gradient* g, mat2* S, double* h) {
    for (int k = 0; k < n; ++k) {
      S[k] = (g[k].H * g[k].H.transpose() - mat2::Identity()) * (1e9 * m.points.weight[q + k]) + g[k].u * g[k].u.transpose();
      h[k] = 1e9 * (g[k].u[0] - m.points.position[q + k][0]) * m.points.weight[q + k];
    }
  });
  return f;
}

bool same_bits(const std::vector<vec2>& a, const std::vector<vec2>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(vec2)) == 0;
}

template <class Q, class G>
void check_same_forces() {
  discrete_model m = grid_model<Q, G>();
  REQUIRE(m.traversal.paired_rows);
  const std::vector<vec2> x = deformed(m);
  const std::vector<vec2> paired = forces<G, 4>(m, x);
  // Batches of the force loop's widths (2 lanes with the baseline flags, 4 with AVX2, 8 with
  // AVX-512), paired and not.
  CHECK(same_bits(paired, forces<G, 2>(m, x)));
  CHECK(same_bits(paired, forces<G, 8>(m, x)));
  m.traversal.paired_rows = false;
  CHECK(same_bits(paired, forces<G, 2>(m, x)));
  CHECK(same_bits(paired, forces<G, 4>(m, x)));
  CHECK(same_bits(paired, forces<G, 8>(m, x)));
  CHECK(same_bits(paired, forces<G, 1>(m, x)));  // a batch of one is never paired
  double largest = 0.0;
  for (const vec2& fI : paired) largest = std::max(largest, fI.norm());
  CHECK(largest > 1.0);  // the rule's forces are not all zero
}

TEST_CASE("paired rows: found for the points of a cell, not for one point per cell") {
  CHECK(grid_model<quadrature::q2, geometry::plane_strain>().traversal.paired_rows);
  CHECK(grid_model<quadrature::q4, geometry::plane_strain>().traversal.paired_rows);
  CHECK_FALSE(grid_model<quadrature::q1, geometry::plane_strain>().traversal.paired_rows);

  // Tiles of an odd size: the pairs start at each tile's first point, and still hold.
  const discrete_model m = grid_model<quadrature::q2, geometry::plane_strain>();
  CHECK_FALSE(make_point_traversal(m.at_points, m.particle_count(), 3).paired_rows);
  CHECK(make_point_traversal(m.at_points, m.particle_count(), 6).paired_rows);

  // A table whose second point of one cell lost a neighbour.
  discrete_model broken = grid_model<quadrature::q2, geometry::plane_strain>();
  shape_table<2>& t = broken.at_points;
  const index_t e = t.offset[1];
  t.neighbor.erase(t.neighbor.begin() + e);
  t.N.erase(t.N.begin() + e);
  t.grad.erase(t.grad.begin() + e);
  for (index_t q = 2; q <= t.points(); ++q) --t.offset[q];
  CHECK_FALSE(make_point_traversal(t, broken.particle_count()).paired_rows);
}

TEST_CASE("paired rows: the forces of the paired traversal have the bits of the point-by-point one") {
  check_same_forces<quadrature::q2, geometry::plane_strain>();
  check_same_forces<quadrature::q2, geometry::axisymmetric>();
  check_same_forces<quadrature::q4, geometry::axisymmetric>();
  check_same_forces<quadrature::vci<quadrature::q2>, geometry::axisymmetric>();
}

}  // namespace paired_rows_test
