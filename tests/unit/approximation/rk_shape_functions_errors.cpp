// Clear errors instead of garbage (docs/method.md section 2.4): a point whose neighbors
// cannot support the basis throws rkpm::error naming the point, the neighbor count and the
// condition estimate; a point covered by no support throws; a table build reports the same.

#include <doctest/doctest.h>

#include <string>
#include <vector>

#include <rkpm/correction/polynomial_bases.hpp>
#include <rkpm/approximation/rk_shape_functions.hpp>
#include <rkpm/discretization/neighbor_search.hpp>
#include <rkpm/discretization/particle_set.hpp>
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

// The message of the rkpm::error thrown by f, or "" when none is thrown.
template <class F>
std::string error_of(F f) {
  try {
    f();
  } catch (const rkpm::error& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE_TEMPLATE("quadratic basis on too small supports: error names point, count, condition",
                   K, cubic_spline, quartic_spline) {
  // Spacing 0.1, support 1.1 h: the point (0.05, 0.05) sees the 2 x 2 particles around it,
  // fewer than the 6 quadratic monomials (and only two abscissae for x^2).
  const auto p = rkpm::make_grid_particles<2>(vec2(0, 0), vec2(1, 1), {11, 11}, 1.1);
  const rkpm::neighbor_search<2> search(p);
  const vec2 x(0.05, 0.05);
  const auto nbr = search.query(x);
  REQUIRE(nbr.size() == 4);
  std::vector<double> N;
  std::vector<vec2> grad;
  const rkpm::rk_shape_functions<K, quadratic, 2> rk;
  const std::string msg = error_of([&] { rk.evaluate(x, p, nbr, N, grad); });
  INFO(msg);
  CHECK(contains(msg, "0.05, 0.05"));
  CHECK(contains(msg, "4 neighbors"));
  CHECK(contains(msg, "condition"));
  CHECK(contains(msg, "support factor"));  // the fix

  // The same particles are fine for the linear basis (4 >= 3 neighbors, not collinear).
  const rkpm::rk_shape_functions<K, linear, 2> rk1;
  CHECK_NOTHROW(rk1.evaluate(x, p, nbr, N, grad));

  // A table build stops with the same kind of message.
  std::vector<vec2> points = {vec2(0.5, 0.5), x, vec2(0.31, 0.77)};
  const std::string msg2 = error_of([&] { rkpm::build_shape_table(search, points, rk); });
  INFO(msg2);
  CHECK(contains(msg2, "condition"));
  CHECK(contains(msg2, "neighbors"));
}

TEST_CASE("a tighter condition limit turns an accepted point into an error") {
  const auto p = rkpm::make_grid_particles<2>(vec2(0, 0), vec2(1, 1), {11, 11}, 2.5);
  const rkpm::neighbor_search<2> search(p);
  const vec2 x(0.0, 0.0);  // corner: the worst conditioned point of the set
  const auto nbr = search.query(x);
  std::vector<double> N;
  std::vector<vec2> grad;
  CHECK_NOTHROW(rkpm::rk_shape_functions<cubic_spline, quadratic, 2>().evaluate(x, p, nbr, N, grad));
  const rkpm::rk_shape_functions<cubic_spline, quadratic, 2> strict(1.0);
  CHECK(strict.max_condition() == 1.0);
  CHECK(contains(error_of([&] { strict.evaluate(x, p, nbr, N, grad); }), "condition"));
}

TEST_CASE("a point outside every support is an error, not an empty sum") {
  const auto p = rkpm::make_grid_particles<2>(vec2(0, 0), vec2(1, 1), {11, 11}, 2.0);
  const rkpm::neighbor_search<2> search(p);
  const vec2 x(3.0, 0.5);
  const auto nbr = search.query(x);
  CHECK(nbr.empty());
  std::vector<double> N;
  std::vector<vec2> grad;
  const std::string msg = error_of(
      [&] { rkpm::rk_shape_functions<quartic_spline, linear, 2>().evaluate(x, p, nbr, N, grad); });
  INFO(msg);
  CHECK(contains(msg, "3, 0.5"));
  CHECK(contains(msg, "outside"));
}

TEST_CASE("zero or negative supports and volumes name the particle") {
  auto p = rkpm::make_grid_particles<2>(vec2(0, 0), vec2(1, 1), {5, 5}, 2.0);
  CHECK_NOTHROW(p.validate());

  SUBCASE("zero support") {
    p.support[7][1] = 0.0;
    const std::string msg = error_of([&] { p.validate(); });
    INFO(msg);
    CHECK(contains(msg, "particle 7"));
    CHECK(contains(msg, "support"));
    CHECK(contains(msg, "direction 1"));
    CHECK(contains(error_of([&] { rkpm::neighbor_search<2> s(p); }), "particle 7"));
  }
  SUBCASE("negative support") {
    p.support[3][0] = -0.5;
    const std::string msg = error_of([&] { rkpm::neighbor_search<2> s(p); });
    INFO(msg);
    CHECK(contains(msg, "particle 3"));
    CHECK(contains(msg, "-0.5"));
    CHECK(contains(msg, "support factor"));
  }
  SUBCASE("zero volume") {
    p.volume[12] = 0.0;
    CHECK(contains(error_of([&] { p.validate(); }), "particle 12"));
  }
  SUBCASE("mismatched lengths") {
    p.support.pop_back();
    CHECK(contains(error_of([&] { p.validate(); }), "25 positions"));
  }
  SUBCASE("empty set") {
    const rkpm::particle_set<2> empty;
    CHECK(contains(error_of([&] { rkpm::neighbor_search<2> s(empty); }), "empty"));
  }
}
