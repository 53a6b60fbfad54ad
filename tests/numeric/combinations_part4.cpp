// Covering configurations (policies::covering_configs) rows 3, 4, 9, 14: each instantiates the
// whole solver and runs a small impact (see test::check_combination). The 16 rows are spread over
// combinations_part1..4 so that the costly instantiations build in parallel; the rows of one
// part use the four materials and the four contact policies.

#include <doctest/doctest.h>

#include "support/solver_fixtures.hpp"

namespace hana = boost::hana;

template <std::size_t Row>
using row_config = typename decltype(+rkpm::policies::covering_configs[hana::size_c<Row>])::type;

TEST_CASE("covering row 3") { rkpm::test::check_combination<row_config<3>>(); }
TEST_CASE("covering row 4") { rkpm::test::check_combination<row_config<4>>(); }
TEST_CASE("covering row 9") { rkpm::test::check_combination<row_config<9>>(); }
TEST_CASE("covering row 14") { rkpm::test::check_combination<row_config<14>>(); }
TEST_CASE("covering row 3, every rule beyond the paper") { rkpm::test::check_combination_with_every_rule<row_config<3>>(); }
TEST_CASE("covering row 4, every rule beyond the paper") { rkpm::test::check_combination_with_every_rule<row_config<4>>(); }
TEST_CASE("covering row 9, every rule beyond the paper") { rkpm::test::check_combination_with_every_rule<row_config<9>>(); }
TEST_CASE("covering row 14, every rule beyond the paper") { rkpm::test::check_combination_with_every_rule<row_config<14>>(); }
