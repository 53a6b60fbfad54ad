// Hencky elastic law against closed forms: principal stretches, rotated stretches, simple shear,
// the small-strain limit (linear elasticity to O(e^2)), a general 3x3 eigen-solver, and bad F.
#include <doctest/doctest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>

#include <rkpm/material/elastic.hpp>

namespace test_unit_material_elastic {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using rkpm::mat3;
using rkpm::material::elastic;
using rkpm::material::elastic_constants;

namespace {

const elastic_constants copper{117e9, 0.35, 8930.0};
const double mu = 117e9 / 2.7;
const double lambda = 117e9 * 0.35 / (1.35 * 0.3);

mat3 block(double f11, double f12, double f21, double f22, double f33) {
  mat3 F;
  F << f11, f12, 0, f21, f22, 0, 0, 0, f33;
  return F;
}

mat3 rotation(double angle) {
  return block(std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle), 1.0);
}

double rel_error(const mat3& a, const mat3& b) { return (a - b).norm() / b.norm(); }

// Hencky stress through a general symmetric 3x3 eigen-solver, independent of the 2x2 closed form.
mat3 hencky_reference(const mat3& F) {
  const Eigen::SelfAdjointEigenSolver<mat3> eig(F * F.transpose());
  const Eigen::Vector3d eps = 0.5 * eig.eigenvalues().array().log();
  const Eigen::Vector3d tau = Eigen::Vector3d::Constant(lambda * eps.sum()) + 2.0 * mu * eps;
  return eig.eigenvectors() * tau.asDiagonal() * eig.eigenvectors().transpose();
}

mat3 stress(const mat3& F) {
  const elastic law(copper);
  auto s = law.initial_state();
  return law.kirchhoff_stress(F, s);
}

}  // namespace

TEST_CASE("principal stretches: tau_i = lambda sum ln l_j + 2 mu ln l_i") {
  for (const auto& l : {Eigen::Vector3d(1.01, 0.99, 1.0), Eigen::Vector3d(2.0, 0.5, 1.3),
                        Eigen::Vector3d(0.4, 0.7, 1.8)}) {
    const mat3 tau = stress(block(l(0), 0, 0, l(1), l(2)));
    const double tr = std::log(l(0) * l(1) * l(2));
    // Errors measured against the stress scale (lambda + 2 mu) max |ln l|: a component can be a
    // near-cancellation of the volumetric and deviatoric parts.
    const double scale = (lambda + 2 * mu) * l.array().log().abs().maxCoeff();
    for (int i = 0; i < 3; ++i)
      CHECK(std::abs(tau(i, i) - (lambda * tr + 2 * mu * std::log(l(i)))) < 1e-13 * scale);
    CHECK(tau(0, 1) == doctest::Approx(0.0).scale(mu * 1e-14));
    CHECK(tau(1, 0) == tau(0, 1));
  }
}

TEST_CASE("rotated stretches: F = R U gives R tau(U) R^T, F = U R gives tau(U)") {
  const mat3 U = block(1.7, 0, 0, 0.6, 1.1);
  const mat3 tau_u = stress(U);
  for (const double angle : {0.3, std::numbers::pi / 2, 2.5, -1.0}) {
    const mat3 R = rotation(angle);
    CHECK(rel_error(stress(R * U), R * tau_u * R.transpose()) < 1e-13);
    CHECK(rel_error(stress(U * R), tau_u) < 1e-13);
  }
}

TEST_CASE("simple shear closed form") {
  // b = [[1 + g^2, g], [g, 1]]: ln l_1 = -ln l_2 = asinh(g / 2), cos 2 theta = g / sqrt(g^2 + 4),
  // so tau11 = -tau22 = 2 mu asinh(g / 2) g / sqrt(g^2 + 4), tau12 = 2 mu asinh(g / 2) 2 /
  // sqrt(g^2 + 4), tau33 = 0 (no volume change).
  for (const double g : {1e-3, 0.3, 1.0, 5.0, 20.0}) {
    CAPTURE(g);
    const mat3 tau = stress(block(1, g, 0, 1, 1));
    const double a = 2 * mu * std::asinh(g / 2) / std::sqrt(g * g + 4);
    const double scale = 2 * mu * std::asinh(g / 2);
    CHECK(std::abs(tau(0, 0) - a * g) < 1e-12 * scale);
    CHECK(std::abs(tau(1, 1) + a * g) < 1e-12 * scale);
    CHECK(tau(0, 1) == doctest::Approx(2 * a).epsilon(1e-12));
    CHECK(tau(1, 0) == doctest::Approx(2 * a).epsilon(1e-12));
    CHECK(std::abs(tau(2, 2)) < 1e-12 * scale);
  }
}

TEST_CASE("general block F against a 3x3 eigen-solver, including equal in-plane stretches") {
  const mat3 cases[] = {block(1.2, 0.3, -0.4, 0.9, 1.05), block(0.8, -0.6, 0.5, 1.3, 0.7),
                        block(1.5, 0.0, 0.0, 1.5, 1.0),   // repeated in-plane eigenvalue
                        block(1.0, 0.0, 0.0, 1.0, 1.0),   // identity: zero stress
                        rotation(0.7) * block(1.3, 0.0, 0.0, 1.3, 0.9)};
  for (const mat3& F : cases) {
    const mat3 tau = stress(F);
    CHECK(tau.allFinite());
    const mat3 ref = hencky_reference(F);
    CHECK((tau - ref).norm() <= 1e-13 * std::max(ref.norm(), mu));
    CHECK(tau(0, 2) == 0.0);
    CHECK(tau(1, 2) == 0.0);
    CHECK(tau(2, 0) == 0.0);
    CHECK(tau(2, 1) == 0.0);
  }
}

TEST_CASE("small strain: tau = lambda tr(e) I + 2 mu e + O(e^2)") {
  mat3 H;  // displacement gradient direction, with rotation and out-of-plane stretch
  H << 0.8, -0.5, 0, 0.9, -0.3, 0, 0, 0, 0.4;
  double previous = 0.0;
  for (const double t : {1e-3, 5e-4, 2.5e-4}) {
    const mat3 e = 0.5 * t * (H + H.transpose());
    const mat3 linear = lambda * e.trace() * mat3::Identity() + 2 * mu * e;
    const double err = (stress(mat3::Identity() + t * H) - linear).norm();
    CAPTURE(t);
    CHECK(err < 10.0 * mu * t * t);  // O(e^2) with a modest constant
    if (previous > 0) CHECK(previous / err == doctest::Approx(4.0).epsilon(0.05));
    previous = err;
  }
}

TEST_CASE("the elastic state stays at zero plastic strain and work") {
  const elastic law(copper);
  auto s = law.initial_state();
  (void)law.kirchhoff_stress(block(3.0, 1.0, 0.0, 0.4, 1.0), s);
  CHECK(s.equivalent_plastic_strain == 0.0);
  CHECK(s.plastic_work == 0.0);
}

TEST_CASE("a bad deformation gradient throws instead of returning NaN") {
  CHECK_THROWS_AS(stress(block(-1.0, 0, 0, 1.0, 1.0)), rkpm::error);  // det F < 0
  CHECK_THROWS_AS(stress(block(1.0, 1.0, 1.0, 1.0, 1.0)), rkpm::error);  // det F = 0
  CHECK_THROWS_AS(stress(block(1.0, 0, 0, 1.0, 0.0)), rkpm::error);  // F33 = 0
  CHECK_THROWS_AS(stress(block(NAN, 0, 0, 1.0, 1.0)), rkpm::error);
  CHECK_THROWS_AS(stress(block(INFINITY, 0, 0, 1.0, 1.0)), rkpm::error);
  mat3 F = mat3::Identity();
  F(0, 2) = 0.1;
  CHECK_THROWS_WITH_AS(stress(F), doctest::Contains("out-of-plane"), rkpm::error);
}

}  // namespace test_unit_material_elastic
