// Tutorial 14: fracture, cracks that cut the kernels.
//
// ---------------------------------------------------------------------------------------
// Introduction
// ---------------------------------------------------------------------------------------
// A brittle material that breaks (material::rankine_fracture: Rankine's maximum principal stress
// with a fracture energy G_c, docs/method.md section 4.7) and cracks that cut the approximation
// (section 3.7): when a point has failed, the solver cuts its background cell through its centre,
// normal to the direction the point broke in, and rebuilds the model so that no kernel reaches
// across a cut (section 5.12). Nothing in the solver's type changes: the material is the only
// new policy, and a cell may be cut by hand before the run (a notch).
//
// The experiment: Kalthoff and Winkler's edge-impact test (J.F. Kalthoff, S. Winkler, "Failure
// mode transition at high rates of shear loading", Impact Loading and Dynamic Behavior of
// Materials, DGM Informationsgesellschaft, 1988, 185-195). A plate of maraging steel with two
// parallel edge notches is struck between them by a projectile; at low speed a brittle crack
// leaves each notch tip at about 70 degrees to the notch. Here the upper half (the plate is
// symmetric about the line between the notches), 100 x 100 mm, its notch 50 mm long along
// y = 25 mm, the edge below the notch pushed at 16.5 m/s. The program writes the crack path
// (each cut as a segment), the particles at the end, the energy ledger with the fracture energy,
// and the crack's angle, measured from the notch tip to the cut cells within 30 mm of it.
//
// Usage: tutorial_14_fracture [output directory] [cell size mm] [end time s]
//        (defaults: results/14_fracture, 2 mm, 80e-6 s)

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include <rkpm/contact/none.hpp>
#include <rkpm/io/csv.hpp>
#include <rkpm/io/gnuplot.hpp>
#include <rkpm/material/rankine_fracture.hpp>
#include <rkpm/solver/make_solver.hpp>

namespace fs = std::filesystem;
using namespace rkpm;

// ---------------------------------------------------------------------------------------
// The method, as types: the cubic spline with the linear correction on the 2 x 2 Gauss rule,
// plane strain, the brittle material, no tools.
// ---------------------------------------------------------------------------------------
using method = config<kernel::cubic_spline, correction::linear, quadrature::q4, geometry::plane_strain,
                      material::rankine_fracture, contact::none>;

// Maraging steel 18Ni(300) as the experiment's; G_c from its K_Ic = 68 MPa m^1/2 in plane strain,
// G_c = K_Ic^2 (1 - nu^2) / E. The strength is the model's choice (the experiment gives none);
// the crack's direction follows the stress field, not the strength.
constexpr double E = 190e9, nu = 0.3, rho = 8000.0, strength = 1.0e9;
const double G_c = 68e6 * 68e6 * (1.0 - nu * nu) / E;
constexpr double side = 0.1, notch_y = 0.025, notch_length = 0.05, impact_speed = 16.5;

int main(int argc, char** argv) {
  try {
    const fs::path dir = argc > 1 ? fs::path(argv[1]) : fs::path("results/14_fracture");
    const double cell = (argc > 2 ? std::strtod(argv[2], nullptr) : 2.0) * 1e-3;
    const double end_time = argc > 3 ? std::strtod(argv[3], nullptr) : 80e-6;
    fs::create_directories(dir);

    // ---------------------------------------------------------------------------------
    // The plate: particles at the nodes of a grid of square cells (the cells are what cracks
    // cut), the support twice the spacing, the band width the window's (107).
    // ---------------------------------------------------------------------------------
    const int n = static_cast<int>(std::lround(side / cell)) + 1;
    const vec2 lo(0.0, 0.0), hi(side, side);
    const double support = 2.0 * cell;
    problem_for<method> p{
        .particles = make_grid_particles<2>(lo, hi, Eigen::Vector2i(n, n), 2.0),
        .mesh = make_grid_mesh(lo, hi, Eigen::Vector2i(n, n)),
        .material = material::rankine_fracture({E, nu, rho}, strength, G_c,
                                               material::rankine_fracture::band_width_of_support<kernel::cubic_spline>(support)),
        .contact = {}};
    // The edge below the notch pushed at the projectile's speed (reached in 1 us); the line
    // between the notches, y = 0, a line of symmetry.
    for (index_t I = 0; I < p.particles.size(); ++I) {
      const vec2 X = p.particles.position[I];
      if (X[0] < 1e-9 && X[1] < notch_y - 1e-9)
        p.constraints.push_back({I, 0, [](double t) { return impact_speed * std::min(1.0, t / 1e-6); }});
      if (X[1] < 1e-9) p.constraints.push_back({I, 1, [](double) { return 0.0; }});
    }
    run_options options;
    options.end_time = end_time;
    auto solver = make_solver<method>(std::move(p), options);

    // The notch: the cells of the row just below y = 25 mm, from the edge to its tip, cut as a
    // crack cuts them (normal +y), before the first step.
    const index_t row = static_cast<index_t>(std::lround(notch_y / cell)) - 1, cells_per_row = n - 1;
    std::vector<std::pair<index_t, vec2>> notch;
    for (index_t i = 0; (i + 0.5) * cell < notch_length; ++i) notch.emplace_back(row * cells_per_row + i, vec2(0, 1));
    solver.cut_cells(notch);
    const index_t notch_cuts = static_cast<index_t>(solver.cracks().size());
    const vec2 tip(static_cast<double>(notch.size()) * cell, (static_cast<double>(row) + 0.5) * cell);
    fmt::print("Kalthoff-Winkler plate: {} particles, cells of {} mm, G_c = {:.4g} J/m^2, band {:.3g} mm\n",
               solver.model().particle_count(), cell * 1e3, G_c, solver.material().band_width() * 1e3);

    // ---------------------------------------------------------------------------------
    // The run, with a progress line every tenth of it.
    // ---------------------------------------------------------------------------------
    const auto start = std::chrono::steady_clock::now();
    io::csv_writer history(dir / "history.csv", {"time_us", "cells_cut", "pieces", "fracture_J_m", "kinetic_J_m"});
    double next_report = 0.0;
    solver.run(
        [&](const auto& s) {
          history.row({s.time() * 1e6, static_cast<double>(s.cracks().size() - notch_cuts),
                       static_cast<double>(s.fragments().pieces), s.energy().plastic, s.energy().kinetic});
          if (s.time() >= next_report) {
            fmt::print("  {:>5.1f} us  step {:>6}  cells cut {:>4}  fracture energy {:.4g} J/m\n", s.time() * 1e6,
                       s.steps(), s.cracks().size() - notch_cuts, s.energy().plastic);
            std::fflush(stdout);
            next_report += 0.1 * end_time;
          }
        },
        20);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    // ---------------------------------------------------------------------------------
    // The crack path (each cut on the cells at their final corners), the particles, the angle.
    // ---------------------------------------------------------------------------------
    const std::vector<vec2> x = solver.particle_positions();
    background_mesh now{x, solver.model().mesh.cell};
    io::csv_writer path(dir / "crack_path.csv", {"x_mm", "y_mm", "notch"});
    io::csv_writer centres(dir / "crack_cells.csv", {"x_mm", "y_mm"});
    double sx = 0.0, sy = 0.0;
    int counted = 0;
    for (const cell_crack& k : solver.cracks()) {
      const auto [a, b] = crack_chord(now, k, 0.0);
      const bool in_notch = std::any_of(notch.begin(), notch.end(), [&](const auto& c) { return c.first == k.cell; });
      path.row({a[0] * 1e3, a[1] * 1e3, in_notch ? 1.0 : 0.0});
      path.row({b[0] * 1e3, b[1] * 1e3, in_notch ? 1.0 : 0.0});
      path.row({NAN, NAN, NAN});
      if (in_notch) continue;
      vec2 c = vec2::Zero();  // the cell's centre in the reference configuration
      for (const stored_index v : solver.model().mesh.cell[k.cell]) c += 0.25 * solver.initial_positions()[v];
      centres.row({c[0] * 1e3, c[1] * 1e3});
      if ((c - tip).norm() < 0.03 && c[1] > tip[1]) {
        sx += c[0] - tip[0];
        sy += c[1] - tip[1];
        ++counted;
      }
    }
    io::csv_writer particles(dir / "particles.csv", {"x_mm", "y_mm"});
    for (const vec2& xi : x) particles.row({xi[0] * 1e3, xi[1] * 1e3});

    const double angle = counted > 0 ? std::atan2(sy, sx) * 180.0 / std::numbers::pi : NAN;
    fmt::print("\n{} steps in {:.1f} s; {} cells cut past the notch, {} pieces\n", solver.steps(), seconds,
               solver.cracks().size() - notch_cuts, solver.fragments().pieces);
    fmt::print("fracture energy {:.4g} J/m, kinetic {:.4g} J/m, energy balance {:.2e}\n", solver.energy().plastic,
               solver.energy().kinetic, solver.energy().balance_error());
    if (counted > 0)
      fmt::print("crack angle from the notch tip: {:.1f} degrees to the notch (measured: about 70, Kalthoff and "
                 "Winkler 1988)\n",
                 angle);
    else
      fmt::print("no crack has left the notch tip yet (a longer end time)\n");

    if (io::gnuplot_available()) {
      const auto file = [&](const std::string& f) { return "'" + (dir / f).string() + "'"; };
      io::gnuplot_png(dir / "crack_path.png",
                      "set datafile separator ','\nset size ratio -1\nset xlabel 'x (mm)'\nset ylabel 'y (mm)'\n"
                      "set title 'Kalthoff-Winkler plate (upper half): the crack at the end'\n"
                      "plot " + file("particles.csv") + " u 1:2 w p pt 7 ps 0.2 lc rgb '#999999' t 'particles', " +
                          file("crack_path.csv") + " u 1:($3 > 0 ? $2 : 1/0) w l lw 3 lc rgb '#1f77b4' t 'notch', " +
                          file("crack_path.csv") + " u 1:($3 > 0 ? 1/0 : $2) w l lw 3 lc rgb '#d62728' t 'crack'\n",
                      {.width = 800, .height = 800});
      fmt::print("figure: crack_path.png in {}\n", dir.string());
    }
    // The tutorial's own checks: the ledger balances, and a crack has left the notch.
    if (!(solver.energy().balance_error() < 0.02) || counted == 0) {
      std::fprintf(stderr, "tutorial_14_fracture: energy balance %.3g or no crack past the notch\n",
                   solver.energy().balance_error());
      return 1;
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tutorial_14_fracture: %s\n", e.what());
    return 1;
  }
}
