// Gradients of the RK shape functions (docs/method.md (11)-(14), d(M^-1) = -M^-1 dM M^-1)
// against central finite differences of N itself, with step 1e-6 times the support in each
// direction, on a 20% perturbed grid and the Taylor bar's anisotropic grid (metres), for both
// kernels and both corrections, at interior points, particles, edges and corners.
//
// Error measure: |grad N_I - fd_I|_inf <= 1e-7 * sum_J |grad N_J|_inf at each point. The
// difference quotient carries ~eps |N| / step ~ 1e-10 / a of round-off and ~1e-12 of
// truncation, against sum |grad N| ~ 1 / a.

#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <vector>

#include <rkpm/correction/polynomial_bases.hpp>
#include <rkpm/approximation/rk_shape_functions.hpp>
#include <rkpm/discretization/neighbor_search.hpp>
#include <rkpm/discretization/particle_set.hpp>
#include <rkpm/kernel/cubic_spline.hpp>
#include <rkpm/kernel/quartic_spline.hpp>

namespace {

using rkpm::index_t;
using rkpm::particle_set;
using rkpm::vec2;

template <class K, class C>
struct combo {
  using kernel = K;
  using correction = C;
};

template <class C>
double support_factor() {
  return C::order == 1 ? 2.0 : 2.5;
}

particle_set<2> perturbed(const vec2& lo, const vec2& hi, Eigen::Vector2i n, double factor) {
  auto p = rkpm::make_grid_particles<2>(lo, hi, n, factor);
  const vec2 h = (hi - lo).cwiseQuotient(vec2(n[0] - 1, n[1] - 1));
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  for (vec2& x : p.position)
    for (int k = 0; k < 2; ++k)
      if (std::abs(x[k] - lo[k]) > 1e-12 * h[k] && std::abs(x[k] - hi[k]) > 1e-12 * h[k])
        x[k] += u(rng) * h[k];
  return p;
}

std::vector<vec2> points_in(const vec2& lo, const vec2& hi, const particle_set<2>& p) {
  std::vector<vec2> pts = {lo, hi, vec2(lo[0], hi[1]), vec2(hi[0], lo[1]),
                           vec2(0.5 * (lo[0] + hi[0]), lo[1]), vec2(hi[0], 0.3 * lo[1] + 0.7 * hi[1])};
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 40; ++i)
    pts.emplace_back(lo[0] + u(rng) * (hi[0] - lo[0]), lo[1] + u(rng) * (hi[1] - lo[1]));
  for (index_t i = 0; i < p.size(); i += 13) pts.push_back(p.position[i]);
  return pts;
}

// N at x as a dense vector over all particles (zero outside the neighbor list).
template <class K, class C>
std::vector<double> dense_N(const rkpm::neighbor_search<2>& search, const vec2& x) {
  const rkpm::rk_shape_functions<K, C, 2> rk;
  std::vector<index_t> nbr;
  std::vector<double> N;
  std::vector<vec2> grad;
  search.query(x, nbr);
  rk.evaluate(x, search.particles(), nbr, N, grad);
  std::vector<double> d(search.particles().size(), 0.0);
  for (std::size_t j = 0; j < nbr.size(); ++j) d[nbr[j]] = N[j];
  return d;
}

template <class K, class C>
void check_gradients(const particle_set<2>& p, const std::vector<vec2>& points) {
  const rkpm::neighbor_search<2> search(p);
  const rkpm::rk_shape_functions<K, C, 2> rk;
  std::vector<index_t> nbr;
  std::vector<double> N;
  std::vector<vec2> grad;
  double worst = 0.0;
  for (const vec2& x : points) {
    search.query(x, nbr);
    rk.evaluate(x, p, nbr, N, grad);
    vec2 a = vec2::Zero();
    double gscale = 0.0;
    for (std::size_t j = 0; j < nbr.size(); ++j) {
      a += p.support[nbr[j]];
      gscale += grad[j].cwiseAbs().maxCoeff();
    }
    a /= static_cast<double>(nbr.size());
    for (int k = 0; k < 2; ++k) {
      const double step = 1e-6 * a[k];
      vec2 xp = x, xm = x;
      xp[k] += step;
      xm[k] -= step;
      const auto Np = dense_N<K, C>(search, xp);
      const auto Nm = dense_N<K, C>(search, xm);
      std::vector<double> g(p.size(), 0.0);
      for (std::size_t j = 0; j < nbr.size(); ++j) g[nbr[j]] = grad[j][k];
      for (index_t I = 0; I < p.size(); ++I) {
        const double fd = (Np[I] - Nm[I]) / (2.0 * step);
        const double err = std::abs(fd - g[I]) / gscale;
        worst = std::max(worst, err);
        INFO("point (" << x.transpose() << "), particle " << I << ", direction " << k);
        if (err >= 1e-7) CHECK(err < 1e-7);
      }
    }
  }
  MESSAGE(K::name << " + " << C::name << ": worst relative difference to central differences "
                  << worst);
  CHECK(worst < 1e-7);
}

}  // namespace

using rkpm::correction::linear;
using rkpm::correction::quadratic;
using rkpm::kernel::cubic_spline;
using rkpm::kernel::quartic_spline;

TEST_CASE_TEMPLATE("RK gradients against central differences of N", T,
                   combo<cubic_spline, linear>, combo<cubic_spline, quadratic>,
                   combo<quartic_spline, linear>, combo<quartic_spline, quadratic>) {
  using K = typename T::kernel;
  using C = typename T::correction;
  SUBCASE("20% perturbed grid") {
    const vec2 lo(0.0, 0.0), hi(1.0, 0.6);
    const auto p = perturbed(lo, hi, {11, 7}, support_factor<C>());
    check_gradients<K, C>(p, points_in(lo, hi, p));
  }
  SUBCASE("Taylor bar grid, metres") {
    const vec2 lo(0.0, 0.0), hi(3.2e-3, 32.4e-3);
    const auto p = rkpm::make_grid_particles<2>(lo, hi, {21, 51}, support_factor<C>());
    check_gradients<K, C>(p, points_in(lo, hi, p));
  }
}
