// neighbor_search (cell lists) against brute force: for random clouds with random
// per-particle, per-direction supports, every query returns exactly the particles I with
// |x_k - X_Ik| < a_Ik in every direction, in ascending order, including query points far
// outside the cloud, on its bounding box, and in 1D.

#include <doctest/doctest.h>

#include <random>
#include <vector>

#include <rkpm/discretization/neighbor_search.hpp>
#include <rkpm/discretization/particle_set.hpp>

namespace {

using rkpm::index_t;
using rkpm::particle_set;
using rkpm::vec;

template <int Dim>
std::vector<index_t> brute_force(const particle_set<Dim>& p, const vec<Dim>& x) {
  std::vector<index_t> out;
  for (index_t i = 0; i < p.size(); ++i) {
    bool inside = true;
    for (int k = 0; k < Dim; ++k) inside = inside && std::abs(x[k] - p.position[i][k]) < p.support[i][k];
    if (inside) out.push_back(i);
  }
  return out;
}

// n particles uniform in [lo, hi]^Dim with supports a_k uniform in [amin, amax], independently
// per particle and direction.
template <int Dim>
particle_set<Dim> random_cloud(int n, double lo, double hi, double amin, double amax,
                               std::mt19937& rng) {
  std::uniform_real_distribution<double> ux(lo, hi), ua(amin, amax);
  particle_set<Dim> p;
  for (int i = 0; i < n; ++i) {
    vec<Dim> x, a;
    for (int k = 0; k < Dim; ++k) {
      x[k] = ux(rng);
      a[k] = ua(rng);
    }
    p.position.push_back(x);
    p.support.push_back(a);
    p.volume.push_back(1.0);
  }
  return p;
}

template <int Dim>
void compare(const particle_set<Dim>& p, const std::vector<vec<Dim>>& queries,
             std::size_t& nonempty) {
  const rkpm::neighbor_search<Dim> search(p);
  std::vector<index_t> got;
  for (const auto& x : queries) {
    search.query(x, got);
    const auto expect = brute_force(p, x);
    INFO("query (" << x.transpose() << ")");
    CHECK(got == expect);
    if (!expect.empty()) ++nonempty;
  }
}

}  // namespace

TEST_CASE("2D random clouds, random supports: cell lists equal brute force") {
  std::mt19937 rng(12345);
  std::size_t nonempty = 0, total = 0;
  struct shape {
    int n;
    double lo, hi, amin, amax;
  };
  // Dense with small supports, sparse with large ones, mixed scales (1e-3 m cloud with
  // supports from a tenth to a half of it), and a tiny cloud.
  for (const shape s : {shape{2000, 0.0, 1.0, 0.005, 0.08}, shape{300, -5.0, 5.0, 0.5, 4.0},
                        shape{800, 0.0, 1e-3, 1e-6, 5e-4}, shape{3, 0.0, 1.0, 0.1, 0.9}}) {
    const auto p = random_cloud<2>(s.n, s.lo, s.hi, s.amin, s.amax, rng);
    const double w = s.hi - s.lo;
    std::uniform_real_distribution<double> uq(s.lo - 0.5 * w, s.hi + 0.5 * w);
    std::vector<rkpm::vec2> queries;
    for (int i = 0; i < 1500; ++i) queries.emplace_back(uq(rng), uq(rng));
    // Far outside, on the cloud's own particles, and at its bounding-box corners.
    queries.emplace_back(s.hi + 100.0 * w, s.lo);
    queries.emplace_back(s.lo - 1e6 * w, s.lo - 1e6 * w);
    queries.emplace_back(1e300, -1e300);
    for (index_t i = 0; i < p.size(); i += 17) queries.push_back(p.position[i]);
    compare<2>(p, queries, nonempty);
    total += queries.size();
  }
  // The comparison is only meaningful if most queries find something.
  CHECK(nonempty > total / 3);
}

TEST_CASE("grid particles: a query at a particle finds the (2s-1)^2 stencil, edges excluded") {
  // Support exactly 2h: the particles at distance 2h lie on the support edge, where the
  // window is zero; the strict test excludes them, leaving 3 x 3. h = 1/8 so that positions
  // and distances are exact (with h = 0.1, 0.5 - 0.3 rounds below 0.2 and 0.7 - 0.5 above).
  const auto p = rkpm::make_grid_particles<2>(rkpm::vec2(0, 0), rkpm::vec2(1, 1), {9, 9}, 2.0);
  const rkpm::neighbor_search<2> search(p);
  const auto centre = search.query(rkpm::vec2(0.5, 0.5));
  CHECK(centre.size() == 9);
  const auto corner = search.query(rkpm::vec2(0.0, 0.0));
  CHECK(corner.size() == 4);
  std::size_t dummy = 0;
  compare<2>(p, {rkpm::vec2(0.0625, 0.0625), rkpm::vec2(1.0, 1.0), rkpm::vec2(1.2, 0.5)}, dummy);
}

TEST_CASE("1D random cloud") {
  std::mt19937 rng(99);
  const auto p = random_cloud<1>(500, 0.0, 10.0, 0.01, 0.6, rng);
  std::uniform_real_distribution<double> uq(-3.0, 13.0);
  std::vector<vec<1>> queries;
  for (int i = 0; i < 2000; ++i) queries.emplace_back(uq(rng));
  std::size_t nonempty = 0;
  compare<1>(p, queries, nonempty);
  CHECK(nonempty > 1000);
}

TEST_CASE("single particle and identical positions") {
  particle_set<2> p;
  p.position = {rkpm::vec2(1, 1)};
  p.support = {rkpm::vec2(0.5, 0.25)};
  p.volume = {1.0};
  const rkpm::neighbor_search<2> one(p);
  CHECK(one.query(rkpm::vec2(1.4, 1.2)) == std::vector<index_t>{0});
  CHECK(one.query(rkpm::vec2(1.4, 1.3)).empty());
  // All particles at one spot: the cloud has zero extent, one cell.
  p.position.assign(4, rkpm::vec2(2, -1));
  p.support.assign(4, rkpm::vec2(1, 1));
  p.volume.assign(4, 1.0);
  const rkpm::neighbor_search<2> same(p);
  CHECK(same.query(rkpm::vec2(2.5, -0.5)) == std::vector<index_t>{0, 1, 2, 3});
  CHECK(same.query(rkpm::vec2(3.5, -0.5)).empty());
}

TEST_CASE("a search over some of the particles: brute force's among those, by their indices in the set") {
  // One body's search among several (discretization/search_rows.hpp, body_searches): every third
  // particle of a random cloud, larger supports on the others so that they would be found.
  std::mt19937 rng(7);
  auto p = random_cloud<2>(600, 0.0, 1.0, 0.02, 0.1, rng);
  std::vector<index_t> some;
  for (index_t i = 0; i < p.size(); ++i)
    if (i % 3 == 1) some.push_back(i);
    else p.support[i] *= 2.0;
  const rkpm::neighbor_search<2> search(p, nullptr, some);
  std::uniform_real_distribution<double> uq(-0.2, 1.2);
  std::size_t found = 0, others = 0;
  for (int k = 0; k < 1000; ++k) {
    const rkpm::vec2 x(uq(rng), uq(rng));
    std::vector<index_t> expect;
    for (const index_t i : brute_force(p, x))
      if (i % 3 == 1) expect.push_back(i);
      else ++others;
    CHECK(search.query(x) == expect);
    found += expect.size();
  }
  CHECK(found > 1000);
  CHECK(others > found);
  CHECK_THROWS_WITH(rkpm::neighbor_search<2>(p, nullptr, std::vector<index_t>{}),
                    doctest::Contains("over none of the particles"));
  CHECK_THROWS_WITH(rkpm::neighbor_search<2>(p, nullptr, std::vector<index_t>{3, 600}),
                    doctest::Contains("over particle 600 of 600"));
}
