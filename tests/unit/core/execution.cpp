// The execution layer (core/execution.hpp) and its fixed-block sums (core/block_sums.hpp):
// every index visited once; sums, maxima and minima the same on one thread and on two; an
// error thrown by a row comes out of the parallel loop; the coloured loop runs colour after
// colour; on one process the exchange points accept an all-owned model and refuse ghosts.

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include <rkpm/core/execution.hpp>

namespace test_unit_core_execution {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

namespace {

void use_threads([[maybe_unused]] int threads) {
#ifdef _OPENMP
  omp_set_num_threads(threads);
#endif
}

std::vector<double> wiggles(index_t n) {
  std::vector<double> x(n);
  for (index_t I = 0; I < n; ++I) x[I] = std::sin(0.37 * static_cast<double>(I)) * std::exp(0.001 * static_cast<double>(I));
  return x;
}

}  // namespace

TEST_CASE("block_sums: every index once, sums exact where they can be, and independent of the thread count") {
  // Two and a half blocks, so the last block is short.
  const index_t n = 5 * block_sums<2>::block_size / 2 + 3;
  const block_sums<2> sums(n);
  std::vector<int> visits(n, 0);
  std::vector<double> x(n);
  for (index_t I = 0; I < n; ++I) x[I] = std::sin(0.37 * static_cast<double>(I)) * std::exp(0.001 * static_cast<double>(I));
  const auto run = [&](int threads) {
    use_threads(threads);
    return sums([&](index_t I, block_sums<2>::sums& s) {
      ++visits[I];
      s[0] += static_cast<double>(I);  // integers: exact in any order
      s[1] += x[I];
    });
  };
  const auto one = run(1);
  const auto two = run(2);
  for (index_t I = 0; I < n; ++I) REQUIRE(visits[I] == 2);
  CHECK(one[0] == static_cast<double>(n) * static_cast<double>(n - 1) / 2.0);
  CHECK(one == two);
  double serial = 0.0;  // the same terms in one serial sum: equal to rounding only
  for (double v : x) serial += v;
  CHECK(one[1] == doctest::Approx(serial).epsilon(1e-12));
}

TEST_CASE("max_over and min_over: the extremes, whatever the thread count, and value runs once per index") {
  const index_t n = 10007;
  const std::vector<double> x = wiggles(n);
  std::vector<int> visits(n, 0);
  const auto run = [&](int threads) {
    use_threads(threads);
    const double hi = exec::max_over({0, n}, [&](index_t I) {
      ++visits[I];
      return x[I];
    });
    const double lo = exec::min_over({0, n}, [&](index_t I) { return x[I]; });
    return std::array{hi, lo};
  };
  const auto one = run(1);
  const auto two = run(2);
  for (index_t I = 0; I < n; ++I) REQUIRE(visits[I] == 2);
  CHECK(one == two);
  CHECK(one[0] == *std::ranges::max_element(x));
  CHECK(one[1] == *std::ranges::min_element(x));
  CHECK(exec::max_over({5, 5}, [&](index_t I) { return x[I]; }, 0.0) == 0.0);  // empty: the start value
}

TEST_CASE("parallel_for and parallel_for_each_row: every index once; a row's error leaves the loop") {
  use_threads(2);
  const index_t n = 3000;
  std::vector<int> visits(n, 0);
  exec::parallel_for(index_range{100, n}, [&](index_t I) { ++visits[I]; });
  for (index_t I = 0; I < n; ++I) REQUIRE(visits[I] == (I >= 100 ? 1 : 0));
  struct scratch {
    std::vector<index_t> rows;  // one per thread: no sharing
  };
  std::vector<int> rows(n, 0);
  exec::parallel_for_each_row<scratch>(n, 64, [&](index_t I, scratch& s) {
    s.rows.push_back(I);
    ++rows[I];
  });
  for (index_t I = 0; I < n; ++I) REQUIRE(rows[I] == 1);
  CHECK_THROWS_WITH_AS(exec::parallel_for_each_row<scratch>(n, 64,
                                                          [&](index_t I, scratch&) {
                                                            if (I == 1234) fail("row {} failed", I);
                                                          }),
                       "row 1234 failed", error);
  use_threads(1);
}

TEST_CASE("for_each_coloured: every item once, colour after colour, the serial colours in order") {
  use_threads(2);
  // Colours of 5, 1 and 7 items, the last visited on one thread.
  const std::vector<index_t> colour_start{0, 5, 6, 13};
  std::vector<index_t> order;
  std::vector<int> colour_of{0, 0, 0, 0, 0, 1, 2, 2, 2, 2, 2, 2, 2};
  exec::for_each_coloured(colour_start, 2, [&](index_t k) {
#pragma omp critical(test_coloured_order)
    order.push_back(k);
  });
  REQUIRE(order.size() == 13);
  for (std::size_t i = 1; i < order.size(); ++i) CHECK(colour_of[order[i - 1]] <= colour_of[order[i]]);
  CHECK(std::vector<index_t>(order.begin() + 6, order.end()) == std::vector<index_t>{6, 7, 8, 9, 10, 11, 12});
  std::vector<index_t> first(order.begin(), order.begin() + 5);
  std::ranges::sort(first);
  CHECK(first == std::vector<index_t>{0, 1, 2, 3, 4});
  use_threads(1);
}

TEST_CASE("ownership and exchange on one process") {
  const ownership own = ownership::single_process(10, 40);
  CHECK(own.particles.size() == 10);
  CHECK(own.ghost_particles.empty());
  CHECK(own.points.size() == 40);
  CHECK_NOTHROW(own.validate(10, 40));
  CHECK_THROWS_AS(own.validate(11, 40), error);  // a particle neither owned nor a ghost
  CHECK_THROWS_AS(own.validate(10, 41), error);
  std::vector<vec2> d(10, vec2(1.0, 2.0));
  exec::exchange(exchange_point::after_predictor, own, d);
  CHECK(d == std::vector<vec2>(10, vec2(1.0, 2.0)));  // nothing to exchange: unchanged
  // Ghosts need a backend that fills them; this build has none and says so.
  ownership split = own;
  split.particles.end = 8;
  split.ghost_particles = {8, 10};
  CHECK_NOTHROW(split.validate(10, 40));
  CHECK_THROWS_AS(exec::exchange(exchange_point::after_scatter, split, d), error);
}

}  // namespace test_unit_core_execution
