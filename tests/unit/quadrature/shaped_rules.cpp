// q2_split and q2_tri (include/rkpm/quadrature/shaped_rules.hpp) against exact integrals and
// their documented placement. A centroid with its part's area integrates every linear
// function of X exactly over the part, so both rules are exact for 1, x, y on any cell
// (q2 is not, on a non-affine cell) and miss the quadratic moments; with the weight 2 pi R the
// volume of revolution is exact (Pappus) on any cell. Exact polygon moments come from Green's
// theorem on the straight edges, independently of the rules.

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include <rkpm/discretization/quadrature_points.hpp>
#include <rkpm/geometry/axisymmetric.hpp>
#include <rkpm/geometry/plane_strain.hpp>
#include <rkpm/quadrature/shaped_rules.hpp>

namespace test_unit_quadrature_shaped_rules {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

namespace {

// int_P x^a y^b dA by Green's theorem, Gauss-Legendre with 6 points on each edge (exact to
// degree 11 along an edge).
double polygon_moment(const std::vector<vec2>& p, int a, int b) {
  static const double x6[6] = {-0.9324695142031521, -0.6612093864662645, -0.2386191860831969,
                               0.2386191860831969,  0.6612093864662645,  0.9324695142031521};
  static const double w6[6] = {0.1713244923791704, 0.3607615730481386, 0.4679139345726910,
                               0.4679139345726910, 0.3607615730481386, 0.1713244923791704};
  double s = 0.0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const vec2 A = p[k], B = p[(k + 1) % p.size()];
    for (int g = 0; g < 6; ++g) {
      const vec2 X = 0.5 * (A + B) + 0.5 * x6[g] * (B - A);
      s += 0.5 * w6[g] * std::pow(X[0], a + 1) * std::pow(X[1], b) / (a + 1) * (B[1] - A[1]);
    }
  }
  return s;
}

background_mesh one_cell(std::vector<vec2> nodes) {
  background_mesh m;
  m.node = std::move(nodes);
  m.cell = {{0, 1, 2, 3}};
  return m;
}

template <class Q, class G = geometry::plane_strain>
double rule_moment(const background_mesh& m, int a, int b) {
  const auto qp = make_quadrature_points<Q, G>(m);
  double s = 0.0;
  for (index_t q = 0; q < qp.size(); ++q) s += qp.weight[q] * std::pow(qp.position[q][0], a) * std::pow(qp.position[q][1], b);
  return s;
}

const std::vector<vec2> distorted = {vec2(0.3, -0.2), vec2(2.1, 0.1), vec2(1.7, 1.9), vec2(-0.1, 1.2)};

template <class Q>
void check_exactness(const std::vector<vec2>& cell) {
  const auto m = one_cell(cell);
  const double area = polygon_moment(cell, 0, 0);
  for (int a = 0; a <= 2; ++a)
    for (int b = 0; a + b <= 2; ++b) {
      CAPTURE(a);
      CAPTURE(b);
      const double e = polygon_moment(cell, a, b), err = std::abs(rule_moment<Q>(m, a, b) - e) / (std::abs(e) + area);
      if (a + b <= 1) CHECK(err < 1e-14);
      else CHECK(err > 1e-4);  // one point per part cannot integrate a quadratic
    }
  // Pappus: 2 pi int r dA, whatever the cell's shape.
  CHECK(rule_moment<Q, geometry::axisymmetric>(m, 0, 0) ==
        doctest::Approx(2.0 * std::numbers::pi * polygon_moment(cell, 1, 0)).epsilon(1e-14));
}

}  // namespace

TEST_CASE("q2_split and q2_tri: exact for linear functions on any cell, Pappus in axisymmetry") {
  check_exactness<quadrature::q2_split>(distorted);
  check_exactness<quadrature::q2_tri>(distorted);
  const std::vector<vec2> elongated = {vec2(1.0, 0.0), vec2(1.16, 0.02), vec2(1.17, 0.66), vec2(0.99, 0.64)};
  check_exactness<quadrature::q2_split>(elongated);
  check_exactness<quadrature::q2_tri>(elongated);
}

TEST_CASE("q2_split halves the cell across its longer side") {
  using R = quadrature::q2_split;
  // Taylor-bar-like cell, 0.16 wide and 0.648 tall: the points lie one above the other.
  auto p = R::cell_points({vec2(0, 0), vec2(0.16, 0), vec2(0.16, 0.648), vec2(0, 0.648)});
  CHECK(p[0].position[0] == doctest::Approx(0.08));
  CHECK(p[1].position[0] == doctest::Approx(0.08));
  CHECK(p[0].position[1] == doctest::Approx(0.162));
  CHECK(p[1].position[1] == doctest::Approx(0.486));
  CHECK(p[0].area == doctest::Approx(0.5 * 0.16 * 0.648));
  CHECK(p[1].area == doctest::Approx(0.5 * 0.16 * 0.648));
  // The same cell lying down: side by side.
  p = R::cell_points({vec2(0, 0), vec2(0.648, 0), vec2(0.648, 0.16), vec2(0, 0.16)});
  CHECK(p[0].position[0] == doctest::Approx(0.162));
  CHECK(p[1].position[0] == doctest::Approx(0.486));
  CHECK(p[0].position[1] == doctest::Approx(0.08));
  // A square is cut across its first side x0-x1 (points side by side along it), also with its
  // corners rounded differently.
  for (double e : {0.0, 1e-15, -1e-15}) {
    p = R::cell_points({vec2(0, 0), vec2(1 + e, 0), vec2(1, 1 - e), vec2(0, 1)});
    CHECK(p[0].position[0] == doctest::Approx(0.25));
    CHECK(p[1].position[0] == doctest::Approx(0.75));
    CHECK(p[0].position[1] == doctest::Approx(0.5));
  }
}

TEST_CASE("q2_tri cuts along the shorter diagonal, inside the cell") {
  using R = quadrature::q2_tri;
  // Square: diagonal x0-x2 on the tie.
  auto p = R::cell_points({vec2(0, 0), vec2(1, 0), vec2(1, 1), vec2(0, 1)});
  CHECK((p[0].position - vec2(2.0 / 3.0, 1.0 / 3.0)).norm() < 1e-15);
  CHECK((p[1].position - vec2(1.0 / 3.0, 2.0 / 3.0)).norm() < 1e-15);
  // A rhombus whose diagonal x1-x3 is the shorter.
  p = R::cell_points({vec2(0, 0), vec2(2, -0.5), vec2(4, 0), vec2(2, 0.5)});
  CHECK((p[0].position - vec2(4.0 / 3.0, 0.0)).norm() < 1e-15);
  CHECK((p[1].position - vec2(8.0 / 3.0, 0.0)).norm() < 1e-15);
  // A non-convex cell (reflex corner x3): only x1-x3 cuts it inside, though it is the longer.
  const std::vector<vec2> dart = {vec2(0, 0), vec2(10, 0), vec2(1, 1), vec2(1, 0.5)};
  p = R::cell_points({dart[0], dart[1], dart[2], dart[3]});
  CHECK(p[0].area > 0.0);
  CHECK(p[1].area > 0.0);
  CHECK(p[0].area + p[1].area == doctest::Approx(one_cell(dart).area()).epsilon(1e-15));
  CHECK((p[0].position - (dart[0] + dart[1] + dart[3]) / 3.0).norm() < 1e-15);
}

TEST_CASE("a mesh of several cells: weights add up to the area; inverted cells are errors") {
  background_mesh m = make_grid_mesh(vec2(0, 0), vec2(3, 2), Eigen::Vector2i(4, 3));
  m.node[5] += vec2(0.2, -0.15);
  m.node[6] += vec2(-0.1, 0.2);
  for (auto* weights : {+[](const background_mesh& x) { return make_quadrature_points<quadrature::q2_split, geometry::plane_strain>(x); },
                        +[](const background_mesh& x) { return make_quadrature_points<quadrature::q2_tri, geometry::plane_strain>(x); }}) {
    const auto qp = weights(m);
    REQUIRE(qp.size() == 12);
    double s = 0.0;
    for (double w : qp.weight) s += w;
    CHECK(s == doctest::Approx(6.0).epsilon(1e-14));
    for (index_t q = 0; q < qp.size(); ++q) CHECK(qp.cell[q] == q / 2);
  }
  auto clockwise = one_cell({vec2(0, 0), vec2(0, 1), vec2(1, 1), vec2(1, 0)});
  CHECK_THROWS_WITH_AS((make_quadrature_points<quadrature::q2_tri, geometry::plane_strain>(clockwise)),
                       doctest::Contains("counter-clockwise"), error);
}

}  // namespace test_unit_quadrature_shaped_rules
