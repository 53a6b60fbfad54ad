// rkpm_bench_setup: the Taylor bar (Q2, cubic kernel, linear correction, the wall) set up in
// parts over the processes of mpiexec and stepped (tools/rkpm bench --setup; docs/performance.md
// "Set-up in parts"). Every rank builds the model's layout (particles, cells, points, bodies),
// partitions it by coordinate bisection and builds its own part (parallel/rank_setup.hpp): no
// rank holds a table of the whole model. With --whole, each rank builds the whole model and
// METIS partitions it instead (the set-up before), for comparison. Printed per rank: owned
// particles, ghosts, points, peak resident memory (getrusage: the set-up's peak or the steps',
// whichever is larger) and its bytes per local particle, set-up and step times.
//
//   mpiexec -np P rkpm_bench_setup [--resolution 32] [--steps 100] [--whole]

#include <chrono>
#include <cstdio>
#include <optional>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <mpi.h>
#include <sys/resource.h>

#include <rkpm/parallel/communicator.hpp>
#include <rkpm/parallel/coordinate_bisection.hpp>
#include <rkpm/parallel/distributed_solver.hpp>
#include <rkpm/parallel/partition.hpp>
#include <rkpm/parallel/rank_setup.hpp>

#include "taylor_bar_solver.hpp"

namespace {

using namespace rkpm;
using clock_type = std::chrono::steady_clock;
using method = bench::wall_method<quadrature::q2>;
using solver_type = solver_for<method>;

double peak_rss_bytes() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) * 1024.0;  // Linux: kilobytes
}

double seconds_since(clock_type::time_point t0) {
  return std::chrono::duration<double>(clock_type::now() - t0).count();
}

void run(parallel::communicator& comm, int resolution, int steps, bool whole) {
  const auto t0 = clock_type::now();
  auto p = bench::bar::build<bench::wall_contact>(bench::bar::parameters{}, resolution);
  const run_options options = bench::bench_options();
  particle_set<2> particles = std::move(p.particles);
  background_mesh mesh = std::move(p.mesh);
  p.particles = {};
  p.mesh = {};
  std::optional<parallel::distributed_solver<solver_type>> part;
  if (whole) {
    discrete_model m = build_discrete_model<kernel::cubic_spline, correction::linear, quadrature::q2,
                                            bench::bar::geometry_type>(std::move(particles), std::move(mesh),
                                                                       options.max_moment_condition);
    const parallel::particle_partition partition =
        parallel::partition_particles(m.at_points, m.particle_count(), comm.size());
    part.emplace(comm, std::move(m), std::move(p), options, partition);
  } else {
    parallel::model_layout layout =
        parallel::make_model_layout<kernel::cubic_spline, correction::linear, quadrature::q2,
                                    bench::bar::geometry_type>(std::move(particles), std::move(mesh),
                                                               options.max_moment_condition);
    const parallel::particle_partition partition =
        parallel::bisect_coordinates(layout.whole.particles.position, comm.size());
    part.emplace(comm, std::move(layout), std::move(p), options, partition);
  }
  MPI_Barrier(MPI_COMM_WORLD);
  const double setup_s = seconds_since(t0);
  const double setup_rss = peak_rss_bytes();
  const auto t1 = clock_type::now();
  for (int k = 0; k < steps; ++k) part->solver().step();
  MPI_Barrier(MPI_COMM_WORLD);
  const double step_s = steps > 0 ? seconds_since(t1) / steps : 0.0;
  const parallel::halo_plan& plan = part->plan();
  const double local = static_cast<double>(plan.local_particles());
  const std::vector<double> mine{static_cast<double>(plan.owned.size()), static_cast<double>(plan.ghosts.size()),
                                 static_cast<double>(plan.points.size()), setup_rss, peak_rss_bytes(), local};
  std::vector<double> all(mine.size() * static_cast<std::size_t>(comm.size()));
  MPI_Gather(mine.data(), static_cast<int>(mine.size()), MPI_DOUBLE, all.data(), static_cast<int>(mine.size()),
             MPI_DOUBLE, 0, MPI_COMM_WORLD);
  if (comm.rank() != 0) return;
  fmt::print("Taylor bar, resolution {}, {} process(es), set-up {}: {:.2f} s, a step {:.4f} s ({} steps)\n",
             resolution, comm.size(), whole ? "whole (METIS)" : "in parts (bisection)", setup_s, step_s, steps);
  fmt::print("{:>5} {:>10} {:>9} {:>10} {:>14} {:>14} {:>16}\n", "rank", "owned", "ghosts", "points",
             "peak set-up MB", "peak run MB", "B / local part.");
  for (int r = 0; r < comm.size(); ++r) {
    const double* v = all.data() + static_cast<std::size_t>(r) * mine.size();
    fmt::print("{:>5} {:>10.0f} {:>9.0f} {:>10.0f} {:>14.0f} {:>14.0f} {:>16.0f}\n", r, v[0], v[1], v[2],
               v[3] / 1e6, v[4] / 1e6, v[4] / v[5]);
  }
}

}  // namespace

int main(int argc, char** argv) {
  parallel::mpi_session session(argc, argv);
  parallel::communicator comm;
  int resolution = 32, steps = 100;
  bool whole = false;
  CLI::App app("rkpm_bench_setup: the Taylor bar set up in parts and stepped (tools/bench/setup.cpp)");
  app.add_option("--resolution", resolution, "Taylor bar resolution (32: about 10^6 particles)")
      ->check(CLI::Range(1, 200))
      ->capture_default_str();
  app.add_option("--steps", steps, "steps after the set-up")->check(CLI::Range(0, 1000000))->capture_default_str();
  app.add_flag("--whole", whole, "build the whole model on every rank and partition it with METIS (the old set-up)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return comm.rank() == 0 ? app.exit(e) : e.get_exit_code();
  }
  try {
    run(comm, resolution, steps, whole);
  } catch (const parallel::rank_failure& e) {
    if (comm.rank() == 0) std::fprintf(stderr, "rkpm_bench_setup: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rkpm_bench_setup (rank %d): %s\n", comm.rank(), e.what());
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  return 0;
}
