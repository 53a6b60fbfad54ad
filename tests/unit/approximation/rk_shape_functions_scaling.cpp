// Scale invariance of the RK shape functions (libigl-style property test): the same particle
// set given in metres and scaled by f (positions and supports times f, volumes times f^2, i.e.
// millimetres for f = 1e3, and the extreme f = 1e-8 and 1e8) gives the same N and grad N
// divided by f, entry by entry, to 1e-12 relative to sum |N| and sum |grad N|_inf. This holds
// only because the basis is scaled by the support (docs/method.md (8)): with unscaled
// monomials M would be singular to round-off at f = 1e-8.

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
struct scaling_combo {
  using kernel = K;
  using correction = C;
};

particle_set<2> scaled(const particle_set<2>& p, double f) {
  particle_set<2> q = p;
  for (vec2& x : q.position) x *= f;
  for (vec2& a : q.support) a *= f;
  for (double& v : q.volume) v *= f * f;
  return q;
}

struct dense {
  std::vector<double> N;
  std::vector<vec2> grad;
};

template <class K, class C>
dense evaluate_dense(const particle_set<2>& p, const vec2& x) {
  const rkpm::neighbor_search<2> search(p);
  const rkpm::rk_shape_functions<K, C, 2> rk;
  std::vector<index_t> nbr;
  std::vector<double> N;
  std::vector<vec2> grad;
  search.query(x, nbr);
  rk.evaluate(x, p, nbr, N, grad);
  dense d{std::vector<double>(p.size(), 0.0), std::vector<vec2>(p.size(), vec2::Zero())};
  for (std::size_t j = 0; j < nbr.size(); ++j) {
    d.N[nbr[j]] = N[j];
    d.grad[nbr[j]] = grad[j];
  }
  return d;
}

template <class K, class C>
void check_scaling(const particle_set<2>& metres, const std::vector<vec2>& points) {
  for (double f : {1e3, 1e-8, 1e8}) {
    const particle_set<2> other = scaled(metres, f);
    double worst_N = 0.0, worst_grad = 0.0;
    for (const vec2& x : points) {
      const dense a = evaluate_dense<K, C>(metres, x);
      const dense b = evaluate_dense<K, C>(other, vec2(x * f));
      double sN = 0.0, sg = 0.0, eN = 0.0, eg = 0.0;
      for (index_t I = 0; I < metres.size(); ++I) {
        sN += std::abs(a.N[I]);
        sg += a.grad[I].cwiseAbs().maxCoeff();
        eN = std::max(eN, std::abs(a.N[I] - b.N[I]));
        eg = std::max(eg, (a.grad[I] - f * b.grad[I]).cwiseAbs().maxCoeff());
      }
      worst_N = std::max(worst_N, eN / sN);
      worst_grad = std::max(worst_grad, eg / sg);
    }
    MESSAGE(K::name << " + " << C::name << ", f = " << f << ": worst relative difference "
                    << worst_N << " (N), " << worst_grad << " (grad N)");
    CHECK(worst_N < 1e-12);
    CHECK(worst_grad < 1e-12);
  }
}

}  // namespace

using rkpm::correction::linear;
using rkpm::correction::quadratic;
using rkpm::kernel::cubic_spline;
using rkpm::kernel::quartic_spline;

TEST_CASE_TEMPLATE("RK shape functions: same N and grad N / f in scaled units", T,
                   scaling_combo<cubic_spline, linear>, scaling_combo<cubic_spline, quadratic>,
                   scaling_combo<quartic_spline, linear>, scaling_combo<quartic_spline, quadratic>) {
  using K = typename T::kernel;
  using C = typename T::correction;
  const double s = C::order == 1 ? 2.0 : 2.5;
  // Taylor bar set in metres, lightly perturbed so that nothing is exactly on a grid line.
  const vec2 hi(3.2e-3, 32.4e-3);
  auto p = rkpm::make_grid_particles<2>(vec2(0, 0), hi, {21, 51}, s);
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> u(-0.15, 0.15);
  for (vec2& x : p.position) {
    if (x[0] > 0.0 && x[0] < hi[0]) x[0] += u(rng) * 0.16e-3;
    if (x[1] > 0.0 && x[1] < hi[1]) x[1] += u(rng) * 0.648e-3;
  }
  std::vector<vec2> points = {vec2(0, 0), hi, vec2(hi[0], 0), vec2(0, 0.5 * hi[1])};
  std::uniform_real_distribution<double> v(0.0, 1.0);
  for (int i = 0; i < 30; ++i) points.emplace_back(v(rng) * hi[0], v(rng) * hi[1]);
  check_scaling<K, C>(p, points);
}
