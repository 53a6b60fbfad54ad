// shape_table (docs/method.md section 9.3): the compressed rows agree with point-by-point evaluation,
// compact_columns renumbers the columns to the particles the rows reach, and interpolate()
// reproduces linear fields (scalar and vector) exactly, as the linear RK basis promises.
// A values-only table (the one at the particles) keeps the full table's weighted entries exactly.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <rkpm/correction/polynomial_bases.hpp>
#include <rkpm/discretization/shape_table.hpp>
#include <rkpm/kernel/cubic_spline.hpp>
#include <rkpm/kernel/quartic_spline.hpp>

namespace {

using rkpm::index_t;
using rkpm::vec2;
using rkpm::correction::linear;
using rkpm::correction::quadratic;
using rkpm::kernel::cubic_spline;
using rkpm::kernel::quartic_spline;

struct fixture {
  rkpm::particle_set<2> particles;
  std::vector<vec2> points;
  fixture(double factor) {
    const vec2 lo(0, 0), hi(3.2e-3, 6.48e-3);
    particles = rkpm::make_grid_particles<2>(lo, hi, {21, 11}, factor);
    std::mt19937 rng(31);
    std::uniform_real_distribution<double> u(-0.2, 0.2), v(0.0, 1.0);
    for (vec2& x : particles.position) {
      if (x[0] > 0 && x[0] < hi[0]) x[0] += u(rng) * 0.16e-3;
      if (x[1] > 0 && x[1] < hi[1]) x[1] += u(rng) * 0.648e-3;
    }
    points = {lo, hi, vec2(hi[0], 0), vec2(0, hi[1])};
    for (int i = 0; i < 300; ++i) points.emplace_back(v(rng) * hi[0], v(rng) * hi[1]);
  }
};

}  // namespace

TEST_CASE("table rows match direct evaluation") {
  const fixture f(2.0);
  const rkpm::neighbor_search<2> search(f.particles);
  const rkpm::rk_shape_functions<cubic_spline, linear, 2> rk;
  const auto t = rkpm::build_shape_table(search, f.points, rk);
  REQUIRE(t.points() == static_cast<index_t>(f.points.size()));
  REQUIRE(t.offset.front() == 0);
  REQUIRE(t.offset.back() == t.entries());
  CHECK(t.N.size() == t.neighbor.size());
  CHECK(t.grad.size() == t.neighbor.size());
  std::vector<index_t> nbr;
  std::vector<double> N;
  std::vector<vec2> grad;
  for (index_t p = 0; p < t.points(); ++p) {
    search.query(f.points[p], nbr);
    rk.evaluate(f.points[p], f.particles, nbr, N, grad);
    REQUIRE(t.offset[p + 1] - t.offset[p] == static_cast<index_t>(nbr.size()));
    for (std::size_t j = 0; j < nbr.size(); ++j) {
      const index_t e = t.offset[p] + static_cast<index_t>(j);
      CHECK(t.neighbor[e] == nbr[j]);
      CHECK(t.N[e] == N[j]);
      CHECK(t.grad[e] == grad[j]);
    }
  }
}

TEST_CASE("compact_columns: the columns renumbered to the particles the rows reach") {
  const fixture f(2.5);
  const rkpm::neighbor_search<2> search(f.particles);
  // A few rows only (the first three points), so that most particles are not reached.
  const std::vector<rkpm::vec2> few(f.points.begin(), f.points.begin() + 3);
  const auto t = rkpm::build_shape_table<cubic_spline, linear, 2>(search, few);
  const index_t np = f.particles.size();
  auto c = t;
  const auto particle = rkpm::compact_columns(c, np);
  std::vector<index_t> reached(t.neighbor.begin(), t.neighbor.end());
  std::sort(reached.begin(), reached.end());
  reached.erase(std::unique(reached.begin(), reached.end()), reached.end());
  REQUIRE(particle.size() == reached.size());
  CHECK(static_cast<index_t>(particle.size()) < np);
  for (std::size_t k = 0; k < reached.size(); ++k) CHECK(particle[k] == reached[k]);
  for (index_t e = 0; e < t.entries(); ++e) {
    CHECK(particle[c.neighbor[e]] == t.neighbor[e]);
    CHECK(c.N[e] == t.N[e]);
  }
}

TEST_CASE_TEMPLATE("interpolate reproduces linear fields", K, cubic_spline, quartic_spline) {
  const fixture f(2.0);
  const rkpm::neighbor_search<2> search(f.particles);
  const auto t = rkpm::build_shape_table<K, linear, 2>(search, f.points);
  // u = 3 - 250 x + 40 y (scalar), v = (1e-3 + 0.2 x - 0.05 y, -2e-4 + 0.01 x + 0.3 y).
  auto u = [](const vec2& x) { return 3.0 - 250.0 * x[0] + 40.0 * x[1]; };
  auto v = [](const vec2& x) {
    return vec2(1e-3 + 0.2 * x[0] - 0.05 * x[1], -2e-4 + 0.01 * x[0] + 0.3 * x[1]);
  };
  std::vector<double> du;
  std::vector<vec2> dv;
  for (const vec2& X : f.particles.position) {
    du.push_back(u(X));
    dv.push_back(v(X));
  }
  for (index_t p = 0; p < t.points(); ++p) {
    const vec2& x = f.points[p];
    CHECK(t.interpolate(p, du) == doctest::Approx(u(x)).epsilon(1e-12));
    const vec2 got = t.interpolate(p, dv);
    CHECK((got - v(x)).norm() < 1e-12 * 2e-3);
  }
  // The quadratic basis adds x^2, xy, y^2.
  const fixture g(2.5);
  const rkpm::neighbor_search<2> sq(g.particles);
  const auto tq = rkpm::build_shape_table<K, quadratic, 2>(sq, g.points);
  auto w = [](const vec2& x) { return 1.0 + 1e5 * x[0] * x[0] - 3e4 * x[0] * x[1] + 2e4 * x[1] * x[1]; };
  std::vector<double> dw;
  for (const vec2& X : g.particles.position) dw.push_back(w(X));
  for (index_t p = 0; p < tq.points(); ++p)
    CHECK(tq.interpolate(p, dw) == doctest::Approx(w(g.points[p])).epsilon(1e-12));
}

// The table at the particles keeps values only and leaves out entries with |N_I| < 1e-30
// (shape_table_contents values_only): on a regular grid those are the particles exactly one
// support away, inside the support by rounding. What it keeps is the full table's entries,
// bit for bit and in order, and its rows still reproduce constants and linear fields.
TEST_CASE_TEMPLATE("values_only: the weightless entries left out, reproduction kept", K, cubic_spline, quartic_spline) {
  const vec2 lo(0, 0), hi(3.2e-3, 6.48e-3);
  const auto particles = rkpm::make_grid_particles<2>(lo, hi, {21, 11}, 2.0);
  const rkpm::neighbor_search<2> search(particles);
  const rkpm::rk_shape_functions<K, linear, 2> rk;
  const auto full = rkpm::build_shape_table(search, particles.position, rk);
  const auto t = rkpm::build_shape_table(search, particles.position, rk, rkpm::values_only);
  REQUIRE(t.points() == full.points());
  CHECK(t.grad.empty());
  index_t dropped = 0;
  for (index_t p = 0; p < t.points(); ++p) {
    index_t e = t.offset[p];
    for (index_t f = full.offset[p]; f < full.offset[p + 1]; ++f) {
      if (std::abs(full.N[f]) < 1e-30) {
        ++dropped;
        continue;
      }
      REQUIRE(e < t.offset[p + 1]);
      CHECK(t.neighbor[e] == full.neighbor[f]);
      CHECK(t.N[e] == full.N[f]);
      ++e;
    }
    CHECK(e == t.offset[p + 1]);
    // Reproducing conditions on the kept entries: sum N_I = 1, sum N_I X_I = X_p.
    double sum = 0.0;
    vec2 x = vec2::Zero();
    for (index_t k = t.offset[p]; k < t.offset[p + 1]; ++k) {
      sum += t.N[k];
      x += t.N[k] * particles.position[t.neighbor[k]];
    }
    CHECK(std::abs(sum - 1.0) < 1e-13);
    CHECK((x - particles.position[p]).norm() < 1e-13 * hi.norm());
  }
  // The grid has particles exactly one support away (2 spacings in x and in y): the case is met.
  CHECK(dropped > 0);
  CHECK(t.entries() + dropped == full.entries());
}
