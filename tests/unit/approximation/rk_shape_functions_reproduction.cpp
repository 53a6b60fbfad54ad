// Reproducing conditions of the RK shape functions (docs/method.md (10)-(11)):
//   sum_I N_I(x) p(X_I) = p(x)   and   sum_I grad N_I(x) p(X_I) = grad p(x)
// for every monomial p up to the correction order (linear: 1, x, y; quadratic: also x^2, xy,
// y^2), for both kernels and both corrections, on a uniform grid, a 20% randomly perturbed
// grid (fixed seed), the Taylor bar's 4:1 anisotropic grid (0.16 mm x 0.648 mm, 21 x 51
// particles on [0, 3.2e-3] x [0, 32.4e-3] m) and a geometrically graded grid, at random
// interior points, at particles, along every edge and at every corner.
//
// Error measure (relative, tolerance 1e-12), with a = the neighbors' mean support:
//   values     |sum_I N_I p(X_I) - p(x)|            / sum_I |N_I| (|p(X_I)| + p(a))
//   gradients  |sum_I grad N_I p(X_I) - grad p|_inf / (sum_I |grad N_I|_inf (|p(X_I)| + p(a))
//                                                      + |grad p(x)|_inf)
// i.e. the error relative to the size of the terms that are summed, which is what round-off
// in N_I can affect (about eps times the condition number of M). The floor p(a) (the
// monomial at the support size) keeps the measure meaningful where p(X_I) all vanish, e.g.
// p = x at a point on the edge x = 0, where the exact sum is 0 and only round-off remains.
//
// Support factors a_k = s h_k: s = 2.0 for the linear basis (the 3 x 3 neighborhood of a
// corner point is covered), s = 2.5 for the quadratic one (a corner point still sees three
// particles per direction after the 20% perturbation, enough for x^2 and y^2).

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <random>
#include <string>
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
using rkpm::vec;
using rkpm::vec2;

struct test_set {
  std::string name;
  particle_set<2> particles;
  std::vector<vec2> points;
};

template <class C>
double reproduction_support_factor() {
  return C::order == 1 ? 2.0 : 2.5;
}

// Evaluation points in the box [lo, hi]: the 4 corners, 7 points along each edge (including
// points a hair inside), and `random` uniformly random interior points.
std::vector<vec2> box_points(const vec2& lo, const vec2& hi, int random, std::mt19937& rng) {
  std::vector<vec2> pts;
  const vec2 d = hi - lo;
  for (double fx : {0.0, 1.0})
    for (double fy : {0.0, 1.0}) pts.emplace_back(lo[0] + fx * d[0], lo[1] + fy * d[1]);
  for (double t : {1e-9, 0.013, 0.21, 0.5, 0.77, 0.995, 1.0 - 1e-9}) {
    pts.emplace_back(lo[0] + t * d[0], lo[1]);
    pts.emplace_back(lo[0] + t * d[0], hi[1]);
    pts.emplace_back(lo[0], lo[1] + t * d[1]);
    pts.emplace_back(hi[0], lo[1] + t * d[1]);
  }
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < random; ++i) pts.emplace_back(lo[0] + u(rng) * d[0], lo[1] + u(rng) * d[1]);
  return pts;
}

void add_particle_points(test_set& s, int stride) {
  for (index_t i = 0; i < s.particles.size(); i += stride) s.points.push_back(s.particles.position[i]);
}

test_set uniform_set(double factor) {
  std::mt19937 rng(11);
  test_set s{"uniform 21 x 11 on [0,2] x [0,1]",
             rkpm::make_grid_particles<2>(vec2(0, 0), vec2(2, 1), {21, 11}, factor), {}};
  s.points = box_points(vec2(0, 0), vec2(2, 1), 60, rng);
  add_particle_points(s, 7);
  return s;
}

// Interior particles move by up to 20% of the spacing in each direction; edge particles only
// along their edge and corners not at all, so that the domain stays the box.
test_set perturbed_set(double factor) {
  const vec2 lo(-0.5, 0.25), hi(1.5, 1.25);
  const vec2 h(0.1, 0.1);
  test_set s{"20% perturbed 21 x 11 on [-0.5,1.5] x [0.25,1.25]",
             rkpm::make_grid_particles<2>(lo, hi, {21, 11}, factor), {}};
  std::mt19937 rng(20240611);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  for (vec2& x : s.particles.position)
    for (int k = 0; k < 2; ++k) {
      const bool on_edge = std::abs(x[k] - lo[k]) < 1e-12 || std::abs(x[k] - hi[k]) < 1e-12;
      if (!on_edge) x[k] += u(rng) * h[k];
    }
  s.points = box_points(lo, hi, 60, rng);
  add_particle_points(s, 5);
  return s;
}

test_set taylor_set(double factor) {
  std::mt19937 rng(3);
  const vec2 hi(3.2e-3, 32.4e-3);
  test_set s{"Taylor bar 21 x 51, 0.16 mm x 0.648 mm",
             rkpm::make_grid_particles<2>(vec2(0, 0), hi, {21, 51}, factor), {}};
  s.points = box_points(vec2(0, 0), hi, 80, rng);
  add_particle_points(s, 23);
  return s;
}

// Spacing grows by 1.15 per particle in x (ratio 8 across the bar), uniform in y. Each
// particle's support is the factor times its larger neighboring spacing per direction; the
// volume is its tributary area.
test_set graded_set(double factor) {
  const int nx = 16, ny = 9;
  std::vector<double> xs(nx), ys(ny);
  double step = 1.0, acc = 0.0;
  for (int i = 0; i < nx; ++i) {
    xs[i] = acc;
    acc += step;
    step *= 1.15;
  }
  for (double& x : xs) x *= 4.0 / xs.back();
  for (int j = 0; j < ny; ++j) ys[j] = 0.25 * j;
  auto local = [](const std::vector<double>& c, int i, double& width, double& trib) {
    const double left = i > 0 ? c[i] - c[i - 1] : 0.0;
    const double right = i + 1 < static_cast<int>(c.size()) ? c[i + 1] - c[i] : 0.0;
    width = std::max(left, right);
    trib = 0.5 * (left + right);
  };
  test_set s{"graded 16 x 9, x spacing ratio 1.15", {}, {}};
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      double wx, tx, wy, ty;
      local(xs, i, wx, tx);
      local(ys, j, wy, ty);
      s.particles.position.emplace_back(xs[i], ys[j]);
      s.particles.volume.push_back(tx * ty);
      s.particles.support.emplace_back(factor * wx, factor * wy);
    }
  std::mt19937 rng(5);
  s.points = box_points(vec2(0, 0), vec2(4, 2), 60, rng);
  add_particle_points(s, 3);
  return s;
}

struct monomial {
  const char* name;
  std::function<double(const vec2&)> p;
  std::function<vec2(const vec2&)> grad;
};

std::vector<monomial> monomials(int order) {
  std::vector<monomial> m = {
      {"1", [](const vec2&) { return 1.0; }, [](const vec2&) { return vec2(0, 0); }},
      {"x", [](const vec2& x) { return x[0]; }, [](const vec2&) { return vec2(1, 0); }},
      {"y", [](const vec2& x) { return x[1]; }, [](const vec2&) { return vec2(0, 1); }}};
  if (order >= 2) {
    m.push_back({"x^2", [](const vec2& x) { return x[0] * x[0]; },
                 [](const vec2& x) { return vec2(2 * x[0], 0); }});
    m.push_back({"xy", [](const vec2& x) { return x[0] * x[1]; },
                 [](const vec2& x) { return vec2(x[1], x[0]); }});
    m.push_back({"y^2", [](const vec2& x) { return x[1] * x[1]; },
                 [](const vec2& x) { return vec2(0, 2 * x[1]); }});
  }
  return m;
}

template <class K, class C>
struct reproduction_combo {
  using kernel = K;
  using correction = C;
};

using rkpm::correction::linear;
using rkpm::correction::quadratic;
using rkpm::kernel::cubic_spline;
using rkpm::kernel::quartic_spline;

template <class K, class C>
void check_reproduction(const test_set& s) {
  const rkpm::neighbor_search<2> search(s.particles);
  const rkpm::rk_shape_functions<K, C, 2> rk;
  std::vector<index_t> nbr;
  std::vector<double> N;
  std::vector<vec2> grad;
  double worst_value = 0.0, worst_grad = 0.0;
  for (const vec2& x : s.points) {
    search.query(x, nbr);
    rk.evaluate(x, s.particles, nbr, N, grad);
    vec2 a = vec2::Zero();
    for (index_t I : nbr) a += s.particles.support[I];
    a /= static_cast<double>(nbr.size());
    for (const monomial& m : monomials(C::order)) {
      const double floor = m.p(a);
      double sum = -m.p(x), scale = 0.0;
      vec2 gsum = -m.grad(x);
      double gscale = m.grad(x).cwiseAbs().maxCoeff();
      for (std::size_t j = 0; j < nbr.size(); ++j) {
        const double pI = m.p(s.particles.position[nbr[j]]);
        sum += N[j] * pI;
        scale += std::abs(N[j]) * (std::abs(pI) + floor);
        gsum += grad[j] * pI;
        gscale += grad[j].cwiseAbs().maxCoeff() * (std::abs(pI) + floor);
      }
      const double ev = std::abs(sum) / scale;
      const double eg = gsum.cwiseAbs().maxCoeff() / gscale;
      worst_value = std::max(worst_value, ev);
      worst_grad = std::max(worst_grad, eg);
      INFO(s.name << ", point (" << x.transpose() << "), monomial " << m.name << ", "
                  << nbr.size() << " neighbors");
      CHECK(ev < 1e-12);
      CHECK(eg < 1e-12);
    }
  }
  MESSAGE(K::name << " + " << C::name << " on " << s.name << ": worst relative error "
                  << worst_value << " (values), " << worst_grad << " (gradients)");
}

}  // namespace

TEST_CASE_TEMPLATE("RK reproduction of monomials and their gradients", T,
                   reproduction_combo<cubic_spline, linear>, reproduction_combo<cubic_spline, quadratic>,
                   reproduction_combo<quartic_spline, linear>, reproduction_combo<quartic_spline, quadratic>) {
  using K = typename T::kernel;
  using C = typename T::correction;
  const double s = reproduction_support_factor<C>();
  SUBCASE("uniform") { check_reproduction<K, C>(uniform_set(s)); }
  SUBCASE("perturbed") { check_reproduction<K, C>(perturbed_set(s)); }
  SUBCASE("taylor") { check_reproduction<K, C>(taylor_set(s)); }
  SUBCASE("graded") { check_reproduction<K, C>(graded_set(s)); }
}

TEST_CASE_TEMPLATE("RK reproduction in 1D (11 particles on [0, 1], ends included)", T,
                   reproduction_combo<cubic_spline, linear>, reproduction_combo<cubic_spline, quadratic>,
                   reproduction_combo<quartic_spline, linear>, reproduction_combo<quartic_spline, quadratic>) {
  using K = typename T::kernel;
  using C = typename T::correction;
  const auto p = rkpm::make_grid_particles<1>(vec<1>(0.0), vec<1>(1.0),
                                              Eigen::Matrix<int, 1, 1>(11), reproduction_support_factor<C>());
  const rkpm::neighbor_search<1> search(p);
  const rkpm::rk_shape_functions<K, C, 1> rk;
  std::vector<index_t> nbr;
  std::vector<double> N;
  std::vector<vec<1>> grad;
  for (int i = 0; i <= 200; ++i) {
    const vec<1> x(i / 200.0);
    search.query(x, nbr);
    rk.evaluate(x, p, nbr, N, grad);
    const double floor_base = p.support[0][0];
    for (int deg = 0; deg <= C::order; ++deg) {
      const double floor = std::pow(floor_base, deg);
      double sum = -std::pow(x[0], deg), scale = 0.0;
      double gsum = -(deg > 0 ? deg * std::pow(x[0], deg - 1) : 0.0);
      double gscale = std::abs(gsum);
      for (std::size_t j = 0; j < nbr.size(); ++j) {
        const double pI = std::pow(p.position[nbr[j]][0], deg);
        sum += N[j] * pI;
        scale += std::abs(N[j]) * (std::abs(pI) + floor);
        gsum += grad[j][0] * pI;
        gscale += std::abs(grad[j][0]) * (std::abs(pI) + floor);
      }
      INFO("x = " << x[0] << ", degree " << deg);
      CHECK(std::abs(sum) < 1e-12 * scale);
      CHECK(std::abs(gsum) < 1e-12 * gscale);
    }
  }
}

TEST_CASE("the error measure discriminates: the linear basis does not reproduce x^2") {
  // Guards against a measure (or a set of points) too lenient to see a missing monomial.
  const test_set s = perturbed_set(2.0);
  const rkpm::neighbor_search<2> search(s.particles);
  const rkpm::rk_shape_functions<cubic_spline, linear, 2> rk;
  std::vector<index_t> nbr;
  std::vector<double> N;
  std::vector<vec2> grad;
  double worst = 0.0;
  for (const vec2& x : s.points) {
    search.query(x, nbr);
    rk.evaluate(x, s.particles, nbr, N, grad);
    double sum = -x[0] * x[0], scale = 0.0;
    for (std::size_t j = 0; j < nbr.size(); ++j) {
      const double pI = s.particles.position[nbr[j]][0] * s.particles.position[nbr[j]][0];
      sum += N[j] * pI;
      scale += std::abs(N[j]) * (pI + 0.2 * 0.2);
    }
    worst = std::max(worst, std::abs(sum) / scale);
  }
  CHECK(worst > 1e-3);
}
