// Tutorial 06: axisymmetric forging of a wheel, a punch and a die with corners.
//
// ---------------------------------------------------------------------------------------
// Introduction
// ---------------------------------------------------------------------------------------
// An aluminium slug (radius 22 mm, height 28 mm) stands on a die (a floor and a wall at
// r = 35 mm). A shaped punch comes down at 10 m/s for 20 mm: its land (r 12..24 mm) presses
// the slug while a hub recess (r < 10 mm) and a rim recess (r > 26 mm) leave room for the
// material to rise (docs/method.md section 10.3; the paper's figure of the tools is lost, and
// cases/wheel_forging.hpp documents our reconstruction). The flow stress follows a power law,
// sigma_y = 576.79 (0.01658 + eps_p)^0.3593 MPa, and contact is frictionless.
//
// Unlike the flat tools of tutorial 05, the punch has corners and slanted flanks: a slave
// particle may touch two segments in one step, and the contact search must pick the one it
// crossed (rkpm/contact/segment_search.hpp). The body is axisymmetric: each particle is a
// ring, the axis r = 0 is held at u_r = 0, and the forces are per radian times 2 pi (total).
//
// Usage: tutorial_06_wheel_forging [output directory] [stroke in m]
//        (defaults: results/06_wheel_forging and the full 20 mm)

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

#include "cases/wheel_forging.hpp"

namespace fs = std::filesystem;
using namespace rkpm;
using wheel_forging = cases::wheel_forging;

// The paper's enforcement; Coulomb with the case's coefficient 0 (frictionless). The paper's
// two-point rule: the shapes of Q4 and Q2 are alike here (the paper's figure 9).
using contact_t = contact::particle_to_segment<contact::enforcement::paper, contact::friction::coulomb>;
using method = config<kernel::cubic_spline, correction::linear, quadrature::q2, wheel_forging::geometry_type,
                      wheel_forging::material_type, contact_t>;

int main(int argc, char** argv) {
  try {
    const fs::path dir = argc > 1 ? fs::path(argv[1]) : fs::path("results/06_wheel_forging");
    fs::create_directories(dir);
    wheel_forging::parameters params;  // the paper's numbers (and our tool reconstruction)
    if (argc > 2) params.stroke_m = std::strtod(argv[2], nullptr);

    run_options options;
    options.end_time = wheel_forging::end_time(params);  // stroke / speed
    auto solver = make_solver<method>(wheel_forging::build<contact_t>(params, /*resolution=*/1), options);
    fmt::print("{} particles, {} quadrature points, first time step {:.3g} ns, stroke {:.1f} mm\n",
               solver.model().particle_count(), solver.model().point_count(), solver.time_step() * 1e9,
               params.stroke_m * 1e3);

    // History: the case's measures (volume change, heights in the recesses, penetration) and the
    // punch force averaged over windows of 0.5% of the run (one step's reaction is noisy).
    io::csv_writer history(dir / "history.csv", {"stroke_mm", "punch_force_kN", "volume_change_percent",
                                                 "hub_height_mm", "rim_height_mm", "max_penetration_mm"});
    // tool_impulses() is each tool's impulse since t = 0: a window's is the difference of two.
    double window_impulse = 0.0, window_start = 0.0, next_report = 0.0, last_force = 0.0;
    auto observe = [&](const auto& s) {
      const double t = s.time();
      if (t - window_start < 0.005 * options.end_time && t < options.end_time * (1 - 1e-12)) return;
      const double impulse = s.tool_impulses()[0].y();  // tool 0 is the punch
      const double force = t > window_start ? (impulse - window_impulse) / (t - window_start) : 0.0;
      last_force = force;
      window_impulse = impulse;
      window_start = t;
      const auto m = wheel_forging::measure(s, params, {});
      const double stroke_mm = params.tool_velocity_m_s * t * 1e3;
      history.row({stroke_mm, force * 1e-3, m[1].second * 100, m[2].second, m[3].second, m[0].second});
      if (t >= next_report) {
        fmt::print("  stroke {:>5.2f} mm  step {:>6}  punch {:>7.1f} kN  hub {:>5.2f} mm  volume {:+.2f}%\n",
                   stroke_mm, s.steps(), force * 1e-3, m[2].second, m[1].second * 100);
        std::fflush(stdout);
        next_report += 0.1 * options.end_time;
      }
    };
    solver.run(observe, 1);

    // Final shape, and the tools where they are at the end.
    const auto x = solver.particle_positions();
    {
      io::csv_writer shape(dir / "shape.csv", {"r_mm", "z_mm"});
      for (const vec2& xi : x) shape.row({xi[0] * 1e3, xi[1] * 1e3});
      io::csv_writer punch(dir / "punch.csv", {"r_mm", "z_mm"});
      for (const vec2& c : wheel_forging::punch_outline()) punch.row({c[0] * 1e3, (c[1] - params.stroke_m) * 1e3});
      io::csv_writer die(dir / "die.csv", {"r_mm", "z_mm"});
      for (const vec2& c : wheel_forging::die_outline()) die.row({c[0] * 1e3, c[1] * 1e3});
    }
    double r_max = 0.0;
    for (const vec2& xi : x) r_max = std::max(r_max, xi[0]);
    const auto m = wheel_forging::measure(solver, params, {vec2(0.0, last_force)});
    fmt::print("\nafter {} steps ({:.1f} mm of stroke):\n", solver.steps(), solver.time() * params.tool_velocity_m_s * 1e3);
    for (const auto& [name, value] : m) fmt::print("  {:<22} {:.4g}\n", name, value);
    fmt::print("  {:<22} {:.4g}\n  energy balance error   {:.1e}\n", "largest_radius_mm", r_max * 1e3,
               solver.energy().balance_error());

    if (!io::gnuplot_available()) {
      fmt::print("gnuplot not found: the CSV files are in {}\n", dir.string());
      return 0;
    }
    const std::string common = "set datafile separator ','\nset grid\n";
    io::gnuplot_png(dir / "shape.png",
                    common + "set size ratio -1\nset xrange [0:40]\nset yrange [-2:45]\nset xlabel 'r (mm)'\n"
                             "set ylabel 'z (mm)'\nplot '" + (dir / "shape.csv").string() +
                        "' u 1:2 w p pt 7 ps 0.5 t 'particles', '" + (dir / "punch.csv").string() +
                        "' u 1:2 w l lw 3 t 'punch', '" + (dir / "die.csv").string() + "' u 1:2 w l lw 3 t 'die'\n",
                    {.width = 800, .height = 900});
    io::gnuplot_png(dir / "punch_force.png",
                    common + "set xlabel 'stroke (mm)'\nset ylabel 'punch force (kN)'\nplot '" +
                        (dir / "history.csv").string() + "' u 1:2 w l lw 2 notitle\n");
    fmt::print("figures: shape.png, punch_force.png in {}\n", dir.string());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tutorial_06_wheel_forging: %s\n", e.what());
    return 1;
  }
}
