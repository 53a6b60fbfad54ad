// J2 plasticity in finite simple shear F = [[1, g, 0], [0, 1, 0], [0, 0, 1]], where the principal
// axes rotate and the return mapping is only first-order accurate in the step. Reference: an
// independent RK4 integration, written here, of the continuum model
//   d b_e / dg = l b_e + b_e l^T - 2 gdot n b_e,   d eps_p / dg = gdot,
//   gdot = 2 mu n : d / (3 mu + H(eps_p)),  n = 3/2 dev(tau) / q,  l = e1 e2^T (per unit g),
// with tau = Hencky(b_e) through a general 3x3 eigen-solver, started on the yield surface at the
// exact elastic limit g_y = 2 sinh(sigma_y0 / (2 sqrt(3) mu)) of Hencky simple shear.
#include <doctest/doctest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include <rkpm/material/j2_plasticity.hpp>

#include "support/paper_materials.hpp"

namespace test_unit_material_j2_shear {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using rkpm::mat3;
using rkpm::material::elastic_constants;
using rkpm::material::j2_plasticity;
namespace h = rkpm::material::hardening;

namespace {

using namespace rkpm::test::paper_materials;
const double mu = copper_mu, K = copper_K, lambda = copper_lambda;

mat3 shear(double g) {
  mat3 F = mat3::Identity();
  F(0, 1) = g;
  return F;
}

mat3 hencky(const mat3& b) {
  const Eigen::SelfAdjointEigenSolver<mat3> eig(b);
  const Eigen::Vector3d eps = 0.5 * eig.eigenvalues().array().log();
  const Eigen::Vector3d tau = Eigen::Vector3d::Constant(lambda * eps.sum()) + 2.0 * mu * eps;
  return eig.eigenvectors() * tau.asDiagonal() * eig.eigenvectors().transpose();
}

struct reference_state {
  mat3 b_e;
  double eps_p;
};

template <class Hard>
reference_state rate(const Hard& hardening, const reference_state& x) {
  mat3 l = mat3::Zero();
  l(0, 1) = 1.0;
  const mat3 d = 0.5 * (l + l.transpose());
  const mat3 tau = hencky(x.b_e);
  const mat3 dev = tau - tau.trace() / 3.0 * mat3::Identity();
  const double q = std::sqrt(1.5) * dev.norm();
  const mat3 n = 1.5 * dev / q;
  const double gdot = std::max(0.0, 2.0 * mu * (n.array() * d.array()).sum() /
                                        (3.0 * mu + hardening.slope(x.eps_p)));
  // n and b_e are coaxial, so n b_e is symmetric; symmetrise against round-off.
  const mat3 flow = gdot * (n * x.b_e + x.b_e * n);
  return {l * x.b_e + x.b_e * l.transpose() - flow, gdot};
}

template <class Hard>
reference_state rk4_reference(const Hard& hardening, double g_end, int n) {
  const double g_y = 2.0 * std::sinh(hardening.flow_stress(0.0) / (2.0 * std::sqrt(3.0) * mu));
  reference_state x{shear(g_y) * shear(g_y).transpose(), 0.0};
  const double dg = (g_end - g_y) / n;
  const auto axpy = [](const reference_state& a, double s, const reference_state& k) {
    return reference_state{a.b_e + s * k.b_e, a.eps_p + s * k.eps_p};
  };
  for (int i = 0; i < n; ++i) {
    const auto k1 = rate(hardening, x);
    const auto k2 = rate(hardening, axpy(x, 0.5 * dg, k1));
    const auto k3 = rate(hardening, axpy(x, 0.5 * dg, k2));
    const auto k4 = rate(hardening, axpy(x, dg, k3));
    x.b_e += dg / 6.0 * (k1.b_e + 2.0 * k2.b_e + 2.0 * k3.b_e + k4.b_e);
    x.eps_p += dg / 6.0 * (k1.eps_p + 2.0 * k2.eps_p + 2.0 * k3.eps_p + k4.eps_p);
  }
  return x;
}

struct model_result {
  mat3 tau;
  double eps_p;
  double work;
};

template <class Hard>
model_result drive(const Hard& hardening, double g_end, int n) {
  const j2_plasticity<Hard> law(copper, hardening);
  auto s = law.initial_state();
  mat3 tau;
  for (int i = 1; i <= n; ++i) tau = law.kirchhoff_stress(shear(g_end * i / n), s);
  return {tau, s.equivalent_plastic_strain, s.plastic_work};
}

template <class Hard>
void check_against_reference(const Hard& hardening, double g_end) {
  CAPTURE(g_end);
  const reference_state ref = rk4_reference(hardening, g_end, 4000);
  const mat3 tau_ref = hencky(ref.b_e);
  // The reference stays on the yield surface (a check of the reference itself).
  const mat3 dev_ref = tau_ref - tau_ref.trace() / 3.0 * mat3::Identity();
  CHECK(std::sqrt(1.5) * dev_ref.norm() ==
        doctest::Approx(hardening.flow_stress(ref.eps_p)).epsilon(1e-9));

  double previous_error = 0.0;
  mat3 previous_tau = mat3::Zero();
  for (const int n : {250, 500, 1000}) {
    CAPTURE(n);
    const model_result m = drive(hardening, g_end, n);
    const double err = (m.tau - tau_ref).norm() / tau_ref.norm();
    CHECK(err < 0.6 * g_end / n);  // first order in the step dg = g_end / n
    CHECK(m.eps_p == doctest::Approx(ref.eps_p).epsilon(2.0 / n));
    // Stress keeps the block structure and tau33 is nonzero only through the deviator.
    CHECK(m.tau(0, 2) == 0.0);
    CHECK(m.tau(1, 2) == 0.0);
    if (previous_error > 0.0) {
      // Halving the step halves the error: the model converges to the reference.
      CHECK(previous_error / err > 1.7);
      CHECK(previous_error / err < 2.3);
      // Richardson extrapolation removes the O(dg) term: what is left is far smaller, so the
      // model and the reference describe the same continuum problem.
      const mat3 extrapolated = 2.0 * m.tau - previous_tau;
      CHECK((extrapolated - tau_ref).norm() / tau_ref.norm() < 0.02 * err);
    }
    previous_tau = m.tau;
    previous_error = err;
    // Consistency after the last (plastic) step.
    const mat3 dev = m.tau - m.tau.trace() / 3.0 * mat3::Identity();
    CHECK(std::sqrt(1.5) * dev.norm() ==
          doctest::Approx(hardening.flow_stress(m.eps_p)).epsilon(1e-10));
    // Monotone eps_p: the work is int_0^eps_p sigma_y.
    CHECK(m.work == doctest::Approx(hardening.integral(0.0, m.eps_p)).epsilon(1e-12));
  }
}

}  // namespace

TEST_CASE("simple shear to g = 1, linear hardening, against RK4 of the continuum model") {
  check_against_reference(h::linear{400e6, 100e6}, 1.0);
}

TEST_CASE("simple shear to g = 2, linear hardening with a large modulus") {
  check_against_reference(h::linear{400e6, 5e9}, 2.0);
}

TEST_CASE("simple shear to g = 1, power law, against RK4 of the continuum model") {
  check_against_reference(h::power_law{576.79e6, 0.01658, 0.3593}, 1.0);
}

TEST_CASE("small-strain limit of simple shear: tau12 = (s0 + H eps_p) / sqrt(3)") {
  // For g << 1, eps_p = (sqrt(3) mu g - s0) / (3 mu + H) and tau12 = mu (g - sqrt(3) eps_p).
  const double s0 = 400e6, H = 100e6, g = 0.01;
  const model_result m = drive(h::linear{s0, H}, g, 50);
  const double eps_p = (std::sqrt(3.0) * mu * g - s0) / (3.0 * mu + H);
  CHECK(m.eps_p == doctest::Approx(eps_p).epsilon(1e-2));  // finite-strain terms are O(g)
  CHECK(m.tau(0, 1) == doctest::Approx(mu * (g - std::sqrt(3.0) * eps_p)).epsilon(1e-3));
}

}  // namespace test_unit_material_j2_shear
