// Cracks in the approximation (discretization/crack_set.hpp, solver/crack_growth.hpp;
// docs/method.md section 3.7 and (112)-(113)), against geometry and the reproducing conditions:
//  - the crossing test: a sight line crosses a crack only through both, a point on the crack's
//    line is on one side (its left), not both;
//  - an edge crack half across a particle grid: no point's row reaches across it (checked with
//    the crack's coordinates, not its test), every row still reproduces the linear fields (sum N
//    = 1, sum N X = x, sum grad N = 0, sum grad N X^T = I), and coefficients that jump across
//    the crack give the jump exactly at points away from its tip (without the crack the RK
//    function smears it: the check then fails);
//  - a cell's cut through its centroid, and the segment on the cells' current corners;
//  - the pieces: a model cut all across by a crack holds two, of the masses of its halves.

#include <doctest/doctest.h>

#include <cmath>

#include <rkpm/approximation/rk_shape_functions.hpp>
#include <rkpm/discretization/crack_set.hpp>
#include <rkpm/discretization/shape_table.hpp>
#include <rkpm/geometry/plane_strain.hpp>
#include <rkpm/kernel/cubic_spline.hpp>
#include <rkpm/correction/polynomial_bases.hpp>
#include <rkpm/solver/crack_growth.hpp>
#include <rkpm/solver/make_model.hpp>

namespace test_unit_discretization_crack_set {  // compiled with its neighbours in one program

using namespace rkpm;

TEST_CASE("crack set: a sight line is blocked only by a crack it crosses") {
  const vec2 a(0.0, 0.0), b(1.0, 0.0);
  CHECK(crack_set::crosses(vec2(0.5, -1.0), vec2(0.5, 1.0), a, b));
  CHECK_FALSE(crack_set::crosses(vec2(1.5, -1.0), vec2(1.5, 1.0), a, b));  // past the crack's end
  CHECK_FALSE(crack_set::crosses(vec2(0.5, 0.2), vec2(0.5, 1.0), a, b));   // both on one side
  CHECK_FALSE(crack_set::crosses(vec2(-1.0, 0.0), vec2(2.0, 0.0), a, b));  // along it
  // A point on the crack's line is on its left (y >= 0 for a -> b along +x): seen from above,
  // hidden from below.
  CHECK_FALSE(crack_set::crosses(vec2(0.5, 0.0), vec2(0.5, 1.0), a, b));
  CHECK(crack_set::crosses(vec2(0.5, 0.0), vec2(0.5, -1.0), a, b));
  crack_set cracks(std::vector<crack_set::segment_type>{});  // none: the set a model without cracks gets
  CHECK_FALSE(cracks.blocks(vec2(0.5, -1.0), vec2(0.5, 1.0)));
  for (int k = 0; k < 20; ++k) cracks.add(vec2(3.0 * k, 5.0), vec2(3.0 * k + 1.0, 5.0));  // spread out: many bins
  cracks.add(a, b);
  CHECK(cracks.blocks(vec2(0.5, -1.0), vec2(0.5, 1.0)));
  CHECK(cracks.blocks(vec2(45.5, 4.0), vec2(45.5, 6.0)));
  CHECK_FALSE(cracks.blocks(vec2(47.5, 4.0), vec2(47.5, 6.0)));
  CHECK_FALSE(cracks.blocks(vec2(-3.0, 4.0), vec2(-2.0, 6.0)));  // outside the grid's box
}

namespace {

// An 11 x 11 particle grid on the unit square, support 2 h, and a crack along y = 0.45 (between
// two particle rows) from outside the left edge to x = 0.55.
constexpr double crack_y = 0.45, crack_tip = 0.55;
struct cracked_grid {
  particle_set<2> particles = make_grid_particles<2>(vec2(0, 0), vec2(1, 1), Eigen::Vector2i(11, 11), 2.0);
  crack_set cracks{{{vec2(-0.1, crack_y), vec2(crack_tip, crack_y)}}};
  std::vector<vec2> points;
  cracked_grid() {
    for (int j = 0; j < 20; ++j)
      for (int i = 0; i < 20; ++i) points.emplace_back(0.025 + 0.05 * i, 0.0237 + 0.05 * j);
  }
  shape_table<2> table(bool with_cracks) const {
    const neighbor_search<2> search(particles, with_cracks ? &cracks : nullptr);
    return build_shape_table<kernel::cubic_spline, correction::linear, 2>(search, points);
  }
};

}  // namespace

TEST_CASE("crack set: no row reaches across an edge crack, and each side reproduces the linear fields") {
  const cracked_grid g;
  const shape_table<2> t = g.table(true);
  double worst = 0.0;
  index_t across = 0;
  for (index_t p = 0; p < t.points(); ++p) {
    const vec2 x = g.points[p];
    double sum = 0.0;
    vec2 first = vec2::Zero(), grad = vec2::Zero();
    mat2 grad_first = mat2::Zero();
    for (index_t e = t.offset[p]; e < t.offset[p + 1]; ++e) {
      const vec2 X = g.particles.position[t.neighbor[e]];
      // The straight line from x to X crosses y = 0.45 left of the tip: across the crack.
      if ((x[1] - crack_y) * (X[1] - crack_y) < 0.0) {
        const double s = (crack_y - x[1]) / (X[1] - x[1]);
        if (x[0] + s * (X[0] - x[0]) < crack_tip) ++across;
      }
      sum += t.N[e];
      first += t.N[e] * X;
      grad += t.grad[e];
      grad_first += X * t.grad[e].transpose();
    }
    worst = std::max({worst, std::abs(sum - 1.0), (first - x).cwiseAbs().maxCoeff(), grad.cwiseAbs().maxCoeff(),
                      (grad_first - mat2::Identity()).cwiseAbs().maxCoeff()});
  }
  CHECK(across == 0);
  CHECK(worst < 1e-10);
}

TEST_CASE("crack set: coefficients that jump across the crack give the jump away from its tip") {
  const cracked_grid g;
  // d_I = 0 below the crack, 1 above: each side's rows reproduce its constant.
  std::vector<double> d(g.particles.size());
  for (index_t I = 0; I < g.particles.size(); ++I) d[I] = g.particles.position[I][1] > crack_y ? 1.0 : 0.0;
  const auto jump_error = [&](const shape_table<2>& t) {
    double worst = 0.0;
    for (index_t p = 0; p < t.points(); ++p) {
      const vec2 x = g.points[p];
      if (x[0] > crack_tip - 0.25) continue;  // within two supports of the tip the field bends round it
      worst = std::max(worst, std::abs(t.interpolate(p, d) - (x[1] > crack_y ? 1.0 : 0.0)));
    }
    return worst;
  };
  CHECK(jump_error(g.table(true)) < 1e-12);
  CHECK(jump_error(g.table(false)) > 0.1);  // an intact body smears the jump over a support
}

TEST_CASE("crack growth: a cell's cut runs through its centroid, normal to the crack normal") {
  background_mesh cells = make_grid_mesh(vec2(0, 0), vec2(2, 1), Eigen::Vector2i(3, 2));
  const auto cut = cut_cell(cells, 1, vec2(0, 1));  // cell 1 is [1, 2] x [0, 1]
  REQUIRE(cut);
  const auto [a, b] = crack_chord(cells, *cut, 0.0);
  CHECK(a[1] == doctest::Approx(0.5));
  CHECK(b[1] == doctest::Approx(0.5));
  CHECK(std::abs(a[0] - b[0]) == doctest::Approx(1.0));
  CHECK(std::min(a[0], b[0]) == doctest::Approx(1.0));
  // The cut moves with the cell's corners: stretched to twice the height, it is still halfway.
  for (vec2& x : cells.node) x[1] *= 2.0;
  const auto [c, d] = crack_chord(cells, *cut, 0.1);
  CHECK(c[1] == doctest::Approx(1.0));
  CHECK(std::abs(c[0] - d[0]) == doctest::Approx(1.2));  // lengthened by a tenth at each end
  // A normal at 45 degrees cuts the cell along its diagonal.
  const auto diagonal = cut_cell(make_grid_mesh(vec2(0, 0), vec2(1, 1), Eigen::Vector2i(2, 2)), 0,
                                 vec2(1, 1).normalized());
  REQUIRE(diagonal);
  const auto [e, f] = crack_chord(make_grid_mesh(vec2(0, 0), vec2(1, 1), Eigen::Vector2i(2, 2)), *diagonal, 0.0);
  CHECK((e - f).norm() == doctest::Approx(std::sqrt(2.0)));
}

TEST_CASE("crack growth: a model cut all across holds two pieces") {
  const Eigen::Vector2i n(9, 5);
  particle_set<2> particles = make_grid_particles<2>(vec2(0, 0), vec2(2, 1), n, 2.0);
  background_mesh cells = make_grid_mesh(vec2(0, 0), vec2(2, 1), n);
  const method_names method{"cubic", "linear", "q4"};
  const discrete_model whole = make_model<geometry::plane_strain>(method, particles, cells, default_max_moment_condition);
  const std::vector<double> mass = lumped_masses(whole, 1.0);
  CHECK(crack_fragments(whole, mass).pieces == 1);
  // Cut every cell of the column [1, 1.25] x [0, 1] across x (normal +x).
  std::vector<cell_crack> cuts;
  for (index_t c = 0; c < cells.cells(); ++c)
    if (std::abs(cells.node[cells.cell[c][0]][0] - 1.0) < 1e-12) cuts.push_back(*cut_cell(cells, c, vec2(1, 0)));
  REQUIRE(cuts.size() == 4);
  cells.cracks = cracks_on(cells, cuts);
  const discrete_model cut = make_model<geometry::plane_strain>(method, particles, cells, default_max_moment_condition);
  const fragment_count pieces = crack_fragments(cut, lumped_masses(cut, 1.0));
  CHECK(pieces.pieces == 2);
  // The halves [0, 1.125] and [1.125, 2] of a body of density 1: areas 1.125 and 0.875.
  CHECK(pieces.largest_mass == doctest::Approx(1.125).epsilon(1e-9));
}

}  // namespace test_unit_discretization_crack_set
