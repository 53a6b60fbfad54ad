// Tutorial 10: rate and temperature. The Johnson-Cook material (docs/method.md section 4.5) in a
// Taylor impact and in a bar pulled apart.
//
// ---------------------------------------------------------------------------------------
// Introduction
// ---------------------------------------------------------------------------------------
// Part 1. An OFHC copper cylinder (L0 = 25.4 mm, D0 = 7.62 mm) hits a rigid wall at 190 m/s
// (cases/taylor_bar_johnson_cook.json) with the Johnson-Cook constants of Johnson & Cook
// (1983). Four runs of one solver type (material::johnson_cook) switch the two effects on
// and off:
//   static   C = 0, beta = 0: J2 plasticity with the static curve A + B eps_p^n, isothermal;
//   rate     C = 0.025, beta = 0: the strain-rate term alone;
//   heat     C = 0, beta = 0.9: adiabatic heating alone;
//   both     the full model.
// The final lengths say how much each effect changes the bar; the temperature field of the
// full model is drawn.
// Part 2. A round copper bar (axisymmetric) held at one end and pulled at 100 m/s at the other
// (a nominal strain rate of 6250/s) with the Johnson-Cook damage constants of OFHC copper
// (Johnson & Cook 1985: D1..D5 = 0.54, 4.89, -3.03, 0.014, 1.12, eps_f(1/3) ~ 2.3 at room
// temperature and the reference rate): the damage grows where the bar necks, the points there
// fail (no deviatoric stress, no tension) and the bar comes apart; the failed fraction is
// followed over time.
//
// Usage: tutorial_10_rate_and_temperature [output directory] [end time of part 1 in s]
//        (defaults: results/10_rate_and_temperature and 80e-6 s)

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/io/csv.hpp>
#include <rkpm/io/gnuplot.hpp>
#include <rkpm/io/solver_output.hpp>
#include <rkpm/material/johnson_cook.hpp>
#include <rkpm/solver/make_solver.hpp>

#include "cases/taylor_bar.hpp"

namespace fs = std::filesystem;
using namespace rkpm;

using contact_t = contact::particle_to_segment<contact::enforcement::paper, contact::friction::coulomb>;
using method = config<kernel::cubic_spline, correction::linear, quadrature::q2, geometry::axisymmetric,
                      material::johnson_cook, contact_t>;

// OFHC copper (Johnson & Cook 1983, Table 1; damage: Johnson & Cook 1985).
const material::elastic_constants copper{124e9, 0.34, 8960.0};
material::hardening::johnson_cook copper_flow(double C) { return {90e6, 292e6, 0.31, C, 1.0, 1.09, 294.0, 1356.0}; }

struct outcome {
  std::string label;
  // The length is the largest less the smallest z (what the recovered cylinders are measured by);
  // the height, the largest z, exceeds it once the bar lifts off the wall.
  double height_mm = 0, length_mm = 0, radius_mm = 0, eps_p = 0, max_T = 0, balance = 0, seconds = 0;
};

// ---------------------------------------------------------------------------------------
// Part 1: the Taylor bar, one run
// ---------------------------------------------------------------------------------------
outcome taylor(const std::string& label, double C, double beta, double end_time, const fs::path& dir) {
  cases::taylor_bar::parameters p;  // the typed case's builder, with this test's geometry and speed
  p.velocity_m_s = 190.0;
  p.radius_m = 3.81e-3;
  p.height_m = 25.4e-3;
  p.radial_particles = 13;
  p.axial_particles = 41;
  p.end_time_s = end_time;
  auto bar = cases::taylor_bar::build<contact_t>(p, 1);
  // The same particles, cells, wall and velocity with the Johnson-Cook copper.
  problem<material::johnson_cook, contact_t> pr{
      .particles = bar.particles,
      .mesh = bar.mesh,
      .material = material::johnson_cook(copper, copper_flow(C), material::johnson_cook_heating{383.0, beta}),
      .contact = bar.contact,
      .initial_velocity = bar.initial_velocity,
  };
  run_options o;
  o.end_time = end_time;
  const auto start = std::chrono::steady_clock::now();
  auto s = make_solver<method>(std::move(pr), o);
  s.run([](const auto&) {}, 1000);
  outcome out{label};
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto x = s.particle_positions();
  const auto& X = s.model().particles.position;
  double lowest_mm = x[0][1] * 1e3;
  for (std::size_t I = 0; I < x.size(); ++I) {
    out.height_mm = std::max(out.height_mm, x[I][1] * 1e3);
    lowest_mm = std::min(lowest_mm, x[I][1] * 1e3);
    if (X[I][1] == 0.0) out.radius_mm = std::max(out.radius_mm, x[I][0] * 1e3);
  }
  out.length_mm = out.height_mm - lowest_mm;
  for (const auto& st : s.point_states()) out.eps_p = std::max(out.eps_p, st.equivalent_plastic_strain);
  out.max_T = io::largest_state_field(s, "temperature_K", [](std::size_t) { return true; });
  out.balance = s.energy().balance_error();
  // The final shape and the temperature at the particles (projected as in the snapshots).
  const auto fields = io::snapshot_fields(s);
  std::vector<double> T(x.size(), 294.0);
  for (const auto& f : fields.arrays())
    if (f.name == "temperature_K") T = f.values;
  io::csv_writer shape(dir / fmt::format("shape_{}.csv", label), {"r0_mm", "z0_mm", "r_mm", "z_mm", "T_K"});
  for (std::size_t I = 0; I < x.size(); ++I) shape.row({X[I][0] * 1e3, X[I][1] * 1e3, x[I][0] * 1e3, x[I][1] * 1e3, T[I]});
  fmt::print("  {:<7} length {:6.2f} mm (height {:6.2f} mm)  radius {:5.2f} mm  max eps_p {:5.2f}  max T {:6.1f} K  "
             "({} steps, {:.1f} s)\n",
             label, out.length_mm, out.height_mm, out.radius_mm, out.eps_p, out.max_T, s.steps(), out.seconds);
  std::fflush(stdout);
  return out;
}

// ---------------------------------------------------------------------------------------
// Part 2: a round bar pulled apart, with damage
// ---------------------------------------------------------------------------------------
void tension(const fs::path& dir) {
  const double R = 2e-3, L = 16e-3, V = 100.0, end = 160e-6;
  const Eigen::Vector2i n(9, 33);
  const vec2 lo(0.0, 0.0), hi(R, L);
  // OFHC copper (Johnson & Cook 1985), sigma* positive in tension.
  const material::johnson_cook_damage damage{0.54, 4.89, -3.03, 0.014, 1.12};
  problem<material::johnson_cook, contact_t> pr{
      .particles = make_grid_particles<2>(lo, hi, n, 2.0),
      .mesh = make_grid_mesh(lo, hi, n),
      .material = material::johnson_cook(copper, copper_flow(0.025), material::johnson_cook_heating{383.0}, damage),
      .contact = cases::make_contact<contact_t>({}, 0.0, 1e11),  // no tool: the ends are held by constraints
      // The bar starts stretching uniformly (no wave from the ends): v_z = V z / L.
      .initial_velocity = [&](const vec2& X) { return vec2(0.0, V * X[1] / L); },
  };
  // Both ends pulled: z = 0 held, z = L moving at V (r free); the neck starts where the ends hold.
  for (index_t I = 0; I < static_cast<index_t>(pr.particles.position.size()); ++I) {
    const double z = pr.particles.position[I][1];
    if (z == 0.0) pr.constraints.push_back({I, 1, [](double) { return 0.0; }});
    if (z == L) pr.constraints.push_back({I, 1, [V](double) { return V; }});
  }
  run_options o;
  o.end_time = end;
  auto s = make_solver<method>(std::move(pr), o);
  io::csv_writer history(dir / "tension.csv", {"time_us", "elongation_mm", "failed_fraction", "max_damage", "max_T_K"});
  const auto every = [](std::size_t) { return true; };
  s.run(
      [&](const auto& s) {
        double top = 0.0;
        for (const vec2& p : s.particle_positions()) top = std::max(top, p[1]);
        history.row({s.time() * 1e6, (top - L) * 1e3, io::failed_fraction(s, every),
                     io::largest_state_field(s, "damage", every), io::largest_state_field(s, "temperature_K", every)});
      },
      20);
  const auto x = s.particle_positions();
  const auto fields = io::snapshot_fields(s);
  std::vector<double> D(x.size(), 0.0);
  for (const auto& f : fields.arrays())
    if (f.name == "damage") D = f.values;
  io::csv_writer shape(dir / "tension_shape.csv", {"r_mm", "z_mm", "damage"});
  for (std::size_t I = 0; I < x.size(); ++I) shape.row({x[I][0] * 1e3, x[I][1] * 1e3, D[I]});
  fmt::print("tension: {} steps, failed fraction {:.3f}, max damage {:.2f}, balance error {:.1e}\n", s.steps(),
             io::failed_fraction(s, every), io::largest_state_field(s, "damage", every), s.energy().balance_error());
}

void plot(const fs::path& dir) {
  if (!io::gnuplot_available()) {
    fmt::print("gnuplot not found: the CSV files are in {}\n", dir.string());
    return;
  }
  const std::string common = "set datafile separator ','\nset key autotitle columnhead\nset grid\n";
  const auto f = [&](const std::string& name) { return (dir / name).string(); };
  io::gnuplot_png(dir / "shapes.png",
                  common + "set size ratio -1\nset xlabel 'r (mm): static left, Johnson-Cook right'\nset ylabel 'z (mm)'\n"
                           "plot '" + f("shape_static.csv") + "' u (-$1):2 w p pt 7 ps 0.3 lc rgb '#bbbbbb' t 'initial', '" +
                      f("shape_static.csv") + "' u (-$3):4 w p pt 7 ps 0.4 lc rgb '#1f77b4' t 'static (C = 0, no heat)', '" +
                      f("shape_both.csv") + "' u 3:4 w p pt 7 ps 0.4 lc rgb '#d62728' t 'Johnson-Cook'\n",
                  {.width = 700, .height = 800});
  io::gnuplot_png(dir / "temperature.png",
                  common + "set size ratio -1\nset xlabel 'r (mm)'\nset ylabel 'z (mm)'\nset cblabel 'T (K)'\n"
                           "set palette rgb 33,13,10\nset cbrange [294:*]\nplot '" + f("shape_both.csv") +
                      "' u 3:4:5 w p pt 7 ps 0.8 palette t 'temperature'\n",
                  {.width = 600, .height = 800});
  io::gnuplot_png(dir / "tension.png",
                  common + "set xlabel 'time (us)'\nset ylabel 'max damage'\nset y2label 'failed fraction'\nset y2tics\n"
                           "set key left top\nplot '" + f("tension.csv") +
                      "' u 1:4 w l lw 2 t 'max damage', '' u 1:3 axes x1y2 w l lw 2 t 'failed fraction (right axis)'\n");
  io::gnuplot_png(dir / "tension_shape.png",
                  common + "set xlabel 'r (mm), stretched'\nset ylabel 'z (mm)'\nset cbrange [0:1]\nset cblabel 'damage'\n"
                           "set xrange [0:2.5]\nplot '" + f("tension_shape.csv") + "' u 1:2:3 w p pt 7 ps 0.8 palette notitle\n",
                  {.width = 450, .height = 900});
  fmt::print("figures: shapes.png, temperature.png, tension.png, tension_shape.png in {}\n", dir.string());
}

int main(int argc, char** argv) {
  try {
    const fs::path dir = argc > 1 ? fs::path(argv[1]) : fs::path("results/10_rate_and_temperature");
    fs::create_directories(dir);
    const double end = argc > 2 ? std::strtod(argv[2], nullptr) : 80e-6;
    fmt::print("Part 1: OFHC copper Taylor bar, 190 m/s, {:.0f} us\n", end * 1e6);
    const outcome base = taylor("static", 0.0, 0.0, end, dir);
    const outcome rate = taylor("rate", 0.025, 0.0, end, dir);
    const outcome heat = taylor("heat", 0.0, 0.9, end, dir);
    const outcome both = taylor("both", 0.025, 0.9, end, dir);
    fmt::print("\nfinal length against the static curve's {:.2f} mm: rate {:+.2f} mm, heating {:+.2f} mm, both {:+.2f} mm\n",
               base.length_mm, rate.length_mm - base.length_mm, heat.length_mm - base.length_mm,
               both.length_mm - base.length_mm);
    fmt::print("Part 2: a round copper bar pulled apart with Johnson-Cook damage\n");
    tension(dir);
    plot(dir);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tutorial_10_rate_and_temperature: %s\n", e.what());
    return 1;
  }
}
