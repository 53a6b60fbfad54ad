// Tutorial 05: plane-strain forging of a block between two flat tools.
//
// ---------------------------------------------------------------------------------------
// Introduction
// ---------------------------------------------------------------------------------------
// A 500 mm x 500 mm copper block is squeezed between two rigid flat tools that move toward
// each other at 10 m/s each, with Coulomb friction 0.2, to 60% reduction of its height
// (docs/method.md section 10.2). Friction holds the faces back while the middle flows out: the
// block barrels. The tools slide along the body and new body surface folds onto them, so
// contact must be found anew every step: the particle-to-segment search of (P4)-(P7).
//
// cases/block_forging.hpp builds the problem (21 x 21 particles, tools, material) from a
// parameter struct; this program chooses the method, runs it, records the tool force against
// the stroke and the shapes at 0, 20, 40 and 60% compression, and plots them.
//
// Usage: tutorial_05_block_forging [output directory] [end time in s]
//        (defaults: results/05_block_forging and the paper's 0.015 s, i.e. 60%)

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/io/csv.hpp>
#include <rkpm/io/gnuplot.hpp>
#include <rkpm/solver/make_solver.hpp>

#include "cases/block_forging.hpp"

namespace fs = std::filesystem;
using namespace rkpm;
using block_forging = cases::block_forging;

// ---------------------------------------------------------------------------------------
// The method
// ---------------------------------------------------------------------------------------
// The paper's enforcement with Coulomb friction: the tangential force is the one that makes
// the slave stick to the tool (P6), capped at mu times the normal force (P5).
using contact_t = contact::particle_to_segment<contact::enforcement::paper, contact::friction::coulomb>;
// Q4 keeps the mirror symmetry of the problem about x = 0; the paper's Q2 places its two points
// on one diagonal of each cell, which tilts the block slightly (tutorial 04 compares the rules).
using method = config<kernel::cubic_spline, correction::linear, quadrature::q4, block_forging::geometry_type,
                      block_forging::material_type, contact_t>;

int main(int argc, char** argv) {
  try {
    const fs::path dir = argc > 1 ? fs::path(argv[1]) : fs::path("results/05_block_forging");
    fs::create_directories(dir);
    block_forging::parameters params;  // the paper's numbers
    if (argc > 2) params.end_time_s = std::strtod(argv[2], nullptr);

    run_options options;
    options.end_time = block_forging::end_time(params);
    auto solver = make_solver<method>(block_forging::build<contact_t>(params, /*resolution=*/1), options);
    const double h = params.width_m / (params.particles_per_side - 1.0);
    fmt::print("{} particles, {} quadrature points, first time step {:.3g} us, {:.0f} mm of closure\n",
               solver.model().particle_count(), solver.model().point_count(), solver.time_step() * 1e6,
               2e3 * params.tool_velocity_m_s * options.end_time);

    // The force on the top tool, per metre of depth. The reaction of one step is noisy (a slave
    // particle arriving on the tool is stopped in one step), so we average it over windows of
    // 1% of the run: the impulse of the window divided by its length (tool_impulses() is each
    // tool's impulse since t = 0, so the window's is the difference of two readings).
    io::csv_writer history(dir / "history.csv",
                           {"stroke_mm", "compression_percent", "force_MN_per_m", "width_mm", "balance_error"});
    double window_impulse = 0.0, window_start = 0.0, next_report = 0.0;
    std::vector<double> shape_at{0.0, 0.2, 0.4, 0.6};  // compressions whose shapes we keep
    std::size_t next_shape = 0;
    // The outline of the block: the particles of the reference boundary in order around it (the
    // perimeter coordinate of each in the undeformed square), closed by repeating the first.
    std::vector<std::pair<double, index_t>> outline;
    {
      const auto& X = solver.model().particles.position;
      const double W = params.width_m, H = params.height_m, lo = -0.5 * W, e = 1e-9;
      for (index_t I = 0; I < solver.model().particle_count(); ++I) {
        const double x = X[I][0], y = X[I][1];
        if (y < e) outline.push_back({x - lo, I});
        else if (x > lo + W - e) outline.push_back({W + y, I});
        else if (y > H - e) outline.push_back({W + H + (lo + W - x), I});
        else if (x < lo + e) outline.push_back({2 * W + H + (H - y), I});
      }
      std::sort(outline.begin(), outline.end());
      outline.push_back(outline.front());
    }
    auto write_shape = [&](const auto& s, double compression) {
      const auto x = s.particle_positions();
      io::csv_writer shape(dir / fmt::format("outline_{:.0f}.csv", compression * 100), {"x_mm", "y_mm"});
      for (const auto& [_, I] : outline) shape.row({x[I][0] * 1e3, x[I][1] * 1e3});
      io::csv_writer all(dir / fmt::format("particles_{:.0f}.csv", compression * 100), {"x_mm", "y_mm"});
      for (const vec2& xi : x) all.row({xi[0] * 1e3, xi[1] * 1e3});
    };
    auto observe = [&](const auto& s) {
      const double t = s.time();
      const double impulse = s.tool_impulses()[1].y();  // tool 1 is the top tool
      const double stroke = 2.0 * params.tool_velocity_m_s * t, compression = stroke / params.height_m;
      while (next_shape < shape_at.size() && compression >= shape_at[next_shape] - 1e-9) write_shape(s, shape_at[next_shape++]);
      if (t - window_start >= 0.01 * options.end_time || t >= options.end_time * (1 - 1e-12)) {
        const double force = (impulse - window_impulse) / (t - window_start);
        const auto m = block_forging::measure(s, params, {});
        history.row({stroke * 1e3, compression * 100, force * 1e-6, m[1].second, s.energy().balance_error()});
        window_impulse = impulse;
        window_start = t;
        if (t >= next_report) {
          fmt::print("  {:>4.1f} ms  step {:>6}  compression {:>4.1f}%  width {:>6.1f} mm  force {:>6.1f} MN/m\n",
                     t * 1e3, s.steps(), compression * 100, m[1].second, force * 1e-6);
          std::fflush(stdout);
          next_report += 0.1 * options.end_time;
        }
      }
    };
    solver.run(observe, 1);

    // Key results: the width of the faces and of the middle (barrelling), the volume balance and
    // the largest penetration of a tool, relative to the particle spacing.
    const auto x = solver.particle_positions();
    const auto& X = solver.model().particles.position;
    auto row_width = [&](double y) {
      double lo = 1e30, hi = -1e30;
      for (std::size_t I = 0; I < x.size(); ++I)
        if (std::abs(X[I][1] - y) < 1e-9) lo = std::min(lo, x[I][0]), hi = std::max(hi, x[I][0]);
      return hi - lo;
    };
    double area0 = 0.0, area = 0.0;
    for (index_t q = 0; q < solver.model().point_count(); ++q) {
      area0 += solver.model().points.weight[q];
      area += solver.model().points.weight[q] * solver.point_det_F(q);
    }
    const auto m = block_forging::measure(solver, params, {});
    fmt::print("\nafter {} steps ({:.0f}% compression):\n", solver.steps(),
               100.0 * (1.0 - block_forging::gap(params, solver.time()) / params.height_m));
    fmt::print("  tool gap            {:.1f} mm\n  width at the faces  {:.1f} mm (bottom), {:.1f} mm (top)\n",
               m[0].second, row_width(0.0) * 1e3, row_width(params.height_m) * 1e3);
    fmt::print("  width at mid-height {:.1f} mm\n  largest width       {:.1f} mm\n",
               row_width(0.5 * params.height_m) * 1e3, m[1].second);
    fmt::print("  area change         {:.2f}%\n  largest penetration {:.3f} mm ({:.1f}% of the spacing)\n",
               100.0 * (area / area0 - 1.0), m[2].second, 100.0 * m[2].second * 1e-3 / h);
    fmt::print("  energy balance error {:.1e}\n", solver.energy().balance_error());

    if (!io::gnuplot_available()) {
      fmt::print("gnuplot not found: the CSV files are in {}\n", dir.string());
      return 0;
    }
    const std::string common = "set datafile separator ','\nset grid\n";
    io::gnuplot_png(dir / "tool_force.png",
                    common + "set xlabel 'stroke (mm)'\nset ylabel 'top tool force (MN per m of depth)'\n"
                             "plot '" + (dir / "history.csv").string() + "' u 1:3 w l lw 2 notitle\n");
    // Outlines at each compression, and the particles of the last one.
    std::string shapes = common + "set size ratio -1\nset xlabel 'x (mm)'\nset ylabel 'y (mm)'\nset key outside\nplot ";
    for (std::size_t k = 0; k < next_shape; ++k)
      shapes += fmt::format("{}'{}' u 1:2 w l lw 2 t '{:.0f}%'", k ? ", " : "",
                            (dir / fmt::format("outline_{:.0f}.csv", shape_at[k] * 100)).string(), shape_at[k] * 100);
    if (next_shape > 0)
      shapes += fmt::format(", '{}' u 1:2 w p pt 7 ps 0.4 lc rgb 'black' t 'particles at {:.0f}%'",
                            (dir / fmt::format("particles_{:.0f}.csv", shape_at[next_shape - 1] * 100)).string(),
                            shape_at[next_shape - 1] * 100);
    io::gnuplot_png(dir / "shapes.png", shapes + "\n", {.width = 1000, .height = 600});
    fmt::print("figures: tool_force.png, shapes.png in {}\n", dir.string());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tutorial_05_block_forging: %s\n", e.what());
    return 1;
  }
}
