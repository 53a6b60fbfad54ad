// Quadrature rules and points against exact integrals.
// On [-1, 1]^2: q9 is exact to degree 5 per variable, q4 to degree 3, q2 (the diagonal Gauss
// pair) for 1, xi, eta, xi^2, eta^2, every cubic and xi^2 eta^2, but not xi*eta (it gives 4/3
// instead of 0). On a cell with a bilinear map, int p(X) dA = int p(X(xi)) det J(xi) dxi with
// det J linear in (xi, eta) and X bilinear, so a monomial of degree k in X is a polynomial of
// degree k+1 per variable: q4 is exact for k <= 2, q9 for k <= 4, q2 only for k = 0. Exact
// polygon moments come from Green's theorem on the straight edges (independent of the rules).
// Axisymmetric weights carry 2 pi R: their sum is the volume of revolution 2 pi A r_c (Pappus).

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include <rkpm/discretization/quadrature_points.hpp>
#include <rkpm/quadrature/cell_rules.hpp>
#include <rkpm/geometry/axisymmetric.hpp>
#include <rkpm/geometry/plane_strain.hpp>

using namespace rkpm;

namespace {

double ref_exact(int a, int b) {
  auto m = [](int k) { return k % 2 ? 0.0 : 2.0 / (k + 1); };
  return m(a) * m(b);
}

template <class Q>
double ref_rule(int a, int b) {
  double s = 0.0;
  for (const auto& [xi, eta, w] : Q::rule) s += w * std::pow(xi, a) * std::pow(eta, b);
  return s;
}

// Exact int_P x^a y^b dA over a polygon by Green's theorem with Gauss-Legendre on each edge
// (the edge integrand x^(a+1) y^b dy is a polynomial of degree a+b+1 <= 9 along the edge;
// 6 points are exact to degree 11).
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
      // int x^(a+1) y^b / (a+1) dy along the edge
      s += 0.5 * w6[g] * std::pow(X[0], a + 1) * std::pow(X[1], b) / (a + 1) * (B[1] - A[1]);
    }
  }
  return s;
}

template <class Q, class G = geometry::plane_strain>
double rule_moment(const background_mesh& m, int a, int b) {
  const auto qp = make_quadrature_points<Q, G>(m);
  double s = 0.0;
  for (index_t q = 0; q < qp.size(); ++q) s += qp.weight[q] * std::pow(qp.position[q][0], a) * std::pow(qp.position[q][1], b);
  return s;
}

background_mesh one_cell(std::vector<vec2> nodes) {
  background_mesh m;
  m.node = std::move(nodes);
  m.cell = {{0, 1, 2, 3}};
  return m;
}

// A strongly non-affine (trapezoid-like, no parallel sides) convex quadrilateral.
const std::vector<vec2> distorted = {vec2(0.3, -0.2), vec2(2.1, 0.1), vec2(1.7, 1.9), vec2(-0.1, 1.2)};

}  // namespace

TEST_CASE("reference square: weights sum to 4 and the documented exactness") {
  CHECK(ref_rule<quadrature::q1>(0, 0) == doctest::Approx(4.0).epsilon(1e-15));
  CHECK(ref_rule<quadrature::q2>(0, 0) == doctest::Approx(4.0).epsilon(1e-15));
  CHECK(ref_rule<quadrature::q4>(0, 0) == doctest::Approx(4.0).epsilon(1e-15));
  CHECK(ref_rule<quadrature::q9>(0, 0) == doctest::Approx(4.0).epsilon(1e-15));
  for (int a = 0; a <= 6; ++a)
    for (int b = 0; b <= 6; ++b) {
      CAPTURE(a);
      CAPTURE(b);
      const double e = ref_exact(a, b);
      const bool q9_exact = a <= 5 && b <= 5, q4_exact = a <= 3 && b <= 3;
      // Symmetric rules integrate odd monomials exactly; the even ones beyond the degree fail.
      const bool even = a % 2 == 0 && b % 2 == 0;
      if (q9_exact || !even) CHECK(std::abs(ref_rule<quadrature::q9>(a, b) - e) < 1e-14);
      else CHECK(std::abs(ref_rule<quadrature::q9>(a, b) - e) > 1e-6);
      if (q4_exact || !even) CHECK(std::abs(ref_rule<quadrature::q4>(a, b) - e) < 1e-14);
      else CHECK(std::abs(ref_rule<quadrature::q4>(a, b) - e) > 1e-6);
    }
  // q2: every monomial of degree <= 3 except xi*eta; xi*eta gives 2 * 2 * (1/3) = 4/3.
  for (int a = 0; a <= 3; ++a)
    for (int b = 0; a + b <= 3; ++b) {
      CAPTURE(a);
      CAPTURE(b);
      if (a == 1 && b == 1) continue;
      CHECK(std::abs(ref_rule<quadrature::q2>(a, b) - ref_exact(a, b)) < 1e-14);
    }
  CHECK(ref_rule<quadrature::q2>(1, 1) == doctest::Approx(4.0 / 3.0).epsilon(1e-14));
  // q1 misses xi^2 (0 instead of 4/3).
  CHECK(ref_rule<quadrature::q1>(2, 0) == 0.0);
}

TEST_CASE("distorted cell: q4 exact to degree 2, q9 to degree 4, q2 only the area") {
  const auto m = one_cell(distorted);
  double worst_q2_linear = 0.0;
  CHECK(m.area() == doctest::Approx(polygon_moment(distorted, 0, 0)).epsilon(1e-14));
  for (int a = 0; a <= 5; ++a)
    for (int b = 0; a + b <= 5; ++b) {
      CAPTURE(a);
      CAPTURE(b);
      const double e = polygon_moment(distorted, a, b);
      const double scale = std::abs(e) + polygon_moment(distorted, 0, 0);
      const double err4 = std::abs(rule_moment<quadrature::q4>(m, a, b) - e) / scale;
      const double err9 = std::abs(rule_moment<quadrature::q9>(m, a, b) - e) / scale;
      const double err2 = std::abs(rule_moment<quadrature::q2>(m, a, b) - e) / scale;
      if (a + b <= 2) CHECK(err4 < 1e-13);
      if (a + b == 3) CHECK(err4 > 1e-6);  // degree 4 per variable: beyond q4 on this cell
      if (a + b <= 4) CHECK(err9 < 1e-13);
      if (a + b == 0) CHECK(err2 < 1e-14);
      if (a + b == 1) worst_q2_linear = std::max(worst_q2_linear, err2);
    }
  // The xi*eta term of X det J (c3 a0 + c1 a2 + c2 a1 for X = c0 + c1 xi + c2 eta + c3 xi eta,
  // det J = a0 + a1 xi + a2 eta) is missed; it vanishes for one coordinate of this cell by chance.
  CHECK(worst_q2_linear > 1e-3);
}

TEST_CASE("rectangle: q2 misses exactly the xi*eta part") {
  // [1, 4] x [-1, 1.5]: x = 2.5 + 1.5 xi, y = 0.25 + 1.25 eta, det J = 1.5 * 1.25.
  const auto m = one_cell({vec2(1, -1), vec2(4, -1), vec2(4, 1.5), vec2(1, 1.5)});
  const double cx = 2.5, hx = 1.5, cy = 0.25, hy = 1.25, detJ = hx * hy;
  for (int a = 0; a <= 3; ++a)
    for (int b = 0; a + b <= 3; ++b) {
      CAPTURE(a);
      CAPTURE(b);
      const double e = polygon_moment(m.node, a, b);
      // Only the xi*eta coefficient of x^a y^b is missed: c_11 = [a x^(a-1) hx][b y^(b-1) hy]
      // evaluated at the centre, so the q2 error is c_11 * (4/3) * det J.
      const double c11 = (a ? a * std::pow(cx, a - 1) * hx : 0.0) * (b ? b * std::pow(cy, b - 1) * hy : 0.0);
      // Cubic terms xi^2 eta and xi eta^2 vanish under q2, but x^2 y also has c_11 xi*eta only
      // through the product of the linear parts; higher mixed terms integrate exactly.
      CHECK(rule_moment<quadrature::q2>(m, a, b) - e == doctest::Approx(c11 * 4.0 / 3.0 * detJ).epsilon(1e-12).scale(1.0));
    }
  // In particular q2 integrates 1, x, y, x^2, y^2 exactly on a rectangle.
  for (auto [a, b] : {std::pair{0, 0}, {1, 0}, {0, 1}, {2, 0}, {0, 2}})
    CHECK(rule_moment<quadrature::q2>(m, a, b) == doctest::Approx(polygon_moment(m.node, a, b)).epsilon(1e-14));
}

TEST_CASE("weights carry det J; axisymmetric weights carry 2 pi R (Pappus)") {
  // Two cells: the distorted one and a rectangle sharing no nodes (the mesh need not be conforming).
  background_mesh m;
  m.node = distorted;
  for (const vec2& p : {vec2(3, 0), vec2(5, 0), vec2(5, 0.5), vec2(3, 0.5)}) m.node.push_back(p);
  m.cell = {{0, 1, 2, 3}, {4, 5, 6, 7}};
  const double area = m.area();
  const double first_moment_r = polygon_moment(distorted, 1, 0) + polygon_moment({m.node.begin() + 4, m.node.end()}, 1, 0);
  auto check = [&]<class Q>() {
    const auto ps = make_quadrature_points<Q, geometry::plane_strain>(m);
    const auto ax = make_quadrature_points<Q, geometry::axisymmetric>(m);
    REQUIRE(ps.size() == 2 * Q::points_per_cell);
    double sp = 0.0, sa = 0.0;
    for (index_t q = 0; q < ps.size(); ++q) {
      CHECK(ps.cell[q] == q / Q::points_per_cell);
      CHECK(ax.weight[q] == doctest::Approx(2.0 * std::numbers::pi * ps.position[q][0] * ps.weight[q]).epsilon(1e-15));
      sp += ps.weight[q];
      sa += ax.weight[q];
    }
    CHECK(sp == doctest::Approx(area).epsilon(1e-14));
    // Pappus: V = 2 pi A r_centroid = 2 pi int r dA; r det J is bilinear x linear, exact for q4 and q9.
    if (Q::points_per_cell >= 4) CHECK(sa == doctest::Approx(2.0 * std::numbers::pi * first_moment_r).epsilon(1e-13));
  };
  check.operator()<quadrature::q1>();
  check.operator()<quadrature::q2>();
  check.operator()<quadrature::q4>();
  check.operator()<quadrature::q9>();

  // On rectangles r det J is linear in xi: every rule, q1 and q2 included, gives Pappus exactly.
  // A hollow cylinder r in [1, 3], z in [0, 2]: V = pi (9 - 1) 2.
  const auto grid = [] {
    background_mesh g;
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 4; ++i) g.node.emplace_back(1.0 + 2.0 * i / 3.0, 1.0 * j);
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) g.cell.push_back({4 * j + i, 4 * j + i + 1, 4 * j + i + 5, 4 * j + i + 4});
    return g;
  }();
  auto volume = [&]<class Q>() {
    double s = 0.0;
    for (double w : make_quadrature_points<Q, geometry::axisymmetric>(grid).weight) s += w;
    return s;
  };
  const double V = std::numbers::pi * 8.0 * 2.0;
  CHECK(volume.operator()<quadrature::q1>() == doctest::Approx(V).epsilon(1e-14));
  CHECK(volume.operator()<quadrature::q2>() == doctest::Approx(V).epsilon(1e-14));
  CHECK(volume.operator()<quadrature::q4>() == doctest::Approx(V).epsilon(1e-14));
  CHECK(volume.operator()<quadrature::q9>() == doctest::Approx(V).epsilon(1e-14));
}

TEST_CASE("inverted cells are errors") {
  auto m = one_cell({vec2(0, 0), vec2(0, 1), vec2(1, 1), vec2(1, 0)});  // clockwise
  auto build = [&] { return make_quadrature_points<quadrature::q4, geometry::plane_strain>(m); };
  CHECK_THROWS_WITH_AS(build(), doctest::Contains("counter-clockwise"), error);
}
