// rkpm_bench_halo: what the decomposition of the Taylor bar over P processes costs, measured on
// the real model (docs/method.md section 9.8; tools/rkpm bench --halo runs it on 1 to 4
// processes through mpiexec):
//   - METIS's partition of the bar's particle/point graph (Q2, cubic kernel, linear correction)
//     and each rank's halo plan: owned particles, ghosts, points computed (redundant ghost points
//     included), neighbouring ranks;
//   - the time of one forward exchange of d and v (two 2-vectors per ghost, what a step sends
//     twice), median over the repetitions of the slowest rank's time, after a barrier;
//   - the time of one MPI_Allreduce of a double (a step's stable-step minimum and energy sums);
//   - the force loop measured (parallel/local_model.hpp): the bar squashed into yield a little
//     more at every evaluation (so that every one is plastic), evaluated by one process on 1 and
//     on 2 threads (rank 0 alone, the other ranks asleep), then by the P processes on one thread
//     each (each rank's local model: forward of the ghosts' coefficients, internal_force, the
//     plastic work's fixed-order sum and the support stretch's minimum), the slowest rank's
//     time; the medians, alternated round by round, and their ratios;
//   - the whole step measured (parallel/distributed_solver.hpp): the Taylor bar from impact,
//     stepped in rounds by one process on 1 and on 2 threads (rank 0 alone, one solver) and by
//     the P processes on one thread each (each rank's part of the model: the force loop, the
//     contact and constraints on the shared region, the exchanges and the fixed-order sums), the
//     slowest rank's time per step; the medians of the rounds' ratios;
//   - from them and a force-loop cost per point (--point-us, measured by tools/rkpm bench:
//     BM_step's s_per_particle_step over its points per particle), the modelled time per step on
//     P processes and its parallel efficiency, for 10^7 and 10^8 particles on 16 to 1024
//     processes, with the replicated region (every rank's serial part) and the memory per rank.
// The exchanges are timed on this machine (shared memory, oversubscribed beyond its cores): the
// bandwidth and latency of a cluster are the model's assumptions, given as options and printed.
//
//   mpiexec -np P rkpm_bench_halo [--resolutions 8,32] [--repeat 200] [--rounds 5] [--point-us U]
//                                 [--latency-us A] [--bandwidth-GB-s B]
//                                 [--ghost-layers L] [--point-layers L] [--shared-us U]

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <mpi.h>

#include <omp.h>
#include <sched.h>
#include <unistd.h>

#include <rkpm/parallel/communicator.hpp>
#include <rkpm/parallel/distributed_solver.hpp>
#include <rkpm/parallel/global_blocks.hpp>
#include <rkpm/parallel/halo.hpp>
#include <rkpm/parallel/local_model.hpp>
#include <rkpm/parallel/mpi_block_sums.hpp>
#include <rkpm/parallel/mpi_exchange.hpp>
#include <rkpm/parallel/partition.hpp>
#include <rkpm/solver/body_materials.hpp>
#include <rkpm/solver/point_materials.hpp>

#include "taylor_bar_solver.hpp"

namespace {

using namespace rkpm;

struct options {
  std::vector<int> resolutions{8, 32};
  int repeat = 200;
  int rounds = 9;  // force-loop rounds: one process on 1 and 2 threads, then P processes, alternated
  int steps = 20;  // whole-step rounds: steps per round and way (0: the whole step is not timed)
  double point_us = 0.105;     // force loop per point and step, one core (0.21 us per particle-step, 2 points)
  double latency_us = 2.0;     // a cluster's message latency, assumed
  double bandwidth_GB_s = 10.0;  // and its bandwidth per link, assumed
  // Ghosts and extra (redundant) points of a rank per particle of its boundary: measured on 2
  // ranks, where METIS cuts the bar straight across its radius (printed below as "layers").
  double ghost_layers = 3.5, point_layers = 3.5;
  // The replicated region (parallel/distributed_solver.hpp: the constrained and slave particles
  // and their rows' columns, which every rank corrects alike): its particles per square root of
  // the bar's particles (a band along the surface and the axis; measured by the whole-step
  // rounds, printed as "shared"), each costing --shared-us a step on every rank (measured by perf
  // on one process, the bar at resolution 8: the tool contact's slaves and the axis projection
  // take 0.6% of a step, about 0.05 us for each of its 2,183 shared particles).
  double shared_per_root = 0.0, shared_us = 0.05;
  double measured_shared_per_root = 0.0;  // the last resolution's (not an option)
  // Memory per rank: --bytes-per-particle per owned, ghost or shared particle, plus a fixed part
  // (docs/performance.md, "Set-up in parts": 1.6 to 1.7 KB per local particle, about 30 MB); while
  // it sets up, the layout of the whole model besides (about 100 bytes per particle of the whole).
  double bytes_per_particle = 1650.0, fixed_MB = 30.0, layout_bytes_per_particle = 100.0;
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
  app.add_option("--rounds", o.rounds, "rounds of force-loop timings (one process, then P processes)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  app.add_option("--steps", o.steps, "whole steps per round and way (0: do not time the whole step)")
      ->check(CLI::Range(0, 100000))
      ->capture_default_str();
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
  app.add_option("--shared-per-root", o.shared_per_root,
                 "the model's replicated particles per square root of the particles (0: the measured)")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  app.add_option("--shared-us", o.shared_us, "the model's cost of a replicated particle per step on every rank (us)")
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

// A barrier where the waiting ranks sleep instead of polling (MPI_Barrier spins), so that rank 0
// alone can time one process's force loop on both cores.
void quiet_barrier(MPI_Comm comm) {
  MPI_Request request;
  MPI_Ibarrier(comm, &request);
  for (int done = 0;;) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return;
    usleep(500);
  }
}

// The coefficients of the bar squashed by 1.5 % times `amplitude` (a barrelling field, not a
// polynomial: the whole bar yields).
vec2 squashed(const vec2& X, double radius, double height, double amplitude) {
  const double z = X[1] / height, r = X[0] / radius;
  return X + amplitude * 0.015 * vec2(0.5 * X[0] * (1.0 + 0.6 * std::sin(3.0 * z)) * (1.0 + 0.2 * r * r),
                                       -X[1] * (1.0 + 0.3 * std::cos(2.0 * z + r)));
}

// Pins this process to the `rank`-th CPU it may run on, while it lives, when there are as many
// CPUs as ranks (each rank a core of its own, as on a cluster; mpiexec's own binding is turned
// off by tools/rkpm so that rank 0 can time one process on two threads); restores the mask after.
class pinned_to_core {
 public:
  pinned_to_core(int rank, int ranks) {
    sched_getaffinity(0, sizeof(cpu_set_t), &original_);
    std::vector<int> cpus;
    for (int c = 0; c < CPU_SETSIZE; ++c)
      if (CPU_ISSET(c, &original_)) cpus.push_back(c);
    if (static_cast<int>(cpus.size()) < ranks) return;  // oversubscribed: leave it to the scheduler
    cpu_set_t one;
    CPU_ZERO(&one);
    CPU_SET(cpus[static_cast<std::size_t>(rank)], &one);
    pinned_ = sched_setaffinity(0, sizeof(cpu_set_t), &one) == 0;
  }
  ~pinned_to_core() {
    if (pinned_) sched_setaffinity(0, sizeof(cpu_set_t), &original_);
  }
  pinned_to_core(const pinned_to_core&) = delete;
  pinned_to_core& operator=(const pinned_to_core&) = delete;

 private:
  cpu_set_t original_;
  bool pinned_ = false;
};

struct round_times {
  double one_thread, two_threads, ranks;  // s per evaluation or step, medians over the rounds
  // The ratios of each round's timings (one process on 1 thread, on 2, over P processes), their
  // medians: a burst of load on a noisy host moves these far less than the times.
  double ranks_over_one, ranks_over_two;
  index_t shared = 0;  // the whole step's: the particles every rank holds and corrects alike
};

// The force loop of the bar on one process (1 and 2 threads, rank 0) and on the P processes.
// Each evaluation squashes a little further than the last, from fresh states for each of the
// three, so all three do the same work.
template <class Problem>
round_times time_force_loop(parallel::communicator& comm, const options& o, const Problem& problem,
                                 const discrete_model& m, const parallel::particle_partition& part,
                                 const parallel::halo_plan& plan) {
  using G = geometry::axisymmetric;
  using M = std::decay_t<decltype(problem.material)>;
  const bench::bar::parameters b{};
  const int evaluations = std::max(3, o.repeat / 20);
  const auto amplitude = [](int k) { return 1.0 + 0.002 * k; };
  // Evaluation k's coefficients at the first `owned` particles of `model` (the whole model's or
  // a rank's, which holds its particles' positions); the ghosts' come by the exchange.
  const auto field = [&](const discrete_model& model, index_t owned, int k) {
    std::vector<vec2> x(model.particle_count(), vec2::Zero());
    for (index_t i = 0; i < owned; ++i) x[i] = squashed(model.particles.position[i], b.radius_m, b.height_m, amplitude(k));
    return x;
  };
  const auto step = [](int k) { return step_context{k + 1, 1e-8 * (k + 1), 1e-8}; };
  std::vector<double> one, two, many;
  const discrete_model local = parallel::local_force_model(m, plan);
  const parallel::particle_partition point_owner = parallel::point_owners(part, m.at_points);
  const std::vector<stored_index> owned_points = parallel::owned_point_positions(plan, point_owner);
  parallel::global_block_sums<1> plastic_sum(
      comm, parallel::make_global_block_plan(point_owner, comm.rank(), traversal_tile_points), traversal_tile_points);
  parallel::halo_exchange exchange(comm, plan);
  for (int round = 0; round < o.rounds; ++round) {
    if (comm.rank() == 0)
      for (const int threads : {1, 2}) {
        omp_set_num_threads(threads);
        const materials_by_body<M> material(m, problem.material, {});
        point_materials<G, M> points(m, material);
        std::vector<vec2> f(m.particle_count());
        double total = 0.0;
        for (int k = 0; k < evaluations; ++k) {
          const std::vector<vec2> x = field(m, m.particle_count(), k);
          const double start = MPI_Wtime();
          points.internal_force(m, material, x, f, step(k));
          total += MPI_Wtime() - start;
        }
        (threads == 1 ? one : two).push_back(total / evaluations);
      }
    omp_set_num_threads(1);
    quiet_barrier(comm.get());
    const pinned_to_core pin(comm.rank(), comm.size());
    const materials_by_body<M> material(local, problem.material, {});
    point_materials<G, M> points(local, material);
    std::vector<vec2> f(local.particle_count());
    double total = 0.0;
    for (int k = 0; k < evaluations; ++k) {
      std::vector<vec2> x = field(local, static_cast<index_t>(plan.owned.size()), k);
      MPI_Barrier(comm.get());
      const double start = MPI_Wtime();
      exchange.forward(x);
      points.internal_force(local, material, x, f, step(k));
      const double plastic = plastic_sum([&](index_t i, parallel::global_block_sums<1>::sums& t) {
        const stored_index j = owned_points[i];
        t[0] += points.states()[j].plastic_work * local.points.weight[j];
      })[0];
      const double narrowest = comm.min(points.min_stretch());
      double t = MPI_Wtime() - start;
      MPI_Allreduce(MPI_IN_PLACE, &t, 1, MPI_DOUBLE, MPI_MAX, comm.get());
      total += t;
      if (!(plastic > 0.0 && narrowest > 0.0)) fail("force loop bench: the bar did not yield ({} J)", plastic);
    }
    many.push_back(total / evaluations);
  }
  if (comm.rank() != 0) return {};
  std::vector<double> over_one, over_two;
  for (std::size_t r = 0; r < many.size(); ++r) {
    over_one.push_back(one[r] / many[r]);
    over_two.push_back(two[r] / many[r]);
  }
  return {median(one), median(two), median(many), median(over_one), median(over_two)};
}

// The whole step of the Taylor bar: one solver on rank 0 stepped `steps` steps on 1 thread, then
// `steps` on 2 threads (the other ranks asleep), then the P ranks' solver 2 x `steps` steps (so
// that both stay on the same trajectory, a round apart at most); per round the time per step of
// each, the P processes' the slowest rank's. The solvers start from the same state: the bar at
// the wall, t = 0.
template <class Problem>
round_times time_whole_step(parallel::communicator& comm, const options& o, const Problem& problem,
                                 const discrete_model& m, const parallel::particle_partition& part) {
  using solver_type = solver_for<bench::wall_method<quadrature::q2>>;
  std::optional<solver_type> one;
  if (comm.rank() == 0) one.emplace(discrete_model(m), Problem(problem), bench::bench_options());
  parallel::distributed_solver<solver_type> many(comm, discrete_model(m), Problem(problem), bench::bench_options(), part);
  std::vector<double> t1, t2, tp;
  for (int round = 0; round < o.rounds; ++round) {
    if (comm.rank() == 0)
      for (const int threads : {1, 2}) {
        omp_set_num_threads(threads);
        const double start = MPI_Wtime();
        for (int k = 0; k < o.steps; ++k) one->step();
        (threads == 1 ? t1 : t2).push_back((MPI_Wtime() - start) / o.steps);
      }
    omp_set_num_threads(1);
    quiet_barrier(comm.get());
    const pinned_to_core pin(comm.rank(), comm.size());
    MPI_Barrier(comm.get());
    const double start = MPI_Wtime();
    for (int k = 0; k < 2 * o.steps; ++k) many.solver().step();
    double t = (MPI_Wtime() - start) / (2 * o.steps);
    MPI_Allreduce(MPI_IN_PLACE, &t, 1, MPI_DOUBLE, MPI_MAX, comm.get());
    tp.push_back(t);
  }
  if (comm.rank() != 0) return {};
  const index_t shared = many.shared_count();
  if (one->steps() != many.solver().steps() || one->time() != many.solver().time())
    fail("whole-step bench: one process reached t = {} s at step {}, {} processes t = {} s at step {}: not the same "
         "run",
         one->time(), one->steps(), comm.size(), many.solver().time(), many.solver().steps());
  std::vector<double> over_one, over_two;
  for (std::size_t r = 0; r < tp.size(); ++r) {
    over_one.push_back(t1[r] / tp[r]);
    over_two.push_back(t2[r] / tp[r]);
  }
  return {median(t1), median(t2), median(tp), median(over_one), median(over_two), shared};
}

struct rank_figures {
  double owned, ghosts, points, neighbours, exchanged;  // exchanged: ghosts received plus particles sent
};

// The figures of one resolution on this communicator's P ranks, printed by rank 0.
void measure(parallel::communicator& comm, options& o, int resolution) {
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

  const round_times loop = time_force_loop(comm, o, problem, m, part, plan);
  const std::optional<round_times> whole =
      o.steps > 0 ? std::optional(time_whole_step(comm, o, problem, m, part)) : std::nullopt;

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
  fmt::print("  force loop measured, per evaluation (medians of {} rounds): one process 1 thread {:.3f} ms, 2 threads "
             "{:.3f} ms; {} processes x 1 thread {:.3f} ms (slowest rank, with the forward exchange and both "
             "reductions); speed-up of the {} processes, the median of the rounds' ratios: {:.2f} x one thread, "
             "{:.2f} x two threads\n",
             o.rounds, loop.one_thread * 1e3, loop.two_threads * 1e3, P, loop.ranks * 1e3, P, loop.ranks_over_one,
             loop.ranks_over_two);
  if (whole) {
    o.measured_shared_per_root = static_cast<double>(whole->shared) / std::sqrt(static_cast<double>(n));
    fmt::print("  shared (replicated on every rank): {} particles, {:.2f} per square root of the particles\n",
               whole->shared, o.measured_shared_per_root);
  }
  if (whole)
    fmt::print("  whole step measured, per step (medians of {} rounds of {} steps): one process 1 thread {:.3f} ms, 2 "
               "threads {:.3f} ms; {} processes x 1 thread {:.3f} ms (slowest rank); speed-up of the {} processes, the "
               "median of the rounds' ratios: {:.2f} x one thread, {:.2f} x two threads\n",
               o.rounds, o.steps, whole->one_thread * 1e3, whole->two_threads * 1e3, P, whole->ranks * 1e3, P,
               whole->ranks_over_one, whole->ranks_over_two);
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
// reduction costs 2 log2(P) latencies (recursive doubling). The replicated region grows as
// sqrt(N) and costs every rank the same: it is the model's serial part. Memory per rank: its
// owned, ghost and shared particles at --bytes-per-particle, plus the fixed part; at the set-up
// also the whole model's layout, which every rank reads (parallel/rank_setup.hpp).
void model(const options& o) {
  const double shared_per_root = o.shared_per_root > 0.0 ? o.shared_per_root : o.measured_shared_per_root;
  fmt::print("\nmodel on a cluster (latency {} us, {} GB/s per link, force loop {} us per point and step, {} ghosts and "
             "{} extra points per boundary particle, {:.2f} shared particles per square root of the particles at {} us "
             "each; 2 exchanges and 3 reductions per step; {} bytes per local particle and {} MB a rank):\n",
             o.latency_us, o.bandwidth_GB_s, o.point_us, o.ghost_layers, o.point_layers, shared_per_root,
             o.shared_us, o.bytes_per_particle, o.fixed_MB);
  fmt::print("| particles | P | particles per rank | ghosts per rank | shared | force loop (ms) | replicated (ms) "
             "| exchanges and reductions (ms) | step (ms) | efficiency | memory per rank (MB) | set-up peak (MB) |\n"
             "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const double N : {1e7, 1e8}) {
    const double shared = shared_per_root * std::sqrt(N);
    for (const int P : {16, 64, 256, 1024}) {
      const double per_rank = N / P, boundary = 4.0 * std::sqrt(per_rank);
      const double ghosts = o.ghost_layers * boundary;
      const double points = 2.0 * per_rank + o.point_layers * boundary;
      const double force = points * o.point_us * 1e-3;  // ms
      const double replicated = shared * o.shared_us * 1e-3;
      const double one_exchange = std::min(6, P - 1) * o.latency_us * 1e-3 + ghosts * 32.0 / (o.bandwidth_GB_s * 1e6);
      const double reduction = 2.0 * std::log2(static_cast<double>(P)) * o.latency_us * 1e-3;
      const double communication = 2.0 * one_exchange + 3.0 * reduction;
      const double step = force + replicated + communication;
      const double serial = 2.0 * N * o.point_us * 1e-3 + replicated;
      const double memory = (per_rank + ghosts + shared) * o.bytes_per_particle / 1e6 + o.fixed_MB;
      const double setup = memory + N * o.layout_bytes_per_particle / 1e6;
      fmt::print("| {:.0e} | {} | {:.0f} | {:.0f} | {:.0f} | {:.3f} | {:.3f} | {:.4f} | {:.3f} | {:.2f} | {:.0f} | {:.0f} |\n",
                 N, P, per_rank, ghosts, shared, force, replicated, communication, step, serial / step / P, memory,
                 setup);
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
