// Covering configurations (policies::covering_configs) rows 0, 5, 10, 15: each instantiates the
// whole solver and runs a small impact (see test::check_combination). The 16 rows are spread over
// combinations_part1..4 so that the costly instantiations build in parallel; the rows of one
// part use the four materials and the four contact policies.

#include <doctest/doctest.h>

#include "support/solver_fixtures.hpp"

namespace hana = boost::hana;

template <std::size_t Row>
using row_config = typename decltype(+rkpm::policies::covering_configs[hana::size_c<Row>])::type;

TEST_CASE("covering row 0") { rkpm::test::check_combination<row_config<0>>(); }
TEST_CASE("covering row 5") { rkpm::test::check_combination<row_config<5>>(); }
TEST_CASE("covering row 10") { rkpm::test::check_combination<row_config<10>>(); }
TEST_CASE("covering row 15") { rkpm::test::check_combination<row_config<15>>(); }
TEST_CASE("covering row 0, every rule beyond the paper") { rkpm::test::check_combination_with_every_rule<row_config<0>>(); }
TEST_CASE("covering row 5, every rule beyond the paper") { rkpm::test::check_combination_with_every_rule<row_config<5>>(); }
TEST_CASE("covering row 10, every rule beyond the paper") { rkpm::test::check_combination_with_every_rule<row_config<10>>(); }
TEST_CASE("covering row 15, every rule beyond the paper") { rkpm::test::check_combination_with_every_rule<row_config<15>>(); }
