// Spectrum of the assembled small-strain elastic stiffness (apply_elastic_stiffness, column by
// column), mass-scaled: omega^2 = eig(M^-1/2 K M^-1/2).
// Theory: in plane strain the null space is exactly the three rigid motions (two translations,
// the infinitesimal rotation); any further zero (or near-zero) eigenvalue is a spurious
// zero-energy mode of the quadrature. In axisymmetric geometry a radial translation strains the
// hoop (eps_theta = u_r / r) and a rotation is not admissible, so the only zero mode is the rigid
// axial translation (the ends are free). The axis condition u_r = 0 is a constraint on physical
// values, not a stiffness: we count the zero modes both of K itself and of K restricted to the
// subspace that satisfies the axis constraint (null space of Lambda, rows N_J(X_I) for axis
// particles I, direction r); both must be 1.
// The one-point rule q1 is the negative control: it must show extra near-zero modes.
// Also: the power-iteration stable step equals 2 / omega_max of the full eigen-solution.

#include <doctest/doctest.h>

#include <Eigen/Eigenvalues>

#include "support/solver_fixtures.hpp"

namespace test_numeric_stiffness_spectrum {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

namespace {

const material::elastic_constants copper{117e9, 0.35, 8930.0};

struct spectrum {
  Eigen::VectorXd omega2;       // ascending
  Eigen::VectorXd constrained;  // ascending, on the axis-constrained subspace (axisymmetric)
  double rigid_residual = 0.0;  // |K t| / (|K| |t|) over the rigid modes of the geometry
  double symmetry = 0.0;        // |K - K^T| / |K|
  double power_dt = 0.0, exact_dt = 0.0;

  int zero_modes(const Eigen::VectorXd& w, double tol = 1e-9) const {
    int z = 0;
    for (double x : w) z += std::abs(x) < tol * w.cwiseAbs().maxCoeff();
    return z;
  }
  double relative(const Eigen::VectorXd& w, int i) const { return w[i] / w.cwiseAbs().maxCoeff(); }
};

template <class K, class C, class Q, class G>
spectrum compute(const vec2& lo, const vec2& hi, const Eigen::Vector2i& n) {
  // The test's own dense algebra stays serial: Eigen's OpenMP matrix products spin-wait, and on
  // a loaded 2-core machine the small products here then take seconds instead of microseconds.
  Eigen::setNbThreads(1);
  const double support = test::default_support<C>;
  const discrete_model m =
      build_discrete_model<K, C, Q, G>(make_grid_particles<2>(lo, hi, n, support), make_grid_mesh(lo, hi, n));
  const Eigen::MatrixXd Kmat = test::assemble_stiffness<G>(m, copper);
  const Eigen::VectorXd M = test::dof_masses(m, copper.density);
  spectrum s;
  s.symmetry = (Kmat - Kmat.transpose()).norm() / Kmat.norm();
  const Eigen::VectorXd Ms = M.cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd A = Ms.asDiagonal() * (0.5 * (Kmat + Kmat.transpose())) * Ms.asDiagonal();
  s.omega2 = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(A, Eigen::EigenvaluesOnly).eigenvalues();
  s.exact_dt = 2.0 / std::sqrt(s.omega2.maxCoeff());
  std::vector<double> mass(m.particle_count());
  for (index_t I = 0; I < m.particle_count(); ++I) mass[I] = copper.density * m.lumped_volume[I];
  s.power_dt = reference_stable_time_step<G>(m, copper, mass);

  // Rigid modes as coefficient vectors (linear fields: coefficients = nodal values).
  const index_t np = m.particle_count();
  std::vector<Eigen::VectorXd> rigid;
  Eigen::VectorXd tz = Eigen::VectorXd::Zero(2 * np);
  for (index_t I = 0; I < np; ++I) tz[2 * I + 1] = 1.0;
  rigid.push_back(tz);
  if (!G::is_axisymmetric) {
    Eigen::VectorXd tx = Eigen::VectorXd::Zero(2 * np), rot(2 * np);
    for (index_t I = 0; I < np; ++I) {
      tx[2 * I] = 1.0;
      rot[2 * I] = -m.particles.position[I][1];
      rot[2 * I + 1] = m.particles.position[I][0];
    }
    rigid.push_back(tx);
    rigid.push_back(rot);
  }
  for (const auto& t : rigid) s.rigid_residual = std::max(s.rigid_residual, (Kmat * t).norm() / (Kmat.norm() * t.norm()));

  if (G::is_axisymmetric) {
    // Lambda: physical u_r at axis particles; restrict A to null(Lambda M^-1/2) (same
    // substitution x = M^-1/2 y as A).
    std::vector<index_t> axis;
    for (index_t I = 0; I < np; ++I)
      if (m.particles.position[I][0] <= 1e-12) axis.push_back(I);
    Eigen::MatrixXd L = Eigen::MatrixXd::Zero(static_cast<index_t>(axis.size()), 2 * np);
    for (std::size_t r = 0; r < axis.size(); ++r)
      for (index_t e = m.at_particles.offset[axis[r]]; e < m.at_particles.offset[axis[r] + 1]; ++e)
        L(static_cast<index_t>(r), 2 * m.at_particles.neighbor[e]) = m.at_particles.N[e] * Ms[2 * m.at_particles.neighbor[e]];
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(L);
    Eigen::MatrixXd Z = lu.kernel();
    REQUIRE(Z.cols() == 2 * np - static_cast<index_t>(axis.size()));
    Z = Eigen::HouseholderQR<Eigen::MatrixXd>(Z).householderQ() * Eigen::MatrixXd::Identity(2 * np, Z.cols());
    s.constrained = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Z.transpose() * A * Z, Eigen::EigenvaluesOnly).eigenvalues();
  }
  return s;
}

template <class Q, class G>
spectrum square_patch() {  // 6 x 6 particles, 5 x 5 cells
  return compute<kernel::cubic_spline, correction::linear, Q, G>(vec2(0, 0), vec2(1e-3, 1e-3), Eigen::Vector2i(6, 6));
}
template <class Q, class G>
spectrum taylor_patch() {  // the Taylor bar spacing 0.16 mm x 0.648 mm (4:1), 6 x 6 particles
  return compute<kernel::cubic_spline, correction::linear, Q, G>(vec2(0, 0), vec2(5 * 0.16e-3, 5 * 0.648e-3),
                                                                   Eigen::Vector2i(6, 6));
}

void report(const std::string& what, const spectrum& s, int zeros) {
  MESSAGE(what << ": omega^2/max [0.." << zeros + 1 << "] = " << s.relative(s.omega2, 0) << ", "
               << s.relative(s.omega2, zeros - 1) << ", " << s.relative(s.omega2, zeros) << "; power dt / exact dt = "
               << s.power_dt / s.exact_dt);
}

template <class Q>
void check_plane_strain(const spectrum& s, const std::string& what) {
  report(what, s, 3);
  CHECK(s.symmetry < 1e-13);
  CHECK(s.rigid_residual < 1e-12);
  CHECK(s.zero_modes(s.omega2) == 3);
  CHECK(s.relative(s.omega2, 3) > 1e-6);
  // Power iteration approaches omega_max from below, so its step is slightly long (design note
  // in stable_time_step.hpp) but must be close.
  CHECK(s.power_dt / s.exact_dt == doctest::Approx(1.0).epsilon(5e-3));
  CHECK(s.power_dt >= s.exact_dt * (1.0 - 1e-12));
}

template <class Q>
void check_axisymmetric(const spectrum& s, const std::string& what) {
  report(what, s, 1);
  CHECK(s.symmetry < 1e-13);
  CHECK(s.rigid_residual < 1e-12);
  CHECK(s.zero_modes(s.omega2) == 1);
  CHECK(s.relative(s.omega2, 1) > 1e-6);
  CHECK(s.zero_modes(s.constrained) == 1);
  CHECK(s.relative(s.constrained, 1) > 1e-6);
  MESSAGE(what << ", axis-constrained: omega^2/max [0..2] = " << s.relative(s.constrained, 0) << ", "
               << s.relative(s.constrained, 1));
  CHECK(s.power_dt / s.exact_dt == doctest::Approx(1.0).epsilon(5e-3));
}

}  // namespace

TEST_CASE("plane strain: exactly the three rigid modes for q2, q4, q9") {
  check_plane_strain<quadrature::q2>(square_patch<quadrature::q2, geometry::plane_strain>(), "q2 square");
  check_plane_strain<quadrature::q4>(square_patch<quadrature::q4, geometry::plane_strain>(), "q4 square");
  check_plane_strain<quadrature::q9>(square_patch<quadrature::q9, geometry::plane_strain>(), "q9 square");
  check_plane_strain<quadrature::q2>(taylor_patch<quadrature::q2, geometry::plane_strain>(), "q2 taylor");
  check_plane_strain<quadrature::q4>(taylor_patch<quadrature::q4, geometry::plane_strain>(), "q4 taylor");
  check_plane_strain<quadrature::q9>(taylor_patch<quadrature::q9, geometry::plane_strain>(), "q9 taylor");
}

TEST_CASE("axisymmetric: only the axial translation, with and without the axis constraint") {
  check_axisymmetric<quadrature::q2>(square_patch<quadrature::q2, geometry::axisymmetric>(), "q2 square axi");
  check_axisymmetric<quadrature::q4>(square_patch<quadrature::q4, geometry::axisymmetric>(), "q4 square axi");
  check_axisymmetric<quadrature::q9>(square_patch<quadrature::q9, geometry::axisymmetric>(), "q9 square axi");
  check_axisymmetric<quadrature::q2>(taylor_patch<quadrature::q2, geometry::axisymmetric>(), "q2 taylor axi");
  check_axisymmetric<quadrature::q4>(taylor_patch<quadrature::q4, geometry::axisymmetric>(), "q4 taylor axi");
}

TEST_CASE("the one-point rule q1 has spurious zero-energy modes") {
  // 6 x 6 particles, 25 points: the same test that finds exactly 3 zero modes for q2, q4, q9
  // finds a fourth, spurious one.
  const auto s6 = square_patch<quadrature::q1, geometry::plane_strain>();
  report("q1 square", s6, 3);
  CHECK(s6.zero_modes(s6.omega2) > 3);
  // 10 x 10 particles, 81 points for 200 dofs: no exact extra zero, but a near-zero mode three
  // orders below what q4 gives on the same patch.
  const auto q1 = compute<kernel::cubic_spline, correction::linear, quadrature::q1, geometry::plane_strain>(
      vec2(0, 0), vec2(1e-3, 1e-3), Eigen::Vector2i(10, 10));
  const auto q4 = compute<kernel::cubic_spline, correction::linear, quadrature::q4, geometry::plane_strain>(
      vec2(0, 0), vec2(1e-3, 1e-3), Eigen::Vector2i(10, 10));
  report("q1 10x10", q1, 3);
  report("q4 10x10", q4, 3);
  CHECK(q4.zero_modes(q4.omega2) == 3);
  CHECK(q1.relative(q1.omega2, 3) < 1e-2 * q4.relative(q4.omega2, 3));
}

}  // namespace test_numeric_stiffness_spectrum
