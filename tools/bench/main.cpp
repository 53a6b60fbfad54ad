// rkpm_bench: timings of the explicit solver (tools/rkpm bench [Google Benchmark options]).
// The step benchmarks are in steps.cpp; this file holds the set-up costs and main().
//   BM_model_build<Q>      build_discrete_model: quadrature points, neighbor search, RK shape
//                          tables at points and particles, transpose, lumped volumes
//   BM_solver_build<Q>     make_solver: the above plus the solver constructor (masses, contact set-up,
//                          first internal force, stable step by 100 power iterations)
// Set-up is serial except the OpenMP loops of the first force and the power iteration; it is
// timed with 1 thread so that it is comparable run to run.
// The machine may be shared: compare numbers from the same run, and use repetitions
// (--benchmark_repetitions=3 --benchmark_report_aggregates_only=true).

#include <benchmark/benchmark.h>
#include <omp.h>

#include "taylor_bar_solver.hpp"

namespace rkpm::bench {
namespace {

template <class Q>
void BM_model_build(benchmark::State& state) {
  omp_set_num_threads(1);
  const auto p = bar::build<wall_contact>(bar::parameters{}, 1);
  index_t points = 0;
  for (auto _ : state) {
    auto m = bar_model<Q>(p);
    points = m.point_count();
    benchmark::DoNotOptimize(m.lumped_volume.data());
  }
  state.counters["particles"] = static_cast<double>(p.particles.size());
  state.counters["points"] = static_cast<double>(points);
}

template <class Q>
void BM_solver_build(benchmark::State& state) {
  omp_set_num_threads(1);
  for (auto _ : state) {
    auto s = make_wall_solver<Q>(1);
    benchmark::DoNotOptimize(s.time_step());
  }
}

}  // namespace

BENCHMARK(BM_model_build<quadrature::q2>)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_model_build<quadrature::q4>)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_model_build<quadrature::q9>)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_solver_build<quadrature::q2>)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_solver_build<quadrature::q4>)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_solver_build<quadrature::q9>)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace rkpm::bench

BENCHMARK_MAIN();
