// The end of the point rule (solver/point_force_terms.hpp: S = tau F^-T w, the hoop term and the
// support stretch, written once for a number type) against Eigen's 2x2 arithmetic, whose order
// the formulas write out: the one-point form (double) must have Eigen's bits, and every lane of
// the batched form (a vector V) the one-point form's, on deformation gradients that stretch,
// shear, turn and compress, in both geometries, and a support stretch of 1 at F = I. At every
// width users build: this build's native vector and 2, 4 and 8 lanes (simd_of<N>, core/simd.hpp,
// fixed-size vectors that need no AVX2 or AVX-512 to run).
#include <doctest/doctest.h>

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <tuple>

#include <rkpm/geometry/axisymmetric.hpp>
#include <rkpm/geometry/plane_strain.hpp>
#include <rkpm/solver/point_force_terms.hpp>

namespace point_force_terms_test {

using rkpm::mat2;
using rkpm::mat3;
using rkpm::vec2;

// The same bits, unless Eigen's 2x2 products use fused multiply-adds (a build with -march for a
// machine with FMA units, RKPM_NATIVE_ARCH), which the written-out products and sums do not:
// then rounding apart, relative to the size of the terms summed (scale).
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool agree(double a, double b, double scale) {
#ifdef EIGEN_VECTORIZE_FMA
  return std::abs(a - b) <= 1e-14 * scale;
#else
  (void)scale;
  return same_bits(a, b);
#endif
}

// Lane k of sample n: a block-structured F and a symmetric-in-plane tau of order 1e8 Pa.
mat3 deformation(int n, int k) {
  const double t = 0.37 * n + 0.11 * k, c = std::cos(t), s = std::sin(t);
  mat3 F = mat3::Zero();
  F.topLeftCorner<2, 2>() << (1.0 + 0.3 * s) * c, -0.4 * s + 0.1 * t, (0.8 - 0.2 * c) * s, (1.0 - 0.25 * s) * c + 0.9;
  F(2, 2) = 1.0 + 0.2 * std::sin(2.0 * t);
  return F;
}
mat3 stress(int n, int k) {
  const double t = 0.53 * n + 0.29 * k;
  mat3 tau = mat3::Zero();
  tau.topLeftCorner<2, 2>() << 3e8 * std::sin(t), -1e8 * std::cos(3.0 * t), -1e8 * std::cos(3.0 * t), -2e8 * std::cos(t);
  tau(2, 2) = 1.5e8 * std::sin(2.0 * t);
  return tau;
}

// The point rule with Eigen's 2x2 inverse, products and squared norm.
struct eigen_terms {
  mat2 Fi, S;
  double hoop, stretch;
};
template <class G>
eigen_terms eigen_point_rule(const mat3& F, const mat3& tau, double weight, double radius, const vec2& support_inverse) {
  const mat2 Fi = F.topLeftCorner<2, 2>().inverse();
  const mat2 S = tau.topLeftCorner<2, 2>() * Fi.transpose() * weight;
  const double hoop = G::is_axisymmetric ? tau(2, 2) / F(2, 2) * weight / radius : 0.0;
  const mat2 B = Fi.transpose() * support_inverse.asDiagonal();
  const double s = B.squaredNorm(), det = B.determinant();
  const double largest = std::sqrt(0.5 * (s + std::sqrt(std::max(0.0, s * s - 4.0 * det * det))));
  return {Fi, S, hoop, support_inverse.maxCoeff() / largest};
}

template <class G, class V>
void check_samples() {
  constexpr int width = rkpm::lanes_of<V>;
  const vec2 support_inverse(1.0 / 2.5e-3, 1.0 / 0.8e-3);
  for (int n = 0; n < 40; ++n) {
    std::array<mat3, width> F, tau;
    std::array<double, width> weight, radius;
    for (int k = 0; k < width; ++k) {
      F[k] = deformation(n, k);
      tau[k] = stress(n, k);
      weight[k] = 1e-7 * (1.0 + 0.1 * k + 0.01 * n);
      radius[k] = 1e-3 * (0.5 + k + 0.1 * n);
    }
    const auto block = [](const std::array<mat3, width>& a) {
      return rkpm::gather_block<V>([&](int k) { return rkpm::block_matrix::of(a[k]); });
    };
    std::array<mat2, width> S;
    std::array<double, width> hoop;
    const rkpm::basic_block_lanes<V> Fi =
        rkpm::point_forces_in_lanes<G>(block(F), block(tau), V(weight.data(), rkpm::stdx::element_aligned),
                                       V(radius.data(), rkpm::stdx::element_aligned), S.data(), hoop.data());
    const V stretch = rkpm::support_stretch(Fi, support_inverse);
    for (int k = 0; k < width; ++k) {
      CAPTURE(n);
      CAPTURE(k);
      mat2 S_k;
      double hoop_k;
      const mat2 Fi_k = rkpm::point_forces_of<G>(F[k], tau[k], weight[k], radius[k], S_k, hoop_k);
      const double stretch_k = rkpm::support_stretch(Fi_k, support_inverse);
      const eigen_terms eigen = eigen_point_rule<G>(F[k], tau[k], weight[k], radius[k], support_inverse);
      const double scale = tau[k].cwiseAbs().maxCoeff() * eigen.Fi.cwiseAbs().maxCoeff() * weight[k];
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) {
          CHECK(agree(Fi_k(i, j), eigen.Fi(i, j), 1.0));
          CHECK(agree(S_k(i, j), eigen.S(i, j), scale));
          CHECK(same_bits(S[k](i, j), S_k(i, j)));
        }
      CHECK(agree(hoop_k, eigen.hoop, std::abs(eigen.hoop)));
      CHECK(same_bits(hoop[k], hoop_k));
      CHECK(agree(stretch_k, eigen.stretch, 1.0));
      CHECK(same_bits(stretch[k], stretch_k));
    }
  }
}

// The widths: this build's native vector, and 2, 4 and 8 lanes on any x86-64.
using widths = std::tuple<rkpm::simd_double, rkpm::simd_of<2>, rkpm::simd_of<4>, rkpm::simd_of<8>>;

TEST_CASE_TEMPLATE_DEFINE("point_force_terms: S, the hoop term and the support stretch of a point and of every lane as Eigen's",
                          V, point_force_terms_samples) {
  CAPTURE(rkpm::lanes_of<V>);
  check_samples<rkpm::geometry::axisymmetric, V>();
  check_samples<rkpm::geometry::plane_strain, V>();
}

TEST_CASE_TEMPLATE_DEFINE("point_force_terms: at F = I the support stretch is 1 and S = tau w", V, point_force_terms_identity) {
  using lanes = rkpm::basic_block_lanes<V>;
  constexpr int width = rkpm::lanes_of<V>;
  const lanes identity{};
  lanes tau{V(2e8), V(5e7), V(5e7), V(-1e8), V(3e7)};
  std::array<mat2, width> S;
  std::array<double, width> hoop;
  const lanes Fi = rkpm::point_forces_in_lanes<rkpm::geometry::axisymmetric>(identity, tau, V(2.0), V(4.0), S.data(),
                                                                             hoop.data());
  const V stretch = rkpm::support_stretch(Fi, vec2(1.0 / 3e-3, 1.0 / 1e-3));
  for (int k = 0; k < width; ++k) {
    CHECK(stretch[k] == doctest::Approx(1.0).epsilon(1e-15));
    CHECK(S[k](0, 0) == 4e8);
    CHECK(S[k](0, 1) == 1e8);
    CHECK(S[k](1, 1) == -2e8);
    CHECK(hoop[k] == 3e7 * 2.0 / 4.0);
  }
}

TEST_CASE_TEMPLATE_APPLY(point_force_terms_samples, widths);
TEST_CASE_TEMPLATE_APPLY(point_force_terms_identity, widths);

}  // namespace point_force_terms_test
