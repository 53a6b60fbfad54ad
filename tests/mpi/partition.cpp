// The partition of the particles (parallel/partition.hpp) on the 12 x 8 grid of
// tests/mpi/grid_problem.hpp: the particle graph is the table's (symmetric, weights that count
// the table's entries); METIS gives every particle one part, the same parts every time, within
// a stated balance; a partition given by the caller is checked; impossible part counts are
// one-line errors with the fix. Runs on one process (no MPI call).

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

#include <rkpm/parallel/coordinate_bisection.hpp>
#include <rkpm/parallel/halo.hpp>
#include <rkpm/parallel/partition.hpp>

#include "mpi/grid_problem.hpp"
#include "support/error_message.hpp"

namespace test_mpi_partition {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;
using namespace rkpm::parallel;
using rkpm::test::contains;
using rkpm::test::error_message;

TEST_CASE("particle graph: symmetric, no self links, weights from the table's entries") {
  const test::grid_problem g;
  const particle_graph graph = make_particle_graph(g.table, g.size());
  REQUIRE(graph.vertices() == g.size());
  idx_t work = 0;
  for (const idx_t w : graph.vertex_weight) work += w;
  CHECK(work == g.table.entries());  // every (point, neighbour) entry counted once
  const auto weight = [&](index_t I, index_t J) -> idx_t {
    for (idx_t k = graph.xadj[I]; k < graph.xadj[I + 1]; ++k)
      if (graph.adjncy[k] == J) return graph.edge_weight[k];
    return 0;
  };
  index_t asymmetric = 0, self = 0, unsorted = 0;
  for (index_t I = 0; I < g.size(); ++I)
    for (idx_t k = graph.xadj[I]; k < graph.xadj[I + 1]; ++k) {
      const index_t J = graph.adjncy[k];
      self += J == I;
      asymmetric += weight(J, I) != graph.edge_weight[k];
      unsorted += k > graph.xadj[I] && graph.adjncy[k - 1] >= graph.adjncy[k];
    }
  CHECK(self == 0);
  CHECK(asymmetric == 0);
  CHECK(unsorted == 0);
  // Two particles are linked exactly when some point's support holds both, the weight counting those points.
  std::vector<idx_t> shared(g.size() * g.size(), 0);
  for (index_t q = 0; q < g.table.points(); ++q)
    for (index_t e = g.table.offset[q]; e < g.table.offset[q + 1]; ++e)
      for (index_t f = g.table.offset[q]; f < g.table.offset[q + 1]; ++f)
        if (e != f) ++shared[g.table.neighbor[e] * g.size() + g.table.neighbor[f]];
  index_t differ = 0;
  for (index_t I = 0; I < g.size(); ++I)
    for (index_t J = 0; J < g.size(); ++J) differ += I != J && shared[I * g.size() + J] != weight(I, J);
  CHECK(differ == 0);
}

TEST_CASE("METIS partition: every particle in one part, deterministic, balanced by work") {
  const test::grid_problem g;
  const particle_graph graph = make_particle_graph(g.table, g.size());
  const idx_t total = std::accumulate(graph.vertex_weight.begin(), graph.vertex_weight.end(), idx_t{0});
  const idx_t heaviest = *std::ranges::max_element(graph.vertex_weight);
  for (const index_t parts : {1, 2, 3, 4, 8}) {
    CAPTURE(parts);
    const particle_partition p = partition_particles(graph, parts);
    REQUIRE(p.parts == parts);
    REQUIRE(p.particles() == g.size());
    CHECK(std::ranges::all_of(p.part, [&](stored_index k) { return k >= 0 && k < parts; }));
    const std::vector<index_t> sizes = p.sizes();
    CHECK(std::accumulate(sizes.begin(), sizes.end(), index_t{0}) == g.size());
    CHECK(std::ranges::all_of(sizes, [](index_t n) { return n > 0; }));
    // The same graph and options: the same parts, bit for bit (each process may partition itself).
    CHECK(partition_particles(graph, parts).part == p.part);
    CHECK(partition_particles(g.table, g.size(), parts).part == p.part);
    // Balance: METIS's default tolerance (1.03 for k-way; recursive bisection is tighter) plus
    // one particle's work, the granularity of a graph of 96 vertices.
    std::vector<idx_t> work(parts, 0);
    for (index_t I = 0; I < g.size(); ++I) work[p.part[I]] += graph.vertex_weight[I];
    const double limit = 1.03 * static_cast<double>(total) / static_cast<double>(parts) + heaviest;
    CHECK(static_cast<double>(*std::ranges::max_element(work)) <= limit);
  }
  // On a larger grid the balance is METIS's own tolerance.
  const test::grid_problem large(41, 31);
  const particle_graph lg = make_particle_graph(large.table, large.size());
  const idx_t large_total = std::accumulate(lg.vertex_weight.begin(), lg.vertex_weight.end(), idx_t{0});
  for (const index_t parts : {2, 3, 5, 8, 16}) {
    CAPTURE(parts);
    const particle_partition p = partition_particles(lg, parts);
    std::vector<idx_t> work(parts, 0);
    for (index_t I = 0; I < large.size(); ++I) work[p.part[I]] += lg.vertex_weight[I];
    CHECK(static_cast<double>(*std::ranges::max_element(work)) <=
          1.03 * static_cast<double>(large_total) / static_cast<double>(parts));
  }
}

TEST_CASE("partition errors: impossible part counts and bad given parts, each a one-line error with the fix") {
  const test::grid_problem g;
  const particle_graph graph = make_particle_graph(g.table, g.size());
  CHECK(contains(error_message([&] { partition_particles(graph, 0); }), "at least one part"));
  CHECK(contains(error_message([&] { partition_particles(graph, -2); }), "at least one part"));
  CHECK(contains(error_message([&] { partition_particles(graph, 97); }), "run on at most 96 processes"));
  CHECK(!contains(error_message([&] { partition_particles(graph, 96); }), "run on at most"));
  CHECK(contains(error_message([&] { given_partition({0, 1, 2}, 4); }), "run on at most 3 processes"));
  CHECK(contains(error_message([&] { given_partition({0, 1, 3}, 3); }), "particle 2 is given part 3"));
  CHECK(contains(error_message([&] { given_partition({0, 0, 2}, 3); }), "part 1 of 3 owns no particle"));
  CHECK(contains(error_message([&] { given_partition({0, 0, 0}, 0); }), "at least one part"));
  // A graph from a table of other particles.
  CHECK(contains(error_message([&] { make_particle_graph(g.table, 10); }), "build the table and the graph from the same"));
  // The forced cuts of the other tests are valid partitions (given_partition would throw).
  for (const index_t parts : {1, 2, 3, 4}) CHECK(g.stripes(parts).parts == parts);
}

TEST_CASE("coordinate bisection: straight cuts, balanced by weight, deterministic, without the graph") {
  const test::grid_problem g(41, 31);
  const std::vector<vec2>& x = g.particles.position;
  for (const index_t parts : {1, 2, 3, 4, 5, 16}) {
    CAPTURE(parts);
    const particle_partition p = bisect_coordinates(x, parts);
    REQUIRE(p.parts == parts);
    REQUIRE(p.particles() == g.size());
    CHECK(bisect_coordinates(x, parts).part == p.part);
    // Unit weights: each cut puts the nearest whole particle to its share on each side, so a part
    // is within one particle per level of cuts of N / P.
    const double levels = std::ceil(std::log2(static_cast<double>(parts)));
    for (const index_t n : p.sizes())
      CHECK(std::abs(static_cast<double>(n) - static_cast<double>(g.size()) / static_cast<double>(parts)) <=
            levels + 1e-12);
  }
  // Two parts of the 5.5 x 3.5 box: one straight cut across x, its longer side.
  const particle_partition two = bisect_coordinates(x, 2);
  double left_max = -1.0, right_min = 1.0;
  for (index_t I = 0; I < g.size(); ++I) {
    if (two.part[I] == 0) left_max = std::max(left_max, x[I][0]);
    else right_min = std::min(right_min, x[I][0]);
  }
  CHECK(left_max <= right_min);
  // Four parts: the two halves are cut again across their longer side (y for 2.75 x 3.5).
  const particle_partition four = bisect_coordinates(x, 4);
  index_t moved = 0, crossing = 0;
  for (index_t I = 0; I < g.size(); ++I) {
    moved += (four.part[I] < 2) != (two.part[I] == 0);
    for (index_t J = 0; J < g.size(); ++J) crossing += four.part[I] == 0 && four.part[J] == 1 && x[I][1] > x[J][1];
  }
  CHECK(moved == 0);
  CHECK(crossing == 0);
  // Weights: the left fifth of the box three times as heavy; the two parts' weights differ by at
  // most the heaviest particle, so the cut moves left of the middle.
  std::vector<double> w(g.size());
  for (index_t I = 0; I < g.size(); ++I) w[I] = x[I][0] < 0.2 * g.width ? 3.0 : 1.0;
  const particle_partition weighted = bisect_coordinates(x, w, 2);
  double w0 = 0.0, w1 = 0.0;
  for (index_t I = 0; I < g.size(); ++I) (weighted.part[I] == 0 ? w0 : w1) += w[I];
  CHECK(std::abs(w0 - w1) <= 3.0);
  CHECK(weighted.sizes()[0] < two.sizes()[0]);
}

TEST_CASE("partition cost: links cut, points computed twice and ghosts, against the pairs and the halo plans") {
  const test::grid_problem g;
  for (const index_t parts : {1, 2, 3, 4}) {
    CAPTURE(parts);
    const particle_partition p = parts == 3 ? g.stripes(3) : bisect_coordinates(g.particles.position, parts);
    const partition_costs c = partition_cost(g.table, p);
    // Links: every pair of particles of different parts, once per point whose support holds both.
    std::int64_t cut = 0;
    for (index_t q = 0; q < g.table.points(); ++q)
      for (index_t e = g.table.offset[q]; e < g.table.offset[q + 1]; ++e)
        for (index_t f = e + 1; f < g.table.offset[q + 1]; ++f)
          cut += p.part[g.table.neighbor[e]] != p.part[g.table.neighbor[f]];
    CHECK(c.links_cut == cut);
    // The halo plans (parallel/halo.hpp): their points beyond the table's are the redundant ones,
    // their ghosts the ghosts.
    index_t planned_points = 0, most_ghosts = 0;
    for (int r = 0; r < parts; ++r) {
      const halo_plan h = make_halo_plan(p, g.table, r);
      planned_points += static_cast<index_t>(h.points.size());
      most_ghosts = std::max<index_t>(most_ghosts, static_cast<index_t>(h.ghosts.size()));
    }
    CHECK(c.shared_points == planned_points - g.table.points());
    CHECK(c.max_ghosts == most_ghosts);
    CHECK(c.imbalance >= 1.0);
    CHECK((parts == 1) == (c.links_cut == 0 && c.shared_points == 0));
  }
}

TEST_CASE("part loads: the table's entries at each part's particles, against a hand count") {
  // Three points over five particles: point 0 holds 0, 1, 2; point 1 holds 1, 2, 3; point 2 holds 3, 4.
  shape_table<2> t;
  t.offset = {0, 3, 6, 8};
  t.neighbor = {0, 1, 2, 1, 2, 3, 3, 4};
  // Part 0 owns 0, 1, 2 (entries 1 + 2 + 2), part 1 owns 3, 4 (2 + 1): loads 5 and 3, mean 4.
  const particle_partition p = given_partition({0, 0, 0, 1, 1}, 2);
  CHECK(part_loads(t, p) == std::vector<std::int64_t>{5, 3});
  CHECK(load_imbalance(t, p) == 1.25);
  // Part 1 takes particle 0 too: loads 4 and 4; one part: 1.
  CHECK(load_imbalance(t, given_partition({1, 0, 0, 1, 1}, 2)) == 1.0);
  CHECK(load_imbalance(t, given_partition({0, 0, 0, 0, 0}, 1)) == 1.0);
  // The partition's cost reports the same balance; a table naming a particle past the partition is refused.
  const test::grid_problem g;
  const particle_partition stripes = g.stripes(3);
  CHECK(partition_cost(g.table, stripes).imbalance == load_imbalance(g.table, stripes));
  CHECK(contains(error_message([&] { part_loads(t, given_partition({0, 1, 0, 1}, 2)); }),
                 "names particle 4 but the partition has 4 particles"));
}

TEST_CASE("coordinate bisection errors: one line with the fix") {
  const test::grid_problem g;
  const std::vector<vec2>& x = g.particles.position;
  CHECK(contains(error_message([&] { bisect_coordinates(x, 0); }), "at least one part"));
  CHECK(contains(error_message([&] { bisect_coordinates(x, 97); }), "run on at most 96 processes"));
  CHECK(contains(error_message([&] { bisect_coordinates(x, std::vector<double>(3, 1.0), 2); }),
                 "3 weights for 96 particles"));
  std::vector<vec2> bad = x;
  bad[7][1] = std::nan("");
  CHECK(contains(error_message([&] { bisect_coordinates(bad, 2); }), "particle 7"));
  std::vector<double> negative(x.size(), 1.0);
  negative[5] = -1.0;
  CHECK(contains(error_message([&] { bisect_coordinates(x, negative, 2); }), "non-negative weights"));
}

}  // namespace test_mpi_partition
