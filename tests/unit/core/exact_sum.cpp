// exact_sum (core/exact_sum.hpp) against exact arithmetic: sums whose rounding a plain double sum
// gets wrong (cancellation, terms below the larger ones' last bit, subnormals, the extremes of the
// exponent range), the same bits in every order and split, and the non-finite terms.

#include <doctest/doctest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <rkpm/core/exact_sum.hpp>

namespace test_unit_exact_sum {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using rkpm::exact_sum;

double sum_of(const std::vector<double>& terms) {
  exact_sum s;
  for (const double x : terms) s.add(x);
  return s.value();
}

TEST_CASE("exact_sum: cancellation and terms below the last bit come out exact") {
  CHECK(sum_of({1e100, 1.0, -1e100}) == 1.0);          // a double sum gives 0
  CHECK(sum_of({1.0, 1e-30, -1.0}) == 1e-30);
  CHECK(sum_of({0.1, 0.2, -0.3}) == std::ldexp(1.0, -55));  // a double sum gives 2^-54
  const double tiny = std::numeric_limits<double>::denorm_min(), huge = std::numeric_limits<double>::max();
  CHECK(sum_of({huge, tiny, -huge}) == tiny);
  CHECK(sum_of({huge, huge, -huge}) == huge);  // past the double range in between
  CHECK(sum_of({-3.5, -0.25}) == -3.75);
  CHECK(sum_of({}) == 0.0);
  // 2^53 + 1 + 1: a double sum rounds each +1 away; the exact sum is 2^53 + 2.
  CHECK(sum_of({9007199254740992.0, 1.0, 1.0}) == 9007199254740994.0);
}

TEST_CASE("exact_sum: a million random terms, in any order and any split, one set of bits") {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-60, 60);
  std::vector<double> terms(1 << 20);
  for (double& x : terms) x = std::ldexp(mantissa(random), exponent(random));
  const double forward = sum_of(terms);
  long double reference = 0.0L;  // a check of the magnitude, not of the bits
  for (const double x : terms) reference += x;
  CHECK(std::abs(forward - static_cast<double>(reference)) <= 1e-12 * std::abs(forward));

  std::vector<double> negated(terms.size());
  std::transform(terms.begin(), terms.end(), negated.begin(), [](double x) { return -x; });
  CHECK(sum_of(negated) == -forward);
  std::shuffle(terms.begin(), terms.end(), random);
  CHECK(std::bit_cast<std::uint64_t>(sum_of(terms)) == std::bit_cast<std::uint64_t>(forward));
  std::sort(terms.begin(), terms.end());
  CHECK(std::bit_cast<std::uint64_t>(sum_of(terms)) == std::bit_cast<std::uint64_t>(forward));
  // Three parts, added in two orders, as three processes' limbs would be.
  exact_sum a, b, c;
  for (std::size_t i = 0; i < terms.size(); ++i) (i % 3 == 0 ? a : i % 3 == 1 ? b : c).add(terms[i]);
  exact_sum abc = a, cba = c;
  abc += b;
  abc += c;
  cba += b;
  cba += a;
  CHECK(std::bit_cast<std::uint64_t>(abc.value()) == std::bit_cast<std::uint64_t>(forward));
  CHECK(std::bit_cast<std::uint64_t>(cba.value()) == std::bit_cast<std::uint64_t>(forward));
  // The limbs summed as MPI_SUM sums them, then normalized.
  a.normalize();
  b.normalize();
  exact_sum reduced;
  for (int k = 0; k < exact_sum::limb_count; ++k) reduced.limbs()[k] = a.limbs()[k] + b.limbs()[k];
  reduced += c;
  CHECK(std::bit_cast<std::uint64_t>(reduced.value()) == std::bit_cast<std::uint64_t>(forward));
}

TEST_CASE("exact_sum: the correctly rounded sum of terms a double sum loses") {
  // n copies of 2^-60 after 1: the exact sum is 1 + n 2^-60, which a double sum leaves at 1.
  exact_sum s;
  s.add(1.0);
  for (int i = 0; i < 1 << 12; ++i) s.add(std::ldexp(1.0, -60));
  CHECK(s.value() == 1.0 + std::ldexp(1.0, -48));
}

TEST_CASE("exact_sum: non-finite terms win") {
  const double inf = std::numeric_limits<double>::infinity();
  CHECK(sum_of({1.0, inf, 2.0}) == inf);
  CHECK(sum_of({1.0, -inf}) == -inf);
  CHECK(std::isnan(sum_of({inf, -inf})));
  CHECK(std::isnan(sum_of({1.0, std::numeric_limits<double>::quiet_NaN()})));
}

}  // namespace test_unit_exact_sum
