// rkpm_bench_partition: the two partitions of the particles compared on the Taylor bar (Q2,
// cubic kernel, linear correction) at several resolutions, for P parts (tools/rkpm bench
// --partition; docs/performance.md "Partitions"):
//   metis      METIS on the whole particle graph (parallel/partition.hpp), what a run uses today
//   bisection  recursive coordinate bisection of the reference positions, without the graph
//              (parallel/coordinate_bisection.hpp), weighted by each particle's table entries
// For each: the links cut (METIS's objective), the points computed by two parts or more, the
// most ghosts of a part, the largest part's work over the mean, and the time to partition (for
// METIS with the graph's construction, the part a set-up without the whole model cannot do).
// One process; no MPI call.
//
//   rkpm_bench_partition [--resolutions 1,4,16] [--parts 2,4,16]

#include <chrono>
#include <cstdio>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <rkpm/parallel/coordinate_bisection.hpp>
#include <rkpm/parallel/partition.hpp>

#include "taylor_bar_solver.hpp"

namespace {

using namespace rkpm;
using clock_type = std::chrono::steady_clock;

double seconds_since(clock_type::time_point t0) {
  return std::chrono::duration<double>(clock_type::now() - t0).count();
}

void print_row(const char* method, index_t parts, const parallel::partition_costs& c, double seconds) {
  fmt::print("{:>10} {:>6} {:>12} {:>12} {:>11} {:>10.3f} {:>10.3f}\n", method, parts, c.links_cut, c.shared_points,
             c.max_ghosts, c.imbalance, seconds);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> resolutions{1, 4, 16};
  std::vector<int> parts{2, 4, 16};
  CLI::App app("rkpm_bench_partition: METIS against coordinate bisection on the Taylor bar (tools/bench/partition.cpp)");
  app.add_option("--resolutions", resolutions, "Taylor bar resolutions")->delimiter(',')->check(CLI::Range(1, 32))->capture_default_str();
  app.add_option("--parts", parts, "part counts")->delimiter(',')->check(CLI::Range(1, 4096))->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    for (const int r : resolutions) {
      const auto problem = bench::bar::build<bench::wall_contact>(bench::bar::parameters{}, r);
      const discrete_model m = bench::bar_model<quadrature::q2>(problem);
      fmt::print("\nTaylor bar, resolution {}: {} particles, {} points, {} table entries\n", r, m.particle_count(),
                 m.point_count(), m.at_points.entries());
      fmt::print("{:>10} {:>6} {:>12} {:>12} {:>11} {:>10} {:>10}\n", "method", "parts", "links cut", "shared pts",
                 "max ghosts", "imbalance", "time (s)");
      // Each particle's work, as METIS weighs it: its entries in the table.
      std::vector<double> work(static_cast<std::size_t>(m.particle_count()), 0.0);
      for (const particle_index I : m.at_points.neighbor) work[static_cast<std::size_t>(I)] += 1.0;
      for (const int p : parts) {
        auto t0 = clock_type::now();
        const parallel::particle_partition metis = parallel::partition_particles(m.at_points, m.particle_count(), p);
        const double metis_s = seconds_since(t0);
        t0 = clock_type::now();
        const parallel::particle_partition rcb = parallel::bisect_coordinates(m.particles.position, work, p);
        const double rcb_s = seconds_since(t0);
        print_row("metis", p, parallel::partition_cost(m.at_points, metis), metis_s);
        print_row("bisection", p, parallel::partition_cost(m.at_points, rcb), rcb_s);
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rkpm_bench_partition: %s\n", e.what());
    return 1;
  }
  return 0;
}
