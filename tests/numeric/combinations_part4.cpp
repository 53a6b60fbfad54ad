// Covering configurations (policies::covering_configs) rows 5, 8, 11: each instantiates the whole
// solver and runs a small impact (see test::check_combination). The 12 rows are spread over
// combinations_part1..4 so that the costly instantiations build in parallel; the rows of one
// part use three different contact policies.

#include <doctest/doctest.h>

#include "support/solver_fixtures.hpp"

namespace hana = boost::hana;

template <std::size_t Row>
using row_config = typename decltype(+rkpm::policies::covering_configs[hana::size_c<Row>])::type;

TEST_CASE("covering row 5") { rkpm::test::check_combination<row_config<5>>(); }
TEST_CASE("covering row 8") { rkpm::test::check_combination<row_config<8>>(); }
TEST_CASE("covering row 11") { rkpm::test::check_combination<row_config<11>>(); }
TEST_CASE("covering row 5, every rule beyond the paper") { rkpm::test::check_combination_with_every_rule<row_config<5>>(); }
TEST_CASE("covering row 8, every rule beyond the paper") { rkpm::test::check_combination_with_every_rule<row_config<8>>(); }
TEST_CASE("covering row 11, every rule beyond the paper") { rkpm::test::check_combination_with_every_rule<row_config<11>>(); }
