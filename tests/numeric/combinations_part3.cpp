// Covering configurations (policies::covering_configs) rows 2, 7, 8, 13: each instantiates the
// whole solver and runs a small impact (see test::check_combination). The 16 rows are spread over
// combinations_part1..4 so that the costly instantiations build in parallel; the rows of one
// part use the four materials and the four contact policies.

#include <doctest/doctest.h>

#include "support/solver_fixtures.hpp"

namespace hana = boost::hana;

template <std::size_t Row>
using row_config = typename decltype(+rkpm::policies::covering_configs[hana::size_c<Row>])::type;

TEST_CASE("covering row 2") { rkpm::test::check_combination<row_config<2>>(); }
TEST_CASE("covering row 7") { rkpm::test::check_combination<row_config<7>>(); }
TEST_CASE("covering row 8") { rkpm::test::check_combination<row_config<8>>(); }
TEST_CASE("covering row 13") { rkpm::test::check_combination<row_config<13>>(); }
TEST_CASE("covering row 2, every rule beyond the paper") { rkpm::test::check_combination_with_every_rule<row_config<2>>(); }
TEST_CASE("covering row 7, every rule beyond the paper") { rkpm::test::check_combination_with_every_rule<row_config<7>>(); }
TEST_CASE("covering row 8, every rule beyond the paper") { rkpm::test::check_combination_with_every_rule<row_config<8>>(); }
TEST_CASE("covering row 13, every rule beyond the paper") { rkpm::test::check_combination_with_every_rule<row_config<13>>(); }

TEST_CASE("kinematic contact: the energy balance error falls like dt^2") {
  // Row 2 (elastic, effective-mass contact): same simulated time at 0.7, 0.35 and 0.175 of the
  // stable step. Measured 10.8 %, 2.6 %, 0.65 %.
  double previous = 0.0;
  for (double f : {0.7, 0.35, 0.175}) {
    const auto e = rkpm::test::check_combination<row_config<2>>(static_cast<int>(std::lround(40 * 0.7 / f)), f);
    if (previous > 0.0) CHECK(previous / e.balance_error() > 3.0);
    previous = e.balance_error();
  }
  CHECK(previous < 1e-2);
}
