// Benchmarks of one explicit step on the Taylor bar (tools/bench/taylor_bar_solver.hpp):
//   BM_step<Q>/threads            per quadrature rule, 1 and 2 OpenMP threads, resolution 1
//   BM_step_resolution/r          q2, resolution 1, 2, 3 (21x51, 41x101, 61x151 particles)
//   BM_step_rolling<Q>/threads    the contact-free twin at the same moment of the impact
//   BM_contact_enforce<Q>/threads contact().enforce alone, on copies of the predicted state
//   BM_step_material/m            q2, one thread: m = 0 J2 with linear hardening (the case's),
//                                 m = 1 Johnson-Cook with the same curve at the reference rate
//                                 and copper's rate and heating terms, m = 2 Zerilli-Armstrong fcc
//                                 with the case's yield stress as C0 and copper's other constants
//   BM_material_ratio/m           J2 and law m (1 Johnson-Cook, 2 Zerilli-Armstrong) stepped in
//                                 turn: over_j2, the median of the ratios of steps taken side by
//                                 side (the number to quote)
// Every benchmark builds a fresh solver and advances it by warm_up_steps() before timing, and
// runs a fixed number of iterations, so each repetition times the same window of the impact.
// Wall-clock time (the work is spread over OpenMP threads).

#include <algorithm>
#include <chrono>
#include <vector>

#include <benchmark/benchmark.h>
#include <omp.h>

#include "taylor_bar_solver.hpp"

namespace rkpm::bench {
namespace {

template <class Solver>
void set_counters(benchmark::State& state, const Solver& s) {
  const auto n = static_cast<double>(s.model().particle_count());
  state.counters["particles"] = n;
  state.counters["points"] = static_cast<double>(s.model().point_count());
  // seconds per particle per step
  state.counters["s_per_particle_step"] =
      benchmark::Counter(n, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["active_contacts"] = static_cast<double>(s.last_contact().active);
}

template <class Solver>
void warm_up(Solver& s, int resolution) {
  for (int k = 0; k < warm_up_steps(resolution); ++k) s.step();
}

template <class Q>
void BM_step(benchmark::State& state) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  auto s = make_wall_solver<Q>(1);
  warm_up(s, 1);
  for (auto _ : state) s.step();
  set_counters(state, s);
  state.SetLabel(std::string(Q::name));
}

void BM_step_resolution(benchmark::State& state) {
  omp_set_num_threads(1);
  const int resolution = static_cast<int>(state.range(0));
  auto s = make_wall_solver<quadrature::q2>(resolution);
  warm_up(s, resolution);
  for (auto _ : state) s.step();
  set_counters(state, s);
}

template <class Q>
void BM_step_rolling(benchmark::State& state) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  auto s = make_rolling_solver<Q>(1);
  warm_up(s, 1);
  for (auto _ : state) s.step();
  set_counters(state, s);
  state.SetLabel(std::string(Q::name) + " no contact, u_z = 0 on the face");
}

// One step with each material, on the same bar at the same moment of the impact (each twice,
// alternating, so that a burst of the host's load shows as two disagreeing runs).
void BM_step_material(benchmark::State& state) {
  omp_set_num_threads(1);
  if (state.range(0) == 0) {
    auto s = make_wall_solver<quadrature::q2>(1);
    warm_up(s, 1);
    for (auto _ : state) s.step();
    set_counters(state, s);
    state.SetLabel("j2+linear");
  } else if (state.range(0) == 1) {
    auto s = make_johnson_cook_solver<quadrature::q2>(1);
    warm_up(s, 1);
    for (auto _ : state) s.step();
    set_counters(state, s);
    state.SetLabel("johnson_cook");
  } else {
    auto s = make_zerilli_armstrong_solver<quadrature::q2>(1);
    warm_up(s, 1);
    for (auto _ : state) s.step();
    set_counters(state, s);
    state.SetLabel("zerilli_armstrong");
  }
}

// J2 and another law stepped in turn, each step timed apart (manual time: the other law's step),
// so that every J2 step has a step of the other law at the same moment of the impact and of the
// host's load beside it: the counter over_j2 is the median over the pairs of their ratio, which
// a burst of load on a noisy host moves far less than two separate timings.
// make() builds the other law's solver in place (a solver is not moved: its parts refer to each
// other).
template <class Make>
void material_ratio(benchmark::State& state, Make make, const char* label) {
  omp_set_num_threads(1);
  auto j2 = make_wall_solver<quadrature::q2>(1);
  auto law = make();
  warm_up(j2, 1);
  warm_up(law, 1);
  std::vector<double> ratios;
  const auto timed = [](auto& s) {
    const auto start = std::chrono::steady_clock::now();
    s.step();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  for (auto _ : state) {
    const double t_j2 = timed(j2);
    const double t_law = timed(law);
    ratios.push_back(t_law / t_j2);
    state.SetIterationTime(t_law);
  }
  std::nth_element(ratios.begin(), ratios.begin() + ratios.size() / 2, ratios.end());
  state.counters["over_j2"] = ratios[ratios.size() / 2];
  set_counters(state, law);
  state.SetLabel(label);
}

void BM_material_ratio(benchmark::State& state) {
  if (state.range(0) == 1)
    material_ratio(state, [] { return make_johnson_cook_solver<quadrature::q2>(1); },
                   "johnson_cook / j2+linear, step by step");
  else
    material_ratio(state, [] { return make_zerilli_armstrong_solver<quadrature::q2>(1); },
                   "zerilli_armstrong / j2+linear, step by step");
}

// enforce() corrects d and v in place, so every call gets fresh copies of the state it would
// see inside step(): v(n+1/2) = v(n) + dt/2 a(n), d(n+1) = d(n) + dt v(n+1/2), with
// a(n) = -f_int(n) / m (no body force). Only the enforce call is timed (manual time).
template <class Q>
void BM_contact_enforce(benchmark::State& state) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  auto s = make_wall_solver<Q>(1);
  warm_up(s, 1);
  const index_t n = s.model().particle_count();
  const double dt = s.time_step(), t_next = s.time() + dt;
  std::vector<vec2> d0(n), v0(n);
  for (index_t I = 0; I < n; ++I) {
    v0[I] = s.coefficient_velocities()[I] - 0.5 * dt * s.internal_force()[I] / s.mass()[I];
    d0[I] = s.coefficients()[I] + dt * v0[I];
  }
  std::vector<vec2> d = d0, v = v0;
  contact_result r;
  for (auto _ : state) {
    std::copy(d0.begin(), d0.end(), d.begin());
    std::copy(v0.begin(), v0.end(), v.begin());
    const auto start = std::chrono::steady_clock::now();
    r = s.contact().enforce(s.body(), t_next, dt, d, v);
    benchmark::DoNotOptimize(r);
    state.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  set_counters(state, s);
  state.counters["active_contacts"] = static_cast<double>(r.active);
  state.SetLabel(std::string(Q::name));
}

constexpr int step_iterations = 300;

}  // namespace

BENCHMARK(BM_step<quadrature::q2>)->Arg(1)->Arg(2)->Iterations(step_iterations)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_step<quadrature::q4>)->Arg(1)->Arg(2)->Iterations(step_iterations)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_step<quadrature::q9>)->Arg(1)->Arg(2)->Iterations(step_iterations)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_step_material)->Arg(0)->Arg(1)->Arg(2)->Arg(0)->Arg(1)->Arg(2)->Iterations(step_iterations)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_material_ratio)->Arg(1)->Arg(2)->Iterations(step_iterations)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_step_resolution)->Arg(1)->Arg(2)->Arg(3)->Iterations(100)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_step_rolling<quadrature::q2>)->Arg(1)->Arg(2)->Iterations(step_iterations)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_step_rolling<quadrature::q4>)->Arg(1)->Arg(2)->Iterations(step_iterations)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_contact_enforce<quadrature::q2>)->Arg(1)->Arg(2)->Iterations(2000)->UseManualTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_contact_enforce<quadrature::q4>)->Arg(1)->Arg(2)->Iterations(2000)->UseManualTime()->Unit(benchmark::kMicrosecond);

}  // namespace rkpm::bench
