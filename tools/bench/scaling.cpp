// rkpm_scaling: cost per particle-step and footprint of the explicit loop as the Taylor bar is
// refined (tools/rkpm bench --scaling [options]). One child process per resolution, so that
// each size's peak resident set (wait4's ru_maxrss) is its own: the child builds the solver on
// one thread (the set-up time), takes a few warm-up steps, then times the steps in rounds, each
// round one window on 1 thread and one on 2 threads of the same length, in alternating order
// (so that a drift of the cost along the impact does not read as a thread speed-up). The
// speed-up is the median of the rounds' ratios: a burst of load from the host (this is a
// virtual machine) spoils one round, not the figure. With --rereference the child then rebuilds
// the model in the current configuration once (explicit_solver::rereference, docs/method.md
// section 5.8) on one thread, and reports it in steps on one thread.
// Prints a table and writes DIR/scaling.csv and DIR/scaling.png (cost per particle-step against
// particles, log x). The machine may be shared: read ratios within one run, not absolute times.

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <omp.h>

#include <rkpm/io/gnuplot.hpp>

#include "taylor_bar_solver.hpp"

namespace rkpm::bench {
namespace {

struct options {
  std::vector<int> resolutions{1, 2, 4, 8, 16, 32};
  int max_resolution = 32;
  double particle_steps = 4e6;  // timed particle-steps per thread count and size
  int warm_up_steps = 10;
  int rounds = 5;  // 1-thread / 2-thread window pairs
  std::string rule = "q2";
  bool two_threads = true;  // --one-thread: skip the 2-thread window (a busy machine)
  bool rereference = false; // --rereference: time one rebuild of the model after the steps
  std::filesystem::path out = "results/bench";
};

// What a child measures (written to the parent through a pipe).
struct measurement {
  long particles = 0, points = 0, steps = 0;
  double setup_s = 0.0, one_thread_s = 0.0, two_threads_s = 0.0;
  double speedup = 0.0;  // median over the rounds of (1-thread time / 2-thread time)
  double resident_bytes = 0.0;  // resident set after the timed steps (the peak may be in the set-up)
  double rebuild_s = 0.0;        // --rereference: one rebuild, on one thread
  double rebuild_steps = 0.0;    // the same in steps on one thread
};

// The resident set now, from /proc/self/statm (pages).
double resident_bytes_now() {
  std::ifstream statm("/proc/self/statm");
  double pages = 0.0, resident = 0.0;
  statm >> pages >> resident;
  return resident * static_cast<double>(sysconf(_SC_PAGESIZE));
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

template <class Q>
measurement measure(int resolution, const options& o) {
  measurement m;
  omp_set_num_threads(1);
  const auto start = std::chrono::steady_clock::now();
  auto s = make_wall_solver<Q>(resolution);
  m.setup_s = seconds_since(start);
  m.particles = s.model().particle_count();
  m.points = s.model().point_count();
  for (int k = 0; k < o.warm_up_steps; ++k) s.step();
  m.steps = std::clamp(static_cast<long>(o.particle_steps / static_cast<double>(m.particles)), 3L, 2000L);
  const long rounds = o.two_threads ? std::clamp<long>(o.rounds, 1, m.steps) : 1;
  const long per_round = m.steps / rounds;
  m.steps = per_round * rounds;
  auto timed = [&](int threads) {
    omp_set_num_threads(threads);
    const auto t0 = std::chrono::steady_clock::now();
    for (long k = 0; k < per_round; ++k) s.step();
    return seconds_since(t0);
  };
  std::vector<double> ratio;
  for (long r = 0; r < rounds; ++r) {
    if (!o.two_threads) {
      m.one_thread_s += timed(1);
      continue;
    }
    const double first = timed(r % 2 == 0 ? 1 : 2), second = timed(r % 2 == 0 ? 2 : 1);
    const double one = r % 2 == 0 ? first : second, two = r % 2 == 0 ? second : first;
    m.one_thread_s += one;
    m.two_threads_s += two;
    ratio.push_back(one / two);
  }
  if (!ratio.empty()) {
    std::sort(ratio.begin(), ratio.end());
    const std::size_t h = ratio.size() / 2;
    m.speedup = ratio.size() % 2 ? ratio[h] : 0.5 * (ratio[h - 1] + ratio[h]);
  }
  m.resident_bytes = resident_bytes_now();
  if (o.rereference) {
    omp_set_num_threads(1);  // against the steps on one thread
    const double step_s = m.one_thread_s / static_cast<double>(rounds * per_round);
    const auto t0 = std::chrono::steady_clock::now();
    s.rereference();
    m.rebuild_s = seconds_since(t0);
    m.rebuild_steps = m.rebuild_s / step_s;
  }
  return m;
}

// Runs measure() in a child; returns it with the child's peak resident set in bytes.
std::pair<measurement, double> measure_in_child(int resolution, const options& o) {
  int fd[2];
  if (pipe(fd) != 0) fail("rkpm_scaling: pipe failed");
  const pid_t pid = fork();
  if (pid < 0) fail("rkpm_scaling: fork failed");
  if (pid == 0) {
    close(fd[0]);
    int status = 0;
    try {
      const measurement m = o.rule == "q4" ? measure<quadrature::q4>(resolution, o) : measure<quadrature::q2>(resolution, o);
      if (write(fd[1], &m, sizeof m) != static_cast<ssize_t>(sizeof m)) status = 2;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "rkpm_scaling: resolution %d: %s\n", resolution, e.what());
      status = 1;
    }
    close(fd[1]);
    _exit(status);
  }
  close(fd[1]);
  measurement m;
  const bool got = read(fd[0], &m, sizeof m) == static_cast<ssize_t>(sizeof m);
  close(fd[0]);
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  if (!got || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    fail("rkpm_scaling: the child of resolution {} failed (status {})", resolution, status);
  return {m, static_cast<double>(usage.ru_maxrss) * 1024.0};  // ru_maxrss is in KiB on Linux
}

options parse(int argc, char** argv) {
  options o;
  for (int i = 1; i < argc; ++i) {
    const std::string_view a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) fail("rkpm_scaling: {} needs a value", a);
      return argv[++i];
    };
    if (a == "--max-resolution") o.max_resolution = std::stoi(value());
    else if (a == "--resolutions") {
      o.resolutions.clear();
      std::string list = value();
      for (std::size_t p = 0; p < list.size();) {
        const std::size_t comma = std::min(list.find(',', p), list.size());
        o.resolutions.push_back(std::stoi(list.substr(p, comma - p)));
        p = comma + 1;
      }
    } else if (a == "--particle-steps") o.particle_steps = std::stod(value());
    else if (a == "--warm-up") o.warm_up_steps = std::stoi(value());
    else if (a == "--rounds") o.rounds = std::stoi(value());
    else if (a == "--one-thread") o.two_threads = false;
    else if (a == "--rereference") o.rereference = true;
    else if (a == "--rule") {
      o.rule = value();
      if (o.rule != "q2" && o.rule != "q4") fail("rkpm_scaling: --rule q2 or q4, not {}", o.rule);
    } else if (a == "--out") o.out = value();
    else if (a == "--help" || a == "-h") {
      fmt::print(
          "usage: rkpm_scaling [--max-resolution K] [--resolutions 1,2,4,...] [--particle-steps N]\n"
          "                    [--warm-up STEPS] [--rounds R] [--rule q2|q4] [--one-thread] [--rereference]\n"
          "                    [--out DIR]\n"
          "Taylor bar (cubic, linear, paper contact); one child process per resolution K (about\n"
          "1071 K^2 particles); timed steps per thread count = N / particles (default 4e6, 3 to 2000),\n"
          "in R rounds (default 5) of a 1-thread and a 2-thread window; speed-up: the rounds' median.\n"
          "--rereference: then one rebuild of the model in the current configuration, in steps.\n");
      std::exit(0);
    } else fail("rkpm_scaling: unknown option {} (--help lists them)", a);
  }
  std::erase_if(o.resolutions, [&](int r) { return r < 1 || r > o.max_resolution; });
  if (o.resolutions.empty()) fail("rkpm_scaling: no resolution left at or below --max-resolution {}", o.max_resolution);
  return o;
}

void plot(const std::filesystem::path& csv, const std::filesystem::path& png, const std::string& rule) {
  if (!io::gnuplot_available()) {
    fmt::print(stderr, "rkpm_scaling: gnuplot not found, {} not drawn\n", png.string());
    return;
  }
  io::gnuplot_png(png, fmt::format(
      "set datafile separator ','\n"
      "set logscale x\nset format x '10^{{%L}}'\nset grid\n"
      "set xlabel 'particles'\nset ylabel 'time per particle-step (us)'\nset yrange [0:*]\n"
      "set key bottom right\n"
      "set title 'Taylor bar, {}, cubic, linear: cost per particle-step'\n"
      "plot {} using 1:4 with linespoints lw 2 pt 7 title '1 thread', "
      "'' using 1:5 with linespoints lw 2 pt 5 title '2 threads'\n",
      rule, io::gnuplot_quote(csv.string())), {.width = 900, .height = 600});
}

}  // namespace
}  // namespace rkpm::bench

int main(int argc, char** argv) try {
  using namespace rkpm::bench;
  const options o = parse(argc, argv);
  std::filesystem::create_directories(o.out);
  const auto csv = o.out / "scaling.csv";
  std::ofstream out(csv);
  out << "particles,points,setup_s,us_per_particle_step_1_thread,us_per_particle_step_2_threads,speedup_2_threads,"
         "peak_rss_bytes_per_particle,stepping_rss_bytes_per_particle,resolution,rule,timed_steps,rebuild_s,"
         "rebuild_in_steps\n";
  fmt::print("Taylor bar, {}, cubic, linear, paper contact (one child process per size)\n", o.rule);
  fmt::print("{:>10} {:>10} {:>11} {:>11} {:>9} {:>11} {:>11} {:>10}\n", "particles", "points", "us/p-step 1",
             "us/p-step 2", "speed-up", "peak B/p", "stepping B/p", "set-up (s)");
  for (int r : o.resolutions) {
    const auto [m, rss] = measure_in_child(r, o);
    const double ps = static_cast<double>(m.particles) * static_cast<double>(m.steps);
    const double one = 1e6 * m.one_thread_s / ps, two = 1e6 * m.two_threads_s / ps;  // two = 0: not timed
    const double bytes = rss / static_cast<double>(m.particles);
    const double stepping = m.resident_bytes / static_cast<double>(m.particles);
    fmt::print("{:>10} {:>10} {:>11.3f} {:>11.3f} {:>9.2f} {:>11.0f} {:>11.0f} {:>10.2f}", m.particles, m.points, one,
               two, m.speedup, bytes, stepping, m.setup_s);
    if (o.rereference) fmt::print("  rebuild {:.3f} s = {:.1f} steps", m.rebuild_s, m.rebuild_steps);
    fmt::print("\n");
    std::fflush(stdout);
    out << fmt::format("{},{},{:.4f},{:.5f},{:.5f},{:.3f},{:.0f},{:.0f},{},{},{},{:.4f},{:.2f}\n", m.particles, m.points,
                       m.setup_s, one, two, m.speedup, bytes, stepping, r, o.rule, m.steps, m.rebuild_s,
                       m.rebuild_steps);
    out.flush();
  }
  out.close();
  plot(csv, o.out / "scaling.png", o.rule);
  fmt::print("wrote {} and {}\n", csv.string(), (o.out / "scaling.png").string());
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "%s\n", e.what());
  return 1;
}
