// Covering configurations (policies::covering_configs) rows 1, 6, 11, 12: each instantiates the
// whole solver and runs a small impact (see test::check_combination). The 16 rows are spread over
// combinations_part1..4 so that the costly instantiations build in parallel; the rows of one
// part use the four materials and the four contact policies.

#include <doctest/doctest.h>

#include "support/solver_fixtures.hpp"

namespace hana = boost::hana;

template <std::size_t Row>
using row_config = typename decltype(+rkpm::policies::covering_configs[hana::size_c<Row>])::type;

TEST_CASE("covering row 1") { rkpm::test::check_combination<row_config<1>>(); }
TEST_CASE("covering row 6") { rkpm::test::check_combination<row_config<6>>(); }
TEST_CASE("covering row 11") { rkpm::test::check_combination<row_config<11>>(); }
TEST_CASE("covering row 12") { rkpm::test::check_combination<row_config<12>>(); }
TEST_CASE("covering row 1, every rule beyond the paper") { rkpm::test::check_combination_with_every_rule<row_config<1>>(); }
TEST_CASE("covering row 6, every rule beyond the paper") { rkpm::test::check_combination_with_every_rule<row_config<6>>(); }
TEST_CASE("covering row 11, every rule beyond the paper") { rkpm::test::check_combination_with_every_rule<row_config<11>>(); }
TEST_CASE("covering row 12, every rule beyond the paper") { rkpm::test::check_combination_with_every_rule<row_config<12>>(); }
