// Linear completeness: coefficients d_I = A X_I + b (RK coefficients of a linear field are
// its nodal values, because RK functions reproduce linear fields exactly) give F = I + A at
// every quadrature point, for both kernels, both corrections, every rule and both
// geometries, on distorted cells. Axisymmetric fields take u_r = a r (u_r = 0 on the axis),
// so that the hoop stretch F33 = 1 + u_r / R = 1 + a exactly too.
// Through the solver (one step to the field, solver_at): det F and the Cauchy stress at every
// point equal the Hencky closed form computed here from an independent eigen-decomposition.

#include <doctest/doctest.h>

#include <Eigen/Eigenvalues>

#include "support/solver_fixtures.hpp"

namespace test_numeric_linear_fields {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

namespace {

struct field {
  mat2 A;
  vec2 b;
};

template <class K, class C, class Q, class G>
double worst_F_error(const field& f, bool distort) {
  const bool axi = G::is_axisymmetric;
  const vec2 lo(axi ? 0.0 : 0.4, -0.3), hi(axi ? 1.2 : 1.6, 0.7);
  const Eigen::Vector2i n(7, 6);
  const double support = std::is_same_v<C, correction::quadratic> ? 2.6 : 2.0;
  auto particles = make_grid_particles<2>(lo, hi, n, support);
  auto mesh = make_grid_mesh(lo, hi, n);
  if (distort) test::distort_interior(particles, mesh, vec2((hi - lo)[0] / 6, (hi - lo)[1] / 5), 0.2);
  const discrete_model m = build_discrete_model<K, C, Q, G>(particles, mesh);
  std::vector<vec2> d(m.particle_count());
  for (index_t I = 0; I < m.particle_count(); ++I) d[I] = f.A * m.particles.position[I] + f.b;
  const auto F = test::deformation_gradients<G>(m, d);
  mat3 expected = mat3::Identity();
  expected.topLeftCorner<2, 2>() += f.A;
  if (axi) expected(2, 2) = 1.0 + f.A(0, 0);
  double worst = 0.0;
  for (const mat3& Fq : F) worst = std::max(worst, (Fq - expected).cwiseAbs().maxCoeff());
  return worst;
}

template <class K, class C, class G>
void check_all_rules(const field& f) {
  for (bool distort : {false, true}) {
    CAPTURE(distort);
    CHECK(worst_F_error<K, C, quadrature::q1, G>(f, distort) < 1e-11);
    CHECK(worst_F_error<K, C, quadrature::q2, G>(f, distort) < 1e-11);
    CHECK(worst_F_error<K, C, quadrature::q4, G>(f, distort) < 1e-11);
    CHECK(worst_F_error<K, C, quadrature::q9, G>(f, distort) < 1e-11);
  }
}

template <class G>
void check_all(const field& f) {
  SUBCASE("cubic linear") { check_all_rules<kernel::cubic_spline, correction::linear, G>(f); }
  SUBCASE("cubic quadratic") { check_all_rules<kernel::cubic_spline, correction::quadratic, G>(f); }
  SUBCASE("quartic linear") { check_all_rules<kernel::quartic_spline, correction::linear, G>(f); }
  SUBCASE("quartic quadratic") { check_all_rules<kernel::quartic_spline, correction::quadratic, G>(f); }
}

// Kirchhoff stress of the Hencky law for F, from its own eigen-decomposition of b = F F^T.
mat3 hencky_cauchy(const mat3& F, const material::elastic_constants& c) {
  const Eigen::SelfAdjointEigenSolver<mat3> es(F * F.transpose());
  const Eigen::Vector3d eps = 0.5 * es.eigenvalues().array().log();
  const Eigen::Vector3d tau = Eigen::Vector3d::Constant(c.lame_lambda() * eps.sum()) + 2.0 * c.shear_modulus() * eps;
  return es.eigenvectors() * tau.asDiagonal() * es.eigenvectors().transpose() / F.determinant();
}

template <class Cfg>
void check_through_solver(const mat2& A, const vec2& b) {
  using G = typename Cfg::geometry_type;
  const auto c = test::steel_like();
  const vec2 lo(G::is_axisymmetric ? 0.0 : -0.5, 0.0), hi(1.0, 2.0);
  auto p = test::grid_problem<Cfg>(lo, hi, Eigen::Vector2i(6, 9), c);
  auto s = test::solver_at<Cfg>(std::move(p), [&](const vec2& X) -> vec2 { return A * X + b; },
                                test::tiny_step(0.25, c));
  mat3 F = mat3::Identity();
  F.topLeftCorner<2, 2>() += A;
  if (G::is_axisymmetric) F(2, 2) = 1.0 + A(0, 0);
  const mat3 sigma = hencky_cauchy(F, c);
  const double scale = sigma.cwiseAbs().maxCoeff();
  REQUIRE(scale > 1e-3 * c.youngs_modulus);
  double worst_stress = 0.0, worst_det = 0.0;
  for (index_t q = 0; q < s.model().point_count(); ++q) {
    worst_stress = std::max(worst_stress, (s.point_cauchy_stress(q) - sigma).cwiseAbs().maxCoeff() / scale);
    worst_det = std::max(worst_det, std::abs(s.point_det_F(q) - F.determinant()));
  }
  CHECK(worst_stress < 1e-9);
  CHECK(worst_det < 1e-11);
}

}  // namespace

TEST_CASE("plane strain: F = I + A at every point") {
  field f;
  f.A << 0.13, -0.41, 0.27, -0.08;
  f.b = vec2(0.7, -1.9);
  check_all<geometry::plane_strain>(f);
}

TEST_CASE("axisymmetric: F = I + A and F33 = 1 + a for u_r = a r") {
  field f;
  f.A << 0.21, 0.0, -0.33, 0.12;  // u_r = 0.21 r, u_z = -0.33 r + 0.12 z + b_z
  f.b = vec2(0.0, 0.45);
  check_all<geometry::axisymmetric>(f);
}

TEST_CASE("through the solver: uniform det F and Hencky stress") {
  mat2 A;
  A << 0.02, -0.015, 0.01, -0.012;
  using ps = config<kernel::cubic_spline, correction::linear, quadrature::q2, geometry::plane_strain,
                    material::elastic, contact::none>;
  check_through_solver<ps>(A, vec2(0.3, -0.1));
  mat2 Ar;
  Ar << 0.02, 0.0, 0.007, -0.011;
  using ax = config<kernel::quartic_spline, correction::quadratic, quadrature::q4, geometry::axisymmetric,
                    material::elastic, contact::none>;
  check_through_solver<ax>(Ar, vec2(0.0, 0.2));
}

}  // namespace test_numeric_linear_fields
