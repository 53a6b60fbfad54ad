// J2 plasticity on general 2D paths (stretch, shear and a varying hoop stretch F33):
// objectivity under superposed rigid rotations, the elastic limit (Hencky below yield, linear
// elasticity for small strain), plastic incompressibility, consistency, the energy balance
// int tau : d dt = W_e(b_e) + plastic work, no heap allocation, and bad F.
#define EIGEN_RUNTIME_NO_MALLOC  // lets the test forbid Eigen heap allocation around calls
#include <doctest/doctest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <cmath>
#include <numbers>

#include <rkpm/material/elastic.hpp>
#include <rkpm/material/j2_plasticity.hpp>

#include "support/tensors.hpp"
#include "support/paper_materials.hpp"

using rkpm::mat3;
using rkpm::material::elastic_constants;
using rkpm::material::j2_plasticity;
namespace h = rkpm::material::hardening;

namespace {

using rkpm::test::von_mises;

using namespace rkpm::test::paper_materials;
const double mu = copper_mu, K = copper_K, lambda = copper_lambda;

mat3 block(double f11, double f12, double f21, double f22, double f33) {
  mat3 F;
  F << f11, f12, 0, f21, f22, 0, 0, 0, f33;
  return F;
}

mat3 rotation(double angle) {
  return block(std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle), 1.0);
}

// A non-proportional path with compression, shear, rotation of the principal axes and a
// growing hoop stretch (axisymmetric-like), reaching strains of order 0.5 at t = 1.
mat3 path(double t) {
  return block(1.0 - 0.35 * t, 0.6 * std::sin(2.0 * t), -0.2 * t * t, 1.0 + 0.1 * t,
               1.0 + 0.3 * t);
}

// Stored energy per reference volume of Hencky elasticity, W = mu |dev eps_e|^2 + K/2 tr^2,
// from b_e through a general eigen-solver.
double stored_energy(const mat3& b_e) {
  const Eigen::SelfAdjointEigenSolver<mat3> eig(b_e);
  const Eigen::Vector3d eps = 0.5 * eig.eigenvalues().array().log();
  const double tr = eps.sum();
  return mu * (eps.array() - tr / 3.0).square().sum() + 0.5 * K * tr * tr;
}

mat3 hencky(const mat3& F) {
  const Eigen::SelfAdjointEigenSolver<mat3> eig(F * F.transpose());
  const Eigen::Vector3d eps = 0.5 * eig.eigenvalues().array().log();
  const Eigen::Vector3d tau = Eigen::Vector3d::Constant(lambda * eps.sum()) + 2.0 * mu * eps;
  return eig.eigenvectors() * tau.asDiagonal() * eig.eigenvectors().transpose();
}

// The paper's laws: linear for copper (Taylor bar), the power law of the wheel's steel.
template <class H>
H paper_hardening() {
  if constexpr (std::same_as<H, h::linear>) return copper_hardening;
  else return wheel_hardening;
}

}  // namespace

TEST_CASE_TEMPLATE("objectivity: a superposed rotation R gives tau' = R tau R^T along the path", H,
                   h::linear, h::power_law) {
  const H hardening = paper_hardening<H>();
  const j2_plasticity<H> law(copper, hardening);
  // A fixed 90 degree rotation, and a rotation that grows to 3 rad along the path.
  const auto fixed = [](double) { return rotation(std::numbers::pi / 2); };
  const auto spinning = [](double t) { return rotation(3.0 * t); };
  for (int which = 0; which < 2; ++which) {
    CAPTURE(which);
    auto s = law.initial_state();
    auto s_rot = law.initial_state();
    const int n = 40;
    int plastic_steps = 0;
    for (int i = 1; i <= n; ++i) {
      const double t = double(i) / n;
      const mat3 R = which == 0 ? fixed(t) : spinning(t);
      const double eps_p_before = s.equivalent_plastic_strain;
      const mat3 tau = law.kirchhoff_stress(path(t), s);
      const mat3 tau_rot = law.kirchhoff_stress(R * path(t), s_rot);
      CHECK((tau_rot - R * tau * R.transpose()).norm() < 1e-11 * tau.norm());
      CHECK(s_rot.equivalent_plastic_strain ==
            doctest::Approx(s.equivalent_plastic_strain).epsilon(1e-11));
      CHECK(s_rot.plastic_work == doctest::Approx(s.plastic_work).epsilon(1e-11));
      CHECK((s_rot.elastic_left_cauchy_green.full() - R * s.elastic_left_cauchy_green.full() * R.transpose())
                .norm() < 1e-13);
      if (s.equivalent_plastic_strain > eps_p_before) {
        ++plastic_steps;
        CHECK(von_mises(tau) ==
              doctest::Approx(hardening.flow_stress(s.equivalent_plastic_strain)).epsilon(1e-10));
      }
      // Plastic incompressibility: det(b_e)^(1/2) = det F after every step.
      CHECK(std::sqrt(s.elastic_left_cauchy_green.full().determinant()) ==
            doctest::Approx(path(t).determinant()).epsilon(1e-13));
    }
    CHECK(plastic_steps > 30);
  }
}

TEST_CASE("elastic limit: below yield J2 gives the Hencky stress, and the state stays elastic") {
  // Strains below 2e-3 keep q below 400 MPa.
  const j2_plasticity<h::linear> law(copper, copper_hardening);
  const rkpm::material::elastic elastic_law(copper);
  auto s = law.initial_state();
  auto s_el = elastic_law.initial_state();
  for (int i = 1; i <= 20; ++i) {
    const double t = 0.002 * i / 20.0;
    const mat3 F = rotation(10.0 * t) * path(t);  // large rotation, small strain
    const mat3 tau = law.kirchhoff_stress(F, s);
    const mat3 ref = hencky(F);
    CHECK(von_mises(tau) < 400e6);
    // Round-off of ln(lambda^2) near 1 limits agreement to about 1e-16 / strain.
    CHECK((tau - ref).norm() < 1e-11 * ref.norm());
    CHECK((elastic_law.kirchhoff_stress(F, s_el) - ref).norm() < 1e-11 * ref.norm());
  }
  CHECK(s.equivalent_plastic_strain == 0.0);
  CHECK(s.plastic_work == 0.0);
  // Small strain without rotation: linear elasticity up to O(e^2).
  const double t = 1e-3;
  const mat3 F = path(t);
  const mat3 e = 0.5 * (F + F.transpose()) - mat3::Identity();
  auto fresh = law.initial_state();
  const mat3 tau = law.kirchhoff_stress(F, fresh);
  const mat3 linear = lambda * e.trace() * mat3::Identity() + 2.0 * mu * e;
  CHECK((tau - linear).norm() < 10.0 * mu * (F - mat3::Identity()).squaredNorm());
}

TEST_CASE_TEMPLATE("the stress recomputed from the state is the stress the update returned", H, h::linear,
                   h::power_law) {
  // The solver keeps no tau per point and asks current_kirchhoff_stress(F, s) at output.
  const H hardening = paper_hardening<H>();
  const j2_plasticity<H> law(copper, hardening);
  const rkpm::material::elastic elastic_law(copper);
  auto s = law.initial_state();
  auto s_el = elastic_law.initial_state();
  int elastic_steps = 0, plastic_steps = 0;
  for (int i = 1; i <= 220; ++i) {
    const double t = i <= 20 ? 1e-5 * i : (i - 20) / 200.0;  // 20 steps below yield, then 200 past it
    const mat3 F = rotation(2.0 * t) * path(t);
    const double eps_p = s.equivalent_plastic_strain;
    const mat3 tau = law.kirchhoff_stress(F, s);
    const mat3 again = law.current_kirchhoff_stress(F, s);
    if (s.equivalent_plastic_strain == eps_p) {
      ++elastic_steps;
      CHECK(again == tau);  // b_e is the trial tensor the update decomposed: the same bits
    } else {
      ++plastic_steps;
      CHECK((again - tau).norm() < 1e-12 * tau.norm());  // the principal frame found again
    }
    CHECK(elastic_law.current_kirchhoff_stress(F, s_el) == elastic_law.kirchhoff_stress(F, s_el));
  }
  CHECK(elastic_steps > 0);
  CHECK(plastic_steps > 100);
}

TEST_CASE_TEMPLATE("energy balance: int tau : d = W_e(b_e) + plastic work", H, h::linear,
                   h::power_law) {
  const H hardening = paper_hardening<H>();
  const j2_plasticity<H> law(copper, hardening);
  auto s = law.initial_state();
  const int n = 4000;
  double work = 0.0;
  mat3 tau_prev = mat3::Zero();
  for (int i = 1; i <= n; ++i) {
    const mat3 F0 = path(double(i - 1) / n), F1 = path(double(i) / n);
    const mat3 tau = law.kirchhoff_stress(F1, s);
    // Stress power per reference volume tau : d, d = sym(dF F^-1), trapezoidal in time.
    const mat3 l = (F1 - F0) * (0.5 * (F0 + F1)).inverse();
    work += (0.5 * (tau + tau_prev)).cwiseProduct(0.5 * (l + l.transpose())).sum();
    tau_prev = tau;
  }
  const double stored = stored_energy(s.elastic_left_cauchy_green.full());
  CAPTURE(work);
  CAPTURE(stored);
  CAPTURE(s.plastic_work);
  // The tolerance is measured against the plastic work alone (comparable to the stored energy,
  // which is mostly volumetric here), so a wrong dissipation cannot hide.
  CHECK(s.plastic_work > 0.5 * stored);
  CHECK(std::abs(stored + s.plastic_work - work) < 1e-4 * s.plastic_work);
}

TEST_CASE("kirchhoff_stress allocates nothing on the heap") {
  const j2_plasticity<h::power_law> law(copper, wheel_hardening);
  const rkpm::material::elastic elastic_law(copper);
  auto s = law.initial_state();
  auto s_el = elastic_law.initial_state();
  mat3 sum = mat3::Zero();
  Eigen::internal::set_is_malloc_allowed(false);
  for (int i = 1; i <= 10; ++i) {
    sum += law.kirchhoff_stress(path(0.1 * i), s);
    sum += elastic_law.kirchhoff_stress(path(0.1 * i), s_el);
  }
  Eigen::internal::set_is_malloc_allowed(true);
  CHECK(sum.allFinite());
  CHECK(s.equivalent_plastic_strain > 0.0);
}

TEST_CASE("a bad deformation gradient throws and leaves the state untouched") {
  const j2_plasticity<h::linear> law(copper, copper_hardening);
  auto s = law.initial_state();
  (void)law.kirchhoff_stress(path(0.5), s);
  const auto before = s;
  CHECK_THROWS_WITH_AS(law.kirchhoff_stress(block(-1.0, 0, 0, 1, 1), s),
                       doctest::Contains("det F"), rkpm::error);
  CHECK_THROWS_AS(law.kirchhoff_stress(block(1.0, 0, 0, 1, 0.0), s), rkpm::error);
  CHECK_THROWS_AS(law.kirchhoff_stress(block(NAN, 0, 0, 1, 1), s), rkpm::error);
  CHECK(s.equivalent_plastic_strain == before.equivalent_plastic_strain);
  CHECK(s.previous_deformation == before.previous_deformation);
  CHECK(s.elastic_left_cauchy_green == before.elastic_left_cauchy_green);
}
