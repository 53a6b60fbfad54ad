// The partition of the particles (parallel/partition.hpp) on the 12 x 8 grid of
// tests/mpi/grid_problem.hpp: the particle graph is the table's (symmetric, weights that count
// the table's entries); METIS gives every particle one part, the same parts every time, within
// a stated balance; a partition given by the caller is checked; impossible part counts are
// one-line errors with the fix. Runs on one process (no MPI call).

#include <doctest/doctest.h>

#include <algorithm>
#include <numeric>
#include <vector>

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

}  // namespace test_mpi_partition
