// Tutorial 13: extreme deformation, with kernels rebuilt in the current configuration.
//
// ---------------------------------------------------------------------------------------
// Introduction
// ---------------------------------------------------------------------------------------
// Tutorial 04 ran the paper's Taylor bar at 227 m/s. Faster, the impact face flattens into thin
// layers: every kernel was built once, in the reference configuration, so its support is carried
// by F into a needle or a pancake, and the stable step follows its thinnest direction. This
// program runs the same bar twice at a higher speed (300 m/s by default):
//   - Lagrangian: the kernels of t = 0 throughout (the default of every other program);
//   - re-referenced: whenever a point's principal stretch since the last rebuild exceeds a
//     threshold (1.5 here), the solver makes the current configuration the reference and builds
//     the kernels there again (docs/method.md section 5.8). One line of run_options does it:
//         options.rereference.max_stretch = 1.5;
// and writes, for both, the step size over time, the final shapes with some kernel supports
// drawn as the ellipses they have become, and what each run cost.
//
// Usage: tutorial_13_extreme_deformation [output directory] [velocity m/s] [resolution K]
//                                         [max stretch] [end time s]
//        (defaults: results/13_extreme_deformation, 300, 1, 1.5 and the paper's 80e-6 s; from
//        500 m/s on every particle is a contact slave and the wall twice as wide, below)

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <numbers>
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
// The method, as types: tutorial 04's Q2 method. Re-referencing is not a type: it is a choice
// of run_options, so both runs share one solver type (and one compilation).
// ---------------------------------------------------------------------------------------
using contact_t = contact::particle_to_segment<contact::enforcement::paper, contact::friction::coulomb>;
using method = config<kernel::cubic_spline, correction::linear, quadrature::q2, taylor_bar::geometry_type,
                      taylor_bar::material_type, contact_t>;

struct outcome {
  std::string name;
  double seconds = 0.0, height_mm = 0.0, length_mm = 0.0, radius_mm = 0.0, dt_ratio = 0.0, balance = 0.0;
  long steps = 0;
  index_t rereferences = 0;
};

// The support of particle I as the ellipse it has become: x_I + F_I diag(a_I) (cos t, sin t),
// with F_I the deformation since the kernels were built, at the particle (the lumped
// projection of the points' values, docs/method.md (72)).
template <class Solver>
void write_supports(const Solver& s, const fs::path& path) {
  const auto F = s.template project_to_particles<mat2>([&](index_t q) {
    return mat2(s.point_relative_deformation_gradient(q).template topLeftCorner<2, 2>());
  });
  const auto x = s.particle_positions();
  const auto& X0 = s.initial_positions();
  io::csv_writer out(path, {"r_mm", "z_mm", "particle"});
  const double top = taylor_bar::parameters{}.height_m;
  for (index_t I = 0; I < s.model().particle_count(); ++I) {
    // Every fourth particle of the axial rows near the impact face, and of the axis: a few
    // ellipses where the bar deforms most, not a solid blot.
    const bool near_face = X0[I][1] < 0.2 * top && I % 4 == 0;
    if (!near_face) continue;
    const vec2 a = s.model().particles.support[I];
    for (int k = 0; k <= 48; ++k) {
      const double t = 2.0 * std::numbers::pi * k / 48.0;
      const vec2 p = x[I] + F[I] * vec2(a[0] * std::cos(t), a[1] * std::sin(t));
      out.row({p[0] * 1e3, p[1] * 1e3, static_cast<double>(I)});
    }
    out.row({NAN, NAN, NAN});  // a gap: gnuplot starts the next ellipse afresh
  }
}

outcome run(const std::string& name, const taylor_bar::parameters& params, int resolution,
            rereference_policy when, const fs::path& dir) {
  run_options options;
  options.end_time = params.end_time_s;
  options.rereference = when;
  const auto start = std::chrono::steady_clock::now();
  auto solver = make_solver<method>(taylor_bar::build<contact_t>(params, resolution), options);
  fmt::print("{}: {} particles, first step {:.3g} ns\n", name, solver.model().particle_count(),
             solver.time_step() * 1e9);
  write_supports(solver, dir / fmt::format("supports_start_{}.csv", name));

  io::csv_writer history(dir / fmt::format("history_{}.csv", name),
                         {"time_us", "dt_ns", "height_mm", "radius_mm", "rereferences"});
  double next_report = 0.0;
  auto observe = [&](const auto& s) {
    const auto m = taylor_bar::measure(s, params, {});
    history.row({s.time() * 1e6, s.time_step() * 1e9, m[1].second, m[0].second, static_cast<double>(s.rereferences())});
    if (s.time() >= next_report) {
      fmt::print("  {:>5.1f} us  step {:>8}  dt {:.3g} ns  height {:.3f} mm  rebuilds {}\n", s.time() * 1e6,
                 s.steps(), s.time_step() * 1e9, m[1].second, s.rereferences());
      std::fflush(stdout);
      next_report += 0.1 * options.end_time;
    }
  };
  solver.run(observe, 100);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const auto x = solver.particle_positions();
  io::csv_writer shape(dir / fmt::format("shape_{}.csv", name), {"r_mm", "z_mm"});
  for (const vec2& p : x) shape.row({p[0] * 1e3, p[1] * 1e3});
  write_supports(solver, dir / fmt::format("supports_end_{}.csv", name));

  outcome o{name};
  for (const auto& [key, value] : taylor_bar::measure(solver, params, {})) {
    if (key == "height_mm") o.height_mm = value;
    if (key == "radius_mm") o.radius_mm = value;
    if (key == "length_mm") o.length_mm = value;
  }
  o.seconds = seconds;
  o.steps = static_cast<long>(solver.steps());
  o.dt_ratio = solver.min_time_step() / solver.max_time_step();
  o.balance = solver.energy().balance_error();
  o.rereferences = solver.rereferences();
  return o;
}

void plot(const fs::path& dir) {
  if (!io::gnuplot_available()) {
    fmt::print("gnuplot not found: the CSV files are in {}\n", dir.string());
    return;
  }
  const auto file = [&](const std::string& f) { return "'" + (dir / f).string() + "'"; };
  const std::string common = "set datafile separator ','\nset grid\n";
  io::gnuplot_png(dir / "time_step.png",
                  common + "set logscale y\nset xlabel 'time (us)'\nset ylabel 'time step (ns)'\n"
                           "plot " + file("history_lagrangian.csv") + " u 1:2 w l lw 2 t 'Lagrangian', " +
                      file("history_rereferenced.csv") + " u 1:2 w l lw 2 t 're-referenced'\n");
  // Side by side: the Lagrangian bar mirrored to negative r, the re-referenced one on the right,
  // each with the supports of a few particles near the impact face as they are at the end.
  io::gnuplot_png(dir / "shapes.png",
                  common + "set size ratio -1\nset xlabel 'r (mm): Lagrangian left, re-referenced right'\n"
                           "set ylabel 'z (mm)'\n"
                           "plot " + file("shape_lagrangian.csv") + " u (-$1):2 w p pt 7 ps 0.3 lc rgb '#1f77b4' t 'Lagrangian', " +
                      file("shape_rereferenced.csv") + " u 1:2 w p pt 7 ps 0.3 lc rgb '#d62728' t 're-referenced', " +
                      file("supports_end_lagrangian.csv") + " u (-$1):2 w l lc rgb '#555555' t 'supports', " +
                      file("supports_end_rereferenced.csv") + " u 1:2 w l lc rgb '#555555' notitle\n",
                  {.width = 900, .height = 900});
  io::gnuplot_png(dir / "supports_start.png",
                  common + "set size ratio -1\nset xlabel 'r (mm)'\nset ylabel 'z (mm)'\n"
                           "plot " + file("supports_start_lagrangian.csv") + " u 1:2 w l t 'supports at t = 0'\n",
                  {.width = 600, .height = 600});
  fmt::print("figures: time_step.png, shapes.png, supports_start.png in {}\n", dir.string());
}

int main(int argc, char** argv) {
  try {
    const fs::path dir = argc > 1 ? fs::path(argv[1]) : fs::path("results/13_extreme_deformation");
    fs::create_directories(dir);
    taylor_bar::parameters params;
    params.velocity_m_s = argc > 2 ? std::strtod(argv[2], nullptr) : 300.0;
    const int resolution = argc > 3 ? std::atoi(argv[3]) : 1;
    const double max_stretch = argc > 4 ? std::strtod(argv[4], nullptr) : 1.5;
    if (argc > 5) params.end_time_s = std::strtod(argv[5], nullptr);
    if (params.velocity_m_s >= 500.0) {
      // The face spreads to eight times its radius and its surface particles far apart: the rows
      // behind them reach the wall between them, so every particle must see the wall
      // (docs/method.md section 5.8), and the wall must reach past the face.
      params.slave_layers = 0;
      params.wall_extent = 16.0;
    }

    const outcome lagrangian = run("lagrangian", params, resolution, {}, dir);
    const outcome rebuilt = run("rereferenced", params, resolution, {.max_stretch = max_stretch}, dir);

    io::csv_writer cost(dir / "cost.csv", {"rereferenced", "steps", "wall_s", "dt_min_over_max", "height_mm", "length_mm",
                                           "radius_mm", "rereferences", "balance_error"});
    fmt::print("\n{:<13} {:>9} {:>8} {:>12} {:>9} {:>9} {:>9} {:>8} {:>9}\n", "run", "steps", "time", "dt min/max",
               "height", "length", "radius", "rebuilds", "balance");
    for (const outcome& o : {lagrangian, rebuilt}) {
      fmt::print("{:<13} {:>9} {:>6.1f} s {:>12.3g} {:>6.2f} mm {:>6.2f} mm {:>6.2f} mm {:>8} {:>9.1e}\n", o.name,
                 o.steps, o.seconds, o.dt_ratio, o.height_mm, o.length_mm, o.radius_mm, o.rereferences, o.balance);
      cost.row({o.rereferences > 0 ? 1.0 : 0.0, static_cast<double>(o.steps), o.seconds, o.dt_ratio, o.height_mm, o.length_mm, o.radius_mm,
                        static_cast<double>(o.rereferences), o.balance});
    }
    fmt::print("re-referenced / Lagrangian: steps {:.3f}, time {:.3f}\n",
               static_cast<double>(rebuilt.steps) / static_cast<double>(lagrangian.steps),
               rebuilt.seconds / lagrangian.seconds);
    plot(dir);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tutorial_13_extreme_deformation: %s\n", e.what());
    return 1;
  }
}
