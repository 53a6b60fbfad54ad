// Tutorial 04: the Taylor bar impact, with the paper's two quadrature rules.
//
// ---------------------------------------------------------------------------------------
// Introduction
// ---------------------------------------------------------------------------------------
// A copper cylinder (radius 3.2 mm, length 32.4 mm) hits a rigid wall at 227 m/s
// (docs/method.md section 10.1). The bar mushrooms: the impact face spreads to more than twice
// its radius and the bar loses a third of its length in 80 us. The paper's Table 3 gives the
// final radius of the impact face and the final height for the 2x2 Gauss rule (Q4) and for
// its cheaper two-point rule (Q2); this program computes both.
//
// The case itself (geometry, material, wall, particles) is cases/taylor_bar.hpp: a function
// that turns a struct of parameters into an rkpm::problem for any contact policy. What this
// program chooses is the *method*: one type, rkpm::config<...>, names the kernel, correction,
// quadrature, geometry, material and contact policy, and rkpm::make_solver<method>(problem, options)
// builds the solver for exactly that combination.
//
// Usage: tutorial_04_taylor_bar [output directory] [end time in s]
//        (defaults: results/04_taylor_bar and the paper's 80e-6 s)

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/io/csv.hpp>
#include <rkpm/io/gnuplot.hpp>
#include <rkpm/solver/make_solver.hpp>

#include "cases/taylor_bar.hpp"

namespace fs = std::filesystem;
using namespace rkpm;
using taylor_bar = cases::taylor_bar;

// ---------------------------------------------------------------------------------------
// The method, as types
// ---------------------------------------------------------------------------------------
// The paper's contact algorithm (P4)-(P7) against the rigid wall. The wall is frictionless
// (the case's friction coefficient is 0), but a Coulomb law with coefficient 0 costs nothing
// and lets `--set friction=...` style experiments reuse the same type.
using contact_t = contact::particle_to_segment<contact::enforcement::paper, contact::friction::coulomb>;

// Cubic B-spline kernel, linear correction (reproduces 1, r, z), 2x2 Gauss points per
// background cell; axisymmetric geometry and J2 plasticity with linear hardening, as the case
// requires.
using method_q4 = config<kernel::cubic_spline, correction::linear, quadrature::q4, taylor_bar::geometry_type,
                         taylor_bar::material_type, contact_t>;
// The paper's point: the same method with two points per cell. One alias swaps the rule.
using method_q2 = method_q4::with_quadrature<quadrature::q2>;

struct outcome {
  double radius_mm = 0.0, height_mm = 0.0, eps_p = 0.0, balance_error = 0.0, seconds = 0.0;
  long steps = 0;
  index_t particles = 0, points = 0;
};

// The case's measures (cases/taylor_bar.hpp) by their names.
struct measured {
  double radius_mm = 0.0, height_mm = 0.0, eps_p = 0.0;
};
template <class Solver>
measured measures(const Solver& s, const taylor_bar::parameters& params) {
  measured out;
  for (const auto& [name, value] : taylor_bar::measure(s, params, {})) {
    if (name == "radius_mm") out.radius_mm = value;
    if (name == "height_mm") out.height_mm = value;
    if (name == "max_equivalent_plastic_strain") out.eps_p = value;
  }
  return out;
}

// ---------------------------------------------------------------------------------------
// One run
// ---------------------------------------------------------------------------------------
template <class Method>
outcome run(const taylor_bar::parameters& params, const fs::path& dir) {
  const std::string rule(Method::quadrature_type::name);
  run_options options;
  options.end_time = taylor_bar::end_time(params);  // the step is chosen by rkpm (0.7 of the stable step)

  const auto start = std::chrono::steady_clock::now();
  // make_solver builds the discrete model of the method's kernel, correction and rule, then the
  // solver of its geometry, material and contact.
  auto solver = make_solver<Method>(taylor_bar::build<contact_t>(params, /*resolution=*/1), options);
  fmt::print("{}: {} particles, {} quadrature points, first time step {:.3g} ns\n", rule,
             solver.model().particle_count(), solver.model().point_count(), solver.time_step() * 1e9);

  // Time history of the key measures, every 20 steps, and a progress line every tenth of the run.
  io::csv_writer history(dir / fmt::format("history_{}.csv", rule),
                         {"time_us", "radius_mm", "height_mm", "max_eps_p", "kinetic_J", "balance_error"});
  double next_report = 0.0;
  auto observe = [&](const auto& s) {
    const auto m = measures(s, params);
    history.row({s.time() * 1e6, m.radius_mm, m.height_mm, m.eps_p, s.energy().kinetic,
                 s.energy().balance_error()});
    if (s.time() >= next_report) {
      fmt::print("  {:>5.1f} us  step {:>6}  radius {:.3f} mm  height {:.3f} mm\n", s.time() * 1e6, s.steps(),
                 m.radius_mm, m.height_mm);
      std::fflush(stdout);
      next_report += 0.1 * options.end_time;
    }
  };
  solver.run(observe, 20);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // The deformed section: every particle's current (r, z), and its reference position.
  const auto x = solver.particle_positions();
  const auto& X = solver.model().particles.position;
  io::csv_writer shape(dir / fmt::format("shape_{}.csv", rule), {"r0_mm", "z0_mm", "r_mm", "z_mm"});
  for (std::size_t I = 0; I < x.size(); ++I) shape.row({X[I][0] * 1e3, X[I][1] * 1e3, x[I][0] * 1e3, x[I][1] * 1e3});

  const measured m = measures(solver, params);
  return {m.radius_mm,           m.height_mm, m.eps_p, solver.energy().balance_error(), seconds,
          static_cast<long>(solver.steps()), solver.model().particle_count(), solver.model().point_count()};
}

// ---------------------------------------------------------------------------------------
// Figures
// ---------------------------------------------------------------------------------------
void plot(const fs::path& dir) {
  if (!io::gnuplot_available()) {
    fmt::print("gnuplot not found: the CSV files are in {}\n", dir.string());
    return;
  }
  const std::string q4 = (dir / "history_q4.csv").string(), q2 = (dir / "history_q2.csv").string();
  const std::string common = "set datafile separator ','\nset key autotitle columnhead\nset grid\n";
  io::gnuplot_png(dir / "radius.png",
                  common + "set xlabel 'time (us)'\nset ylabel 'impact face radius (mm)'\n"
                           "plot '" + q4 + "' u 1:2 w l lw 2 t 'Q4', '" + q2 + "' u 1:2 w l lw 2 dt 2 t 'Q2'\n");
  io::gnuplot_png(dir / "height.png",
                  common + "set xlabel 'time (us)'\nset ylabel 'height (mm)'\n"
                           "plot '" + q4 + "' u 1:3 w l lw 2 t 'Q4', '" + q2 + "' u 1:3 w l lw 2 dt 2 t 'Q2'\n");
  // Side by side: Q4 mirrored to negative r, Q2 on the right, the undeformed bar in grey.
  const std::string s4 = (dir / "shape_q4.csv").string(), s2 = (dir / "shape_q2.csv").string();
  io::gnuplot_png(dir / "shape.png",
                  common + "set size ratio -1\nset xlabel 'r (mm): Q4 left, Q2 right'\nset ylabel 'z (mm)'\n"
                           "plot '" + s4 + "' u (-$1):2 w p pt 7 ps 0.3 lc rgb '#bbbbbb' t 'initial', '" + s2 +
                      "' u 1:2 w p pt 7 ps 0.3 lc rgb '#bbbbbb' notitle, '" + s4 +
                      "' u (-$3):4 w p pt 7 ps 0.4 lc rgb '#1f77b4' t 'Q4', '" + s2 +
                      "' u 3:4 w p pt 7 ps 0.4 lc rgb '#d62728' t 'Q2'\n",
                  {.width = 700, .height = 900});
  fmt::print("figures: radius.png, height.png, shape.png in {}\n", dir.string());
}

int main(int argc, char** argv) {
  try {
    const fs::path dir = argc > 1 ? fs::path(argv[1]) : fs::path("results/04_taylor_bar");
    fs::create_directories(dir);
    taylor_bar::parameters params;  // the paper's numbers; change any field here
    if (argc > 2) params.end_time_s = std::strtod(argv[2], nullptr);

    const outcome q4 = run<method_q4>(params, dir);
    const outcome q2 = run<method_q2>(params, dir);

    fmt::print("\n{:<4} {:>9} {:>9} {:>10} {:>8} {:>8} {:>9}   paper (Table 3)\n", "rule", "radius", "height",
               "max eps_p", "steps", "time", "balance");
    auto line = [](const char* rule, const outcome& o, double pr, double ph) {
      fmt::print("{:<4} {:>6.2f} mm {:>6.2f} mm {:>10.3f} {:>8} {:>6.1f} s {:>9.1e}   {:.2f} mm / {:.2f} mm\n", rule,
                 o.radius_mm, o.height_mm, o.eps_p, o.steps, o.seconds, o.balance_error, pr, ph);
    };
    line("Q4", q4, taylor_bar::paper_radius_q4_mm, taylor_bar::paper_height_q4_mm);
    line("Q2", q2, taylor_bar::paper_radius_q2_mm, taylor_bar::paper_height_q2_mm);
    fmt::print("Q2 used {} quadrature points against {} and {:.0f}% less time\n", q2.points, q4.points,
               100.0 * (1.0 - q2.seconds / q4.seconds));
    plot(dir);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tutorial_04_taylor_bar: %s\n", e.what());
    return 1;
  }
}
