// Tutorial 15: hot forging at press speed. A steel billet at 1100 C between two dies at 200 C,
// mass-scaled, with conduction, die chill, plastic and frictional heat.
//
// ---------------------------------------------------------------------------------------
// Introduction
// ---------------------------------------------------------------------------------------
// A 40 mm x 40 mm AISI 1045 billet at 1373 K is squeezed in plane strain between two flat dies
// at 473 K that move toward each other at 20 mm/s each (a hydraulic press), to 50% reduction of
// its height: 0.5 s. Three things are new since tutorial 05:
//   - mass scaling (docs/method.md section 5.10): at press speed the unscaled run would take
//     millions of wave-speed steps; every mass is multiplied by the factor (84) that makes the
//     step a target step, and the kinetic to internal energy ratio (85) shows that the added
//     inertia stays negligible;
//   - heat (sections 5.9 and 5.11): thermal::heat_coupling<Solver> steps the solver and conducts
//     the heat of plastic work (98) and friction (99) through the billet, exchanges heat with the
//     cold dies through an interface conductance (100) and loses heat to the air by convection on
//     the free sides (91); the Johnson-Cook flow stress reads the field (101);
//   - the heat ledger (93): every joule stored in the billet is accounted for by a source or a
//     boundary.
// The program records the die force and the mean, smallest and largest temperature over time,
// and draws the force and the final temperature field.
//
// Usage: tutorial_15_hot_forging [output directory] [end time in s] [particles per side]
//        (defaults: results/15_hot_forging, 0.5 s (50%), 21)

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

#include <fmt/format.h>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/io/csv.hpp>
#include <rkpm/io/gnuplot.hpp>
#include <rkpm/material/johnson_cook.hpp>
#include <rkpm/solver/make_solver.hpp>
#include <rkpm/thermal/heat_coupling.hpp>

#include "cases/contact_setup.hpp"

namespace fs = std::filesystem;
using namespace rkpm;

// ---------------------------------------------------------------------------------------
// The method: one configuration
// ---------------------------------------------------------------------------------------
// The paper's contact with Coulomb friction as in tutorial 05; Q4, which keeps the mirror symmetry
// of the problem about x = 0 (Q2's two points on one diagonal of each cell tilt the flow).
using contact_t = contact::particle_to_segment<contact::enforcement::paper, contact::friction::coulomb>;
using method = config<kernel::cubic_spline, correction::linear, quadrature::q4, geometry::plane_strain,
                      material::johnson_cook, contact_t>;

// ---------------------------------------------------------------------------------------
// The data
// ---------------------------------------------------------------------------------------
// AISI 1045, Johnson-Cook constants of Jaspers & Dautzenberg, J. Mater. Process. Technol. 122
// (2002) 322-330: A = 553.1 MPa, B = 600.8 MPa, n = 0.234, C = 0.0134, m = 1, T_melt = 1733 K,
// T_room = 300 K, reference rate 1/s. At 1373 K, T* = 0.749 and the flow stress is a quarter of
// the room-temperature one (139 MPa at eps_p = 0).
const material::hardening::johnson_cook aisi_1045{553.1e6, 600.8e6, 0.234, 0.0134, 1.0, 1.0, 300.0, 1733.0};
// Elastic constants: the room-temperature E = 210 GPa (hot steel is softer, about 120 GPa at
// 1100 C, but the elastic strains are tiny beside 50% and the step is set by mass scaling).
const material::elastic_constants steel{210e9, 0.3, 7850.0};
constexpr double c_p = 600.0;           // J/(kg K)
constexpr double conductivity = 30.0;   // W/(m K), carbon steel near 1100 C
constexpr double taylor_quinney = 0.9;  // beta
constexpr double T_billet = 1373.0, T_die = 473.0, T_air = 300.0;  // K
constexpr double h_contact = 15e3;      // W/(m^2 K): die-billet interface conductance, of order 10-20 kW/(m^2 K)
constexpr double h_air = 30.0;          // W/(m^2 K): natural convection and radiation folded into one film
constexpr double friction = 0.3;        // Coulomb
constexpr double friction_to_billet = 0.5;
constexpr double die_speed = 20e-3;     // m/s, each die
constexpr double width = 40e-3, height = 40e-3;
constexpr double target_step = 5e-5;    // s: mass scaling's target step (84)

int main(int argc, char** argv) {
  try {
    const fs::path dir = argc > 1 ? fs::path(argv[1]) : fs::path("results/15_hot_forging");
    fs::create_directories(dir);
    const double end_time = argc > 2 ? std::strtod(argv[2], nullptr) : 0.5;  // 0.5 s: 20 mm, 50%
    const int n = argc > 3 ? std::atoi(argv[3]) : 21;
    if (!(end_time > 0.0 && end_time < 0.9 * height / (2 * die_speed)) || n < 5)
      throw std::runtime_error("give an end time in (0, 0.9 s) and at least 5 particles per side");

    // -------------------------------------------------------------------------------------
    // The problem: billet, dies, material
    // -------------------------------------------------------------------------------------
    const vec2 lo(-0.5 * width, 0.0), hi(0.5 * width, height);
    const double w = 1.5 * width;  // the dies' half width: wide enough for the spread billet
    std::vector<contact::rigid_tool> dies{
        contact::rigid_tool("bottom_die", {vec2(-w, 0.0), vec2(w, 0.0)}, contact::side::left,
                            contact::tool_motion::constant_velocity(vec2(0.0, die_speed))),
        contact::rigid_tool("top_die", {vec2(w, height), vec2(-w, height)}, contact::side::left,
                            contact::tool_motion::constant_velocity(vec2(0.0, -die_speed)))};
    problem<material::johnson_cook, contact_t> pr{
        .particles = make_grid_particles<2>(lo, hi, Eigen::Vector2i(n, n), 2.0),
        .mesh = make_grid_mesh(lo, hi, Eigen::Vector2i(n, n)),
        .material = material::johnson_cook(steel, aisi_1045,
                                           material::johnson_cook_heating{c_p, taylor_quinney, T_billet}),
        .contact = cases::make_contact<contact_t>(std::move(dies), friction, 1e12),
        // The billet starts with the dies' velocity field (no impact): v_y from +v at the bottom
        // to -v at the top.
        .initial_velocity = [](const vec2& X) { return vec2(0.0, die_speed * (1.0 - 2.0 * X[1] / height)); },
    };

    // Mass scaling (84): the factor that makes the step target_step; the ratio (85) watched.
    run_options options;
    options.end_time = end_time;
    options.mass_scaling.target_time_step = target_step;
    auto solver = make_solver<method>(std::move(pr), options);
    const auto& m = solver.model();
    const double mass = std::accumulate(solver.physical_mass().begin(), solver.physical_mass().end(), 0.0);
    const double k = solver.mass_scaling_factor();
    const double unscaled_step = solver.time_step() / std::sqrt(k);
    fmt::print("{} particles, {} points; mass scaling factor {:.4g} (added mass {:.4g} kg/m on {:.3g} kg/m), "
               "step {:.3g} us (unscaled {:.3g} us)\n",
               m.particle_count(), m.point_count(), k, (k - 1) * mass, mass, solver.time_step() * 1e6,
               unscaled_step * 1e6);

    // -------------------------------------------------------------------------------------
    // Heat: conduction, convection on the free sides, the dies
    // -------------------------------------------------------------------------------------
    // The free sides x = +-W/2 (without the corners, which start on the dies) as runs of the
    // billet's surface chain, with convection to air (91). The lengths follow the positions.
    const auto& X = m.particles.position;
    std::vector<index_t> sides;
    for (index_t I = 0; I < m.particle_count(); ++I)
      if (std::abs(std::abs(X[I][0]) - 0.5 * width) < 1e-12 && X[I][1] > 1e-12 && X[I][1] < height - 1e-12)
        sides.push_back(I);
    std::vector<thermal::thermal_boundary> boundaries;
    for (const auto& run : thermal::chain_runs(m.bodies.surface("hot forging")[0], sides))
      boundaries.push_back(thermal::thermal_boundary::on_chain(thermal::boundary_kind::convection, run.particle, X,
                                                               run.closed, T_air, h_air));
    // Attached, the coupling is stepped by every step of the solver (and saved in its checkpoints).
    const auto heat = std::make_shared<thermal::heat_coupling<decltype(solver)>>(
        solver, std::vector<thermal::thermal_properties>{{.conductivity = conductivity, .specific_heat = c_p}},
        std::vector{taylor_quinney}, T_billet, boundaries,
        thermal::tool_heat{.temperature = {T_die, T_die}, .conductance = h_contact,
                           .friction_to_body = friction_to_billet});
    solver.attach(heat);

    // Particles to watch: the middle of the bottom face (on the die from the start) and the core.
    auto nearest = [&](vec2 p) {
      index_t best = 0;
      for (index_t I = 1; I < m.particle_count(); ++I)
        if ((X[I] - p).norm() < (X[best] - p).norm()) best = I;
      return best;
    };
    const index_t face = nearest(vec2(0.0, 0.0)), core = nearest(vec2(0.0, 0.5 * height));

    // -------------------------------------------------------------------------------------
    // The run: each step also steps the heat; the die force averaged over windows
    // -------------------------------------------------------------------------------------
    io::csv_writer history(dir / "history.csv", {"time_s", "reduction_percent", "force_MN_per_m", "T_mean_K",
                                                 "T_min_K", "T_max_K", "T_face_K", "T_core_K",
                                                 "kinetic_to_internal"});
    auto mean_T = [&] { return heat->mean_temperature(); };
    double window_impulse = 0.0, window_start = 0.0, next_report = 0.0, peak_force = 0.0, last_force = 0.0;
    auto record = [&] {
      const double t = solver.time();
      // The top die's impulse since t = 0 over a window of 1% of the run, divided by its length:
      // the mean force of the window (one step's reaction is noisy, as in tutorial 05).
      const double impulse = solver.tool_impulses()[1].y();
      const double force = (impulse - window_impulse) / (t - window_start);
      window_impulse = impulse;
      window_start = t;
      peak_force = std::max(peak_force, force);
      last_force = force;
      const auto T = heat->particle_temperatures();
      const auto [lo_T, hi_T] = std::minmax_element(T.begin(), T.end());
      const auto& e = solver.energy();
      history.row({t, 100.0 * 2 * die_speed * t / height, force * 1e-6, mean_T(), *lo_T, *hi_T, T[face], T[core],
                   e.internal > 0 ? e.kinetic / e.internal : 0.0});
      if (t >= next_report) {
        fmt::print("  {:>5.3f} s  step {:>6}  reduction {:>4.1f}%  force {:>6.2f} MN/m  T mean {:6.1f} K  "
                   "face {:6.1f} K  core {:6.1f} K\n",
                   t, solver.steps(), 100.0 * 2 * die_speed * t / height, force * 1e-6, mean_T(), T[face], T[core]);
        std::fflush(stdout);
        next_report += 0.1 * end_time;
      }
    };
    while (solver.before_end()) {
      solver.step_to_end();
      if (solver.time() - window_start >= 0.01 * end_time) record();
    }
    if (solver.time() > window_start) record();

    // -------------------------------------------------------------------------------------
    // Results and checks
    // -------------------------------------------------------------------------------------
    const auto T = heat->particle_temperatures();
    const auto& ledger = heat->conduction().ledger();
    const auto& coupled = heat->ledger();
    const auto& qs = solver.quasi_static();
    fmt::print("\nafter {} steps, {:.3f} s ({:.0f}% reduction):\n", solver.steps(), solver.time(),
               100.0 * 2 * die_speed * solver.time() / height);
    fmt::print("  mass scaling     factor {:.4g}, added mass {:.4g} kg/m, largest kinetic/internal {:.4f} at {:.3f} s\n",
               k, (k - 1) * mass, qs.worst_ratio, qs.worst_time);
    // Without scaling every step is 1/sqrt(k) of the scaled one (the step shrinks as the particles
    // deform, in both runs alike): about sqrt(k) times the steps; end time / first unscaled step
    // is the lower bound.
    fmt::print("  steps            {} scaled; without scaling about {:.3g} (sqrt(k) x steps), at least {:.3g} "
               "(end time / first unscaled step)\n",
               solver.steps(), std::sqrt(k) * solver.steps(), end_time / unscaled_step);
    fmt::print("  die force        {:.2f} MN/m at the end, {:.2f} MN/m largest\n", last_force * 1e-6, peak_force * 1e-6);
    fmt::print("  temperature      mean {:.1f} K, min {:.1f} K, max {:.1f} K\n", mean_T(),
               *std::min_element(T.begin(), T.end()), *std::max_element(T.begin(), T.end()));
    const auto hottest = static_cast<std::size_t>(std::max_element(T.begin(), T.end()) - T.begin());
    fmt::print("  hottest particle {:.1f} K, from ({:.1f}, {:.1f}) mm (reference) now at ({:.1f}, {:.1f}) mm\n", T[hottest],
               X[hottest][0] * 1e3, X[hottest][1] * 1e3, solver.particle_positions()[hottest][0] * 1e3,
               solver.particle_positions()[hottest][1] * 1e3);
    fmt::print("  die chill        face centre {:.1f} K ({:+.1f} K), core {:.1f} K ({:+.1f} K)\n", T[face],
               T[face] - T_billet, T[core], T[core] - T_billet);
    // The face centre against a semi-infinite body at T_billet whose surface meets a medium at
    // T_die through the conductance h from t = 0 (Carslaw & Jaeger, Conduction of Heat in Solids,
    // 2nd ed. 1959, section 2.7): (T_s - T_die) / (T_billet - T_die) = exp(b^2) erfc(b),
    // b = h sqrt(alpha t) / k. The face centre touches the die from the start and barely slides.
    const double b = h_contact * std::sqrt(conductivity / (steel.density * c_p) * solver.time()) / conductivity;
    const double T_semi = T_die + (T_billet - T_die) * std::exp(b * b) * std::erfc(b);
    fmt::print("  semi-infinite    surface {:.1f} K ({:+.1f} K) for a half-space on an isothermal die (b = {:.3f})\n",
               T_semi, T_semi - T_billet, b);
    fmt::print("  heat ledger, kJ/m: stored {:.4f} = plastic {:.4f} + friction {:.4f} + dies {:.4f} + air {:.4f}; "
               "imbalance {:.1e}\n",
               ledger.stored * 1e-3, coupled.plastic * 1e-3, coupled.friction_to_body * 1e-3,
               coupled.from_tools * 1e-3, ledger.convection * 1e-3, ledger.relative_imbalance());
    fmt::print("  plastic work {:.4f} kJ/m, friction heat {:.4f} kJ/m (half to the billet), {} exchanges, "
               "energy balance error {:.1e}\n",
               solver.energy().plastic * 1e-3, coupled.friction * 1e-3, heat->exchanges(),
               solver.energy().balance_error());

    // The final field at the particles, for the figure.
    const auto x = solver.particle_positions();
    {
      io::csv_writer field(dir / "temperature_final.csv", {"x_mm", "y_mm", "T_K", "X_mm", "Y_mm"});
      for (std::size_t I = 0; I < x.size(); ++I) field.row({x[I][0] * 1e3, x[I][1] * 1e3, T[I], X[I][0] * 1e3, X[I][1] * 1e3});
    }

    // Checks that can fail: the ledger (93) closes, the sources are the coupling's heats, the
    // face on the die ends colder than the core, the run stayed quasi-static (85).
    int failures = 0;
    auto check = [&](bool ok, const std::string& what) {
      if (!ok) {
        std::fprintf(stderr, "tutorial_15_hot_forging: check failed: %s\n", what.c_str());
        ++failures;
      }
    };
    check(ledger.relative_imbalance() < 1e-9, fmt::format("heat ledger imbalance {:.2e} >= 1e-9", ledger.relative_imbalance()));
    const double sum = coupled.plastic + coupled.friction_to_body + coupled.from_tools;
    check(std::abs(ledger.sources - sum) <= 1e-9 * std::max(std::abs(ledger.sources), std::abs(sum)),
          fmt::format("sources {:.6e} J/m != plastic + friction + dies {:.6e} J/m", ledger.sources, sum));
    check(coupled.plastic > 0.0 && coupled.from_tools < 0.0, "the billet must deform plastically and lose heat to the dies");
    check(T[face] < T[core], fmt::format("the face on the die ({:.1f} K) must end colder than the core ({:.1f} K)",
                                         T[face], T[core]));
    check(!qs.left() && qs.worst_ratio < 0.05,
          fmt::format("kinetic/internal reached {:.4f} (bound 0.05): the scaled run is not quasi-static", qs.worst_ratio));
    if (failures > 0) return 1;

    if (!io::gnuplot_available()) {
      fmt::print("gnuplot not found: the CSV files are in {}\n", dir.string());
      return 0;
    }
    const std::string common = "set datafile separator ','\nset key autotitle columnhead\nset grid\n";
    const auto f = [&](const std::string& name) { return (dir / name).string(); };
    io::gnuplot_png(dir / "die_force.png",
                    common + "set xlabel 'reduction (%)'\nset ylabel 'top die force (MN per m of depth)'\n"
                             "plot '" + f("history.csv") + "' u 2:3 w l lw 2 notitle\n");
    io::gnuplot_png(dir / "temperatures.png",
                    common + "set xlabel 'time (s)'\nset ylabel 'T (K)'\nset key bottom left\nplot '" + f("history.csv") +
                        "' u 1:4 w l lw 2 t 'mean', '' u 1:5 w l lw 2 t 'min', '' u 1:6 w l lw 2 t 'max', "
                        "'' u 1:7 w l lw 2 t 'face centre', '' u 1:8 w l lw 2 t 'core'\n");
    io::gnuplot_png(dir / "temperature.png",
                    common + "set size ratio -1\nset xlabel 'x (mm)'\nset ylabel 'y (mm)'\nset cblabel 'T (K)'\n"
                             "set palette rgb 33,13,10\nplot '" + f("temperature_final.csv") +
                        "' u 1:2:3 w p pt 7 ps 1.2 palette notitle\n",
                    {.width = 1000, .height = 500});
    fmt::print("figures: die_force.png, temperatures.png, temperature.png in {}\n", dir.string());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tutorial_15_hot_forging: %s\n", e.what());
    return 1;
  }
}
