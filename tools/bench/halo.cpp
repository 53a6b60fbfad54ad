// rkpm_bench_halo: what the decomposition of the Taylor bar over P processes costs, measured on
// the real model (docs/method.md section 9.8; tools/rkpm bench --halo runs it on 1 to 4
// processes through mpiexec):
//   - METIS's partition of the bar's particle/point graph (Q2, cubic kernel, linear correction)
//     and each rank's halo plan: owned particles, ghosts, points computed (redundant ghost points
//     included), neighbouring ranks;
//   - the time of one forward exchange of d and v (two 2-vectors per ghost, what a step sends
//     twice), median over the repetitions of the slowest rank's time, after a barrier;
//   - the time of one MPI_Allreduce of a double (a step's stable-step minimum and energy sums);
//   - from them and a force-loop cost per point (--point-us, measured by tools/rkpm bench:
//     BM_step's s_per_particle_step over its points per particle), the modelled time per step on
//     P processes and its parallel efficiency.
// The exchanges are timed on this machine (shared memory, oversubscribed beyond its cores): the
// bandwidth and latency of a cluster are the model's assumptions, given as options and printed.
//
//   mpiexec -np P rkpm_bench_halo [--resolutions 8,32] [--repeat 200] [--point-us U]
//                                 [--latency-us A] [--bandwidth-GB-s B]
//                                 [--ghost-layers L] [--point-layers L]

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <mpi.h>

#include <rkpm/parallel/communicator.hpp>
#include <rkpm/parallel/halo.hpp>
#include <rkpm/parallel/mpi_exchange.hpp>
#include <rkpm/parallel/partition.hpp>

#include "taylor_bar_solver.hpp"

namespace {

using namespace rkpm;

struct options {
  std::vector<int> resolutions{8, 32};
  int repeat = 200;
  double point_us = 0.105;     // force loop per point and step, one core (0.21 us per particle-step, 2 points)
  double latency_us = 2.0;     // a cluster's message latency, assumed
  double bandwidth_GB_s = 10.0;  // and its bandwidth per link, assumed
  // Ghosts and extra (redundant) points of a rank per particle of its boundary: measured on 2
  // ranks, where METIS cuts the bar straight across its radius (printed below as "layers").
  double ghost_layers = 3.5, point_layers = 3.5;
};

// The command line (CLI11, as the runner's), the same on every rank. Returns the exit code after
// --help (0) or an error (CLI11 has printed either on rank 0), nothing to go on.
std::optional<int> parse(int argc, char** argv, options& o, int rank) {
  CLI::App app("rkpm_bench_halo: the Taylor bar decomposed over the processes of mpiexec (tools/bench/halo.cpp)");
  app.add_option("--resolutions", o.resolutions, "Taylor bar resolutions, e.g. 8,32")
      ->delimiter(',')
      ->check(CLI::Range(1, 32))
      ->capture_default_str();
  app.add_option("--repeat", o.repeat, "timed exchanges and reductions")->check(CLI::Range(1, 1000000))->capture_default_str();
  app.add_option("--point-us", o.point_us, "force loop per point and step on one core (us)")
      ->check(CLI::Range(1e-6, 1e6))
      ->capture_default_str();
  app.add_option("--latency-us", o.latency_us, "the model's message latency (us)")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  app.add_option("--bandwidth-GB-s", o.bandwidth_GB_s, "the model's bandwidth per link (GB/s)")
      ->check(CLI::Range(1e-6, 1e6))
      ->capture_default_str();
  app.add_option("--ghost-layers", o.ghost_layers, "the model's ghosts per boundary particle")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  app.add_option("--point-layers", o.point_layers, "the model's extra points per boundary particle")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  try {
    app.parse(argc, argv);
    return std::nullopt;
  } catch (const CLI::ParseError& e) {
    return rank == 0 ? app.exit(e) : e.get_exit_code();
  }
}

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

// Per repetition, the slowest rank's time (after a barrier, so every rank starts together); the
// median over the repetitions, on every rank.
template <class Work>
double slowest_median(MPI_Comm comm, int repeat, Work&& work) {
  std::vector<double> t(static_cast<std::size_t>(repeat)), slowest(t.size());
  for (int k = 0; k < 10; ++k) work();  // warm-up: buffers, connections
  for (int k = 0; k < repeat; ++k) {
    MPI_Barrier(comm);
    const double start = MPI_Wtime();
    work();
    t[static_cast<std::size_t>(k)] = MPI_Wtime() - start;
  }
  MPI_Allreduce(t.data(), slowest.data(), repeat, MPI_DOUBLE, MPI_MAX, comm);
  return median(slowest);
}

struct rank_figures {
  double owned, ghosts, points, neighbours, exchanged;  // exchanged: ghosts received plus particles sent
};

// The figures of one resolution on this communicator's P ranks, printed by rank 0.
void measure(parallel::communicator& comm, const options& o, int resolution) {
  using Q = quadrature::q2;
  const auto problem = bench::bar::build<bench::wall_contact>(bench::bar::parameters{}, resolution);
  const discrete_model m = bench::bar_model<Q>(problem);
  const index_t n = m.particle_count(), np = m.point_count();
  const int P = comm.size();
  const parallel::particle_partition part =
      parallel::partition_particles(parallel::make_particle_graph(m.at_points, n), P);
  const parallel::halo_plan plan = parallel::make_halo_plan(part, m.at_points, comm.rank());

  index_t sent = 0, received = 0;
  for (const auto& l : plan.sends) sent += static_cast<index_t>(l.particles.size());
  for (const auto& l : plan.receives) received += static_cast<index_t>(l.particles.size());
  const rank_figures mine{static_cast<double>(plan.owned.size()), static_cast<double>(plan.ghosts.size()),
                          static_cast<double>(plan.points.size()), static_cast<double>(plan.receives.size()),
                          static_cast<double>(sent + received)};
  std::vector<rank_figures> all(static_cast<std::size_t>(P));
  MPI_Gather(&mine, 5, MPI_DOUBLE, all.data(), 5, MPI_DOUBLE, 0, comm.get());

  parallel::halo_exchange exchange(comm, plan);
  std::vector<vec2> d(static_cast<std::size_t>(plan.local_particles()), vec2(1.0, 2.0));
  std::vector<vec2> v(d.size(), vec2(-3.0, 4.0));
  const double t_exchange = slowest_median(comm.get(), o.repeat, [&] { exchange.forward(d, v); });
  double x = 1.0, sum = 0.0;
  const double t_allreduce = slowest_median(comm.get(), o.repeat, [&] {
    MPI_Allreduce(&x, &sum, 1, MPI_DOUBLE, MPI_SUM, comm.get());
  });

  if (comm.rank() != 0) return;
  double max_points = 0.0, total_points = 0.0, max_ghosts = 0.0, total_ghosts = 0.0, max_neighbours = 0.0,
         max_exchanged = 0.0;
  for (const auto& r : all) {
    max_points = std::max(max_points, r.points);
    total_points += r.points;
    max_ghosts = std::max(max_ghosts, r.ghosts);
    total_ghosts += r.ghosts;
    max_neighbours = std::max(max_neighbours, r.neighbours);
    max_exchanged = std::max(max_exchanged, r.exchanged);
  }
  // Two exchanges of d and v per step (after the predictor, after the corrections) and about
  // three reductions (stable step, energy ledger, contact); the force loop on the busiest rank.
  const double force_s = max_points * o.point_us * 1e-6;
  const double step_s = force_s + 2.0 * t_exchange + 3.0 * t_allreduce;
  const double serial_s = static_cast<double>(np) * o.point_us * 1e-6;
  fmt::print("resolution {:>2}: {:>9} particles, {:>9} points, P = {}\n", resolution, n, np, P);
  fmt::print("  points computed over all ranks {:>9} (+{:.2f}% redundant), busiest rank {:>9}\n",
             static_cast<index_t>(total_points), 100.0 * (total_points / static_cast<double>(np) - 1.0),
             static_cast<index_t>(max_points));
  fmt::print("  ghosts {:>8} in all ({:.2f}% of the particles), at most {:>8} on a rank, {} neighbouring ranks at most\n",
             static_cast<index_t>(total_ghosts), 100.0 * total_ghosts / static_cast<double>(n),
             static_cast<index_t>(max_ghosts), static_cast<int>(max_neighbours));
  fmt::print("  forward(d, v): {:.1f} us (median of the slowest rank, {} repetitions; {} particles sent and received "
             "by the busiest rank, {:.0f} kB)\n",
             t_exchange * 1e6, o.repeat, static_cast<index_t>(max_exchanged), max_exchanged * 32.0 / 1e3);
  fmt::print("  MPI_Allreduce of a double: {:.1f} us\n", t_allreduce * 1e6);
  fmt::print("  model here: step {:.3f} ms = force loop {:.3f} ms + 2 exchanges + 3 reductions; one process {:.3f} ms; "
             "speed-up {:.2f}, efficiency {:.2f}\n",
             step_s * 1e3, force_s * 1e3, serial_s * 1e3, serial_s / step_s, serial_s / step_s / P);
  if (P == 2) {  // one cut, straight across the bar's radius: the particles of the impact face
    const auto across = std::count_if(m.particles.position.begin(), m.particles.position.end(),
                                      [](const vec2& X) { return X[1] <= 1e-12; });
    fmt::print("  per particle along the cut ({} across the radius): {:.2f} ghosts and {:.2f} extra points on a rank "
               "(the model's --ghost-layers and --point-layers)\n",
               across, max_ghosts / static_cast<double>(across),
               (max_points - static_cast<double>(np) / P) / static_cast<double>(across));
  }
}

// The model at P processes for N particles of the bar's kind (2 Q2 points per particle), parts
// square in the limit: a part of N/P particles has 4 sqrt(N/P) particles of boundary, each with
// --ghost-layers ghosts and --point-layers extra points (measured at P = 2); a forward exchange
// is one message to each of up to 6 neighbours (a 2D partition's parts meet about six others)
// at the assumed latency, and the ghosts' 32 bytes (d and v) at the assumed bandwidth; a
// reduction costs 2 log2(P) latencies (recursive doubling).
void model(const options& o) {
  fmt::print("\nmodel on a cluster (latency {} us, {} GB/s per link, force loop {} us per point and step, {} ghosts and "
             "{} extra points per boundary particle; 2 exchanges and 3 reductions per step):\n",
             o.latency_us, o.bandwidth_GB_s, o.point_us, o.ghost_layers, o.point_layers);
  fmt::print("| particles | P | particles per rank | ghosts per rank | force loop (ms) | exchanges and reductions (ms) "
             "| step (ms) | efficiency |\n|---|---|---|---|---|---|---|---|\n");
  for (const double N : {1e6, 1e7}) {
    for (const int P : {16, 64, 256}) {
      const double per_rank = N / P, boundary = 4.0 * std::sqrt(per_rank);
      const double ghosts = o.ghost_layers * boundary;
      const double points = 2.0 * per_rank + o.point_layers * boundary;
      const double force = points * o.point_us * 1e-3;  // ms
      const double one_exchange = std::min(6, P - 1) * o.latency_us * 1e-3 + ghosts * 32.0 / (o.bandwidth_GB_s * 1e6);
      const double reduction = 2.0 * std::log2(static_cast<double>(P)) * o.latency_us * 1e-3;
      const double communication = 2.0 * one_exchange + 3.0 * reduction;
      const double step = force + communication;
      const double serial = 2.0 * N * o.point_us * 1e-3;
      fmt::print("| {:.0e} | {} | {:.0f} | {:.0f} | {:.3f} | {:.4f} | {:.3f} | {:.2f} |\n", N, P, per_rank, ghosts,
                 force, communication, step, serial / step / P);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  rkpm::parallel::mpi_session session(argc, argv);
  rkpm::parallel::communicator comm;
  try {
    options o;
    if (const auto code = parse(argc, argv, o, comm.rank())) return *code;  // every rank parses the same line
    for (const int k : o.resolutions) measure(comm, o, k);
    if (comm.rank() == 0) model(o);
  } catch (const rkpm::parallel::rank_failure& e) {  // agreed by every rank: a clean stop
    if (comm.rank() == 0) std::fprintf(stderr, "rkpm_bench_halo: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rkpm_bench_halo (rank %d): %s\n", comm.rank(), e.what());
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  return 0;
}
