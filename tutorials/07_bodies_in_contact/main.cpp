// Tutorial 07: bodies in contact, two rods head on against the Taylor bar.
//
// ---------------------------------------------------------------------------------------
// Introduction
// ---------------------------------------------------------------------------------------
// Until now the master of every contact was a rigid tool. The paper writes its algorithm for a
// slave body and a master body whose surface is a chain of master particles
// (docs/method.md section 6.9). Here both are deformable: two copper rods with the Taylor
// bar's data (cases/rod_on_rod.hpp) meet head on, each at 227 m/s. The upper rod's particles
// are the slaves; the lower rod's boundary, joined into segments between its particles at their
// physical positions, is the master surface.
//
// By symmetry the plane where two identical rods meet stays at z = 0 and carries no shear: it
// is a frictionless rigid wall, and each rod is the Taylor bar of tutorial 04. This program
// runs the Taylor bar (cases/taylor_bar.hpp) and the two rods with the same method and
// resolution and compares them; it runs the rods once more with two passes (each rod slave
// against the other in turn); and it prints one contact of the run as the solver saw it: the
// slave's row N_I(X_J), the master's row c_I (76) and the masses of (77)-(78).
//
// Units: SI inside (m, s, kg, N); lengths are printed in mm, times in us.
//
// Usage: tutorial_07_bodies_in_contact [output directory] [end time in s] [resolution K]
//        (defaults: results/07_bodies_in_contact, 80e-6 s and K = 1: 21 x 51 particles per rod)

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/io/csv.hpp>
#include <rkpm/io/gnuplot.hpp>
#include <rkpm/solver/make_solver.hpp>

#include "cases/rod_on_rod.hpp"
#include "cases/taylor_bar.hpp"

namespace fs = std::filesystem;
using namespace rkpm;
using rod_on_rod = cases::rod_on_rod;
using taylor_bar = cases::taylor_bar;

// ---------------------------------------------------------------------------------------
// The method, as types
// ---------------------------------------------------------------------------------------
// One contact policy serves both problems: particle_to_segment holds rigid tools (the Taylor
// bar's wall) and pairs of deformable bodies (the rods') alike. The paper's enforcement (P4)-(P7):
// against the wall f_n = m_J g / dt^2; between bodies the same with the pair's reduced mass (78).
using contact_t = contact::particle_to_segment<contact::enforcement::paper, contact::friction::coulomb>;

// Tutorial 04's method with the paper's two-point rule Q2; the same geometry and material serve
// both cases.
using method = config<kernel::cubic_spline, correction::linear, quadrature::q2, rod_on_rod::geometry_type,
                      rod_on_rod::material_type, contact_t>;
static_assert(std::is_same_v<rod_on_rod::geometry_type, taylor_bar::geometry_type> &&
              std::is_same_v<rod_on_rod::material_type, taylor_bar::material_type>);

// Every 20 steps one row of history.
constexpr int row_every = 20;

// A case's measure by its name (the names of its summary.json).
double measured(const std::vector<std::pair<std::string, double>>& m, const std::string& name) {
  for (const auto& [key, value] : m)
    if (key == name) return value;
  throw std::runtime_error("the case measures no '" + name + "'");
}

struct outcome {
  // [0] the lower rod, [1] the upper rod; the Taylor bar fills [0] only.
  double height_mm[2] = {0, 0}, radius_mm[2] = {0, 0};
  double momentum_error = 0.0;  // largest |P - P0| / sum m |v0| over every step
  double penetration_mm = 0.0;  // deepest penetration found in any step
  double plane_um = 0.0;        // mean z of the two impact faces at the end
  double axis_um[2] = {0, 0};   // z of each rod's particle that started at r = 0 on its impact face
  double min_dt_ns = 0.0;       // the smallest time step of the run
  double seconds = 0.0;
  long steps = 0;
  index_t particles = 0, points = 0;
};

// ---------------------------------------------------------------------------------------
// Part 1: the Taylor bar, the reference
// ---------------------------------------------------------------------------------------
// Tutorial 04's run with this program's method and resolution: the copper bar on a rigid
// frictionless wall at z = 0.
outcome run_taylor_bar(const rod_on_rod::parameters& rods, int resolution, const fs::path& dir) {
  taylor_bar::parameters p;  // the rods' data: the case defaults are the same numbers
  p.velocity_m_s = rods.velocity_m_s;
  p.radius_m = rods.radius_m;
  p.height_m = rods.upper_height_m;
  p.end_time_s = rods.end_time_s;
  p.radial_particles = rods.radial_particles;
  p.axial_particles = rods.axial_particles;
  run_options options;
  options.end_time = taylor_bar::end_time(p);

  const auto start = std::chrono::steady_clock::now();
  auto solver = make_solver<method>(taylor_bar::build<contact_t>(p, resolution), options);
  fmt::print("Taylor bar: {} particles, {} quadrature points, first time step {:.3g} ns\n",
             solver.model().particle_count(), solver.model().point_count(), solver.time_step() * 1e9);
  // Every 20 steps a row: the case's measures, the z of the face's centre (particle 0, at the
  // origin) and the mean wall force since the last row (the wall's impulse since t = 0,
  // tool_impulses(), less its reading at the last row, over the time between).
  io::csv_writer history(dir / "history_taylor_bar.csv", {"time_us", "radius_mm", "height_mm", "centre_um", "force_kN"});
  double row_impulse = 0.0, row_start = 0.0;
  solver.run([&](const auto& s) {
    if (s.steps() % row_every != 0 && s.time() < options.end_time * (1.0 - 1e-12)) return;
    const auto m = taylor_bar::measure(s, p, {});
    const double impulse = -s.tool_impulses()[0].y();  // the reaction is the force on the wall: the bar's is opposite
    const double force = s.time() > row_start ? (impulse - row_impulse) / (s.time() - row_start) : 0.0;
    row_impulse = impulse, row_start = s.time();
    history.row({s.time() * 1e6, measured(m, "radius_mm"), measured(m, "height_mm"), s.particle_positions()[0][1] * 1e6,
                 force * 1e-3});
  }, 1);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const auto x = solver.particle_positions();
  const auto& X = solver.model().particles.position;
  io::csv_writer shape(dir / "shape_taylor_bar.csv", {"r0_mm", "z0_mm", "r_mm", "z_mm"});
  for (std::size_t I = 0; I < x.size(); ++I) shape.row({X[I][0] * 1e3, X[I][1] * 1e3, x[I][0] * 1e3, x[I][1] * 1e3});

  const auto m = taylor_bar::measure(solver, p, {});
  outcome o;
  o.radius_mm[0] = measured(m, "radius_mm");
  o.height_mm[0] = measured(m, "height_mm");
  o.penetration_mm = solver.max_penetration() * 1e3;
  o.seconds = seconds;
  o.steps = static_cast<long>(solver.steps());
  o.min_dt_ns = solver.min_time_step() * 1e9;
  o.particles = solver.model().particle_count();
  o.points = solver.model().point_count();
  fmt::print("  {} steps ({:.2f} to {:.2f} ns), {:.1f} s: radius {:.3f} mm, height {:.3f} mm\n", o.steps, o.min_dt_ns,
             solver.max_time_step() * 1e9, seconds, o.radius_mm[0], o.height_mm[0]);
  return o;
}

// ---------------------------------------------------------------------------------------
// Part 2: one contact, as the solver saw it (docs/method.md (75)-(78))
// ---------------------------------------------------------------------------------------
// After a step, contact().bodies().active_pairs() lists the slave particles in contact: slave J,
// the master segment a-b it penetrated, the contact point's lambda, the gap and the force f_J
// on the slave. The force reaches the coefficients through two rows of shape functions
// evaluated at reference positions:
//   slave body:   f_I += N_I(X_J) f_J                                       (P7), (59)
//   master body:  f_I -= c_I f_J,  c_I = (1 - lambda) N_I(X_a) + lambda N_I(X_b)   (76)
// Both rows sum to one (the correction reproduces constants), so sum_I f_I = f_J - f_J = 0:
// the contact moves no total momentum. This prints both rows for the contact with the largest
// normal force, and the masses: the paper's form uses the pair's reduced mass (78), the
// effective-mass form the mass (77) that closes an isolated gap in one step.
template <class Solver>
bool show_contact(const Solver& s) {
  const auto pairs = s.contact().bodies().active_pairs();
  if (pairs.empty()) return false;  // a step without contact: the paper's form may leave none
  const auto& p = *std::max_element(pairs.begin(), pairs.end(), [](const auto& a, const auto& b) {
    return a.normal_force < b.normal_force;
  });
  const auto& rows = s.model().at_particles;
  const auto& X = s.model().particles.position;
  const auto body = [&](index_t I) { return s.body_of_particle(I); };
  const auto& m = s.mass();

  // The slave's row, and the master's row c_I gathered from the rows of a and b.
  std::map<index_t, double> slave_row, master_row;
  for (index_t e = rows.offset[p.slave]; e < rows.offset[p.slave + 1]; ++e) slave_row[rows.neighbor[e]] += rows.N[e];
  for (const auto& [vertex, weight] : {std::pair{p.a, 1.0 - p.lambda}, std::pair{p.b, p.lambda}})
    for (index_t e = rows.offset[vertex]; e < rows.offset[vertex + 1]; ++e)
      master_row[rows.neighbor[e]] += weight * rows.N[e];
  auto sum = [](const auto& row) {
    double total = 0.0;
    for (const auto& [I, w] : row) total += w;
    return total;
  };
  auto bodies_of = [&](const auto& row) {
    std::string b;
    for (const auto& [I, w] : row)
      if (b.find(std::to_string(body(I))) == std::string::npos) b += (b.empty() ? "" : ", ") + std::to_string(body(I));
    return b;
  };
  // RK shape functions do not interpolate: even the largest entry of a row is well below one,
  // so the force is spread over the coefficients around the point.
  double inv_slave = 0.0, inv_master = 0.0, largest_N = 0.0, largest_c = 0.0;
  for (const auto& [I, w] : slave_row) inv_slave += w * w / m[I], largest_N = std::max(largest_N, w);
  for (const auto& [I, c] : master_row) inv_master += c * c / m[I], largest_c = std::max(largest_c, c);
  const double m_c = (1.0 - p.lambda) * m[p.a] + p.lambda * m[p.b];
  const double m_s = m[p.slave] * m_c / (m[p.slave] + m_c);  // (78)
  const vec2 f = p.force();
  // Net force on all coefficients of both bodies: (sum N - sum c) f_J.
  const vec2 net = (sum(slave_row) - sum(master_row)) * f;

  fmt::print("\n  one contact at t = {:.2f} us (step {}), the largest normal force of the {} in contact:\n",
             s.time() * 1e6, s.steps(), pairs.size());
  fmt::print("    slave J = {} of body {} (X = ({:.3f}, {:.3f}) mm) on segment a = {}, b = {} of body {} "
             "(X_a = ({:.3f}, {:.3f}), X_b = ({:.3f}, {:.3f}) mm)\n",
             p.slave, body(p.slave), X[p.slave][0] * 1e3, X[p.slave][1] * 1e3, p.a, p.b, body(p.a),
             X[p.a][0] * 1e3, X[p.a][1] * 1e3, X[p.b][0] * 1e3, X[p.b][1] * 1e3);
  fmt::print("    (75): lambda = {:.3f}, gap = {:.3f} um, normal n = ({:.3f}, {:.3f}); f_J = ({:.1f}, {:.1f}) kN on the "
             "slave (the whole ring: masses carry 2 pi r)\n",
             p.lambda, p.gap * 1e6, p.normal[0], p.normal[1], f[0] * 1e-3, f[1] * 1e-3);
  fmt::print("    (59) slave row:  {:>2} coefficients of body {}, sum N_I(X_J) = 1 {:+.1e}, largest entry {:.3f}\n",
             slave_row.size(), bodies_of(slave_row), sum(slave_row) - 1.0, largest_N);
  fmt::print("    (76) master row: {:>2} coefficients of body {}, sum c_I      = 1 {:+.1e}, largest entry {:.3f}\n",
             master_row.size(), bodies_of(master_row), sum(master_row) - 1.0, largest_c);
  fmt::print("    net force on all coefficients (sum N - sum c) f_J = ({:.1e}, {:.1e}) N, {:.1e} of |f_J|\n", net[0],
             net[1], net.norm() / f.norm());
  fmt::print("    masses (mg): slave m_J = {:.3f}, contact point m_c = {:.3f}, (78) m_s = {:.3f}; "
             "(77) m_eff = {:.3f} (1 / sum N^2/m = {:.3f}, 1 / sum c^2/m = {:.3f})\n",
             m[p.slave] * 1e6, m_c * 1e6, m_s * 1e6, 1e6 / (inv_slave + inv_master), 1e6 / inv_slave,
             1e6 / inv_master);
  return true;
}

// ---------------------------------------------------------------------------------------
// Part 3: the two rods
// ---------------------------------------------------------------------------------------
// The case builds both rods into one problem: two grids of particles and cells, which the
// solver tells apart as two bodies (the connected parts of the cells, 0 the lower rod, 1 the
// upper), each with its own shape functions, and one contact pair {slave 1, master 0}; with
// two_pass also {slave 0, master 1}. The observer measures every step the total axial
// momentum (no wall, no body force: it must not change) and writes a row every 20 steps.
outcome run_rods(rod_on_rod::parameters p, int resolution, bool two_pass, const fs::path& dir) {
  p.two_pass = two_pass;
  const std::string label = two_pass ? "two_pass" : "one_pass";
  run_options options;
  options.end_time = rod_on_rod::end_time(p);

  const auto start = std::chrono::steady_clock::now();
  auto solver = make_solver<method>(rod_on_rod::build<contact_t>(p, resolution), options);
  const auto& pairs = solver.contact().body_pairs();
  fmt::print("\nrods, {}: {} particles in {} bodies, {} quadrature points, contact pairs", two_pass ? "two passes" : "one pass",
             solver.model().particle_count(), solver.bodies(), solver.model().point_count());
  for (const auto& pr : pairs) fmt::print(" (slave {}, master {})", pr.slave, pr.master);
  fmt::print(", first time step {:.3g} ns\n", solver.time_step() * 1e9);

  const auto body = [&](index_t I) { return solver.body_of_particle(I); };
  const auto& X = solver.model().particles.position;
  const auto& mass = solver.mass();
  const double h = p.lower_height_m / (cases::refined_count(p.axial_particles, resolution) - 1);  // axial spacing
  double P0 = 0.0, scale = 0.0;  // the initial momentum (lower rod up, upper rod down) and sum m |v0|
  for (std::size_t I = 0; I < X.size(); ++I) {
    P0 += mass[I] * (body(I) == 0 ? p.velocity_m_s : -p.velocity_m_s);
    scale += mass[I] * p.velocity_m_s;
  }

  io::csv_writer history(dir / fmt::format("history_{}.csv", label),
                         {"time_us", "lower_radius_mm", "upper_radius_mm", "lower_height_mm", "upper_height_mm",
                          "momentum_error", "plane_um", "contacts", "force_kN", "lower_axis_um", "upper_axis_um"});
  outcome o;
  double impulse = 0.0, last_t = 0.0, row_start = 0.0, next_report = 0.0;
  bool shown = two_pass;  // Part 2 once, in the one-pass run
  auto observe = [&](const auto& s) {
    // Every step: the momentum, and the axial force on the upper rod (its slaves' forces, and
    // the reactions where it is the master), summed into an impulse.
    double P = 0.0;
    for (std::size_t I = 0; I < X.size(); ++I) P += mass[I] * s.coefficient_velocities()[I][1];
    const double error = (P - P0) / scale;
    o.momentum_error = std::max(o.momentum_error, std::abs(error));
    double force = 0.0;
    for (const auto& c : s.contact().bodies().active_pairs())
      force += (body(c.slave) == 1 ? 1.0 : -1.0) * c.force()[1];
    impulse += force * (s.time() - last_t);
    last_t = s.time();
    if (!shown && s.time() >= 0.25 * options.end_time) shown = show_contact(s);
    const bool end = s.time() >= options.end_time * (1.0 - 1e-12);
    if (s.steps() % row_every != 0 && !end) return;

    // A row: radii and heights (the case's measure), the contact plane (mean z of both impact
    // faces), the number of slaves in contact and the mean force since the last row.
    const auto m = rod_on_rod::measure(s, p, {});
    const double radius[2] = {measured(m, "lower_final_radius_mm"), measured(m, "upper_final_radius_mm")};
    const double height[2] = {measured(m, "lower_final_height_mm"), measured(m, "upper_final_height_mm")};
    const auto x = s.particle_positions();
    double plane = 0.0, axis[2] = {0, 0};
    int face = 0;
    for (std::size_t I = 0; I < x.size(); ++I)
      if (std::abs(X[I][1]) <= 1e-9 * p.lower_height_m) {
        plane += x[I][1], ++face;
        if (X[I][0] == 0.0) axis[body(I)] = x[I][1];  // the centre of the face
      }
    plane /= face;
    const double mean_force = s.time() > row_start ? impulse / (s.time() - row_start) : 0.0;
    impulse = 0.0, row_start = s.time();
    history.row({s.time() * 1e6, radius[0], radius[1], height[0], height[1], error, plane * 1e6,
                 static_cast<double>(s.contact().bodies().active_pairs().size()), mean_force * 1e-3, axis[0] * 1e6,
                 axis[1] * 1e6});
    if (s.time() >= next_report || end) {
      fmt::print("  {:>5.1f} us  step {:>6}  radius {:.3f} / {:.3f} mm  height {:.3f} / {:.3f} mm (lower / upper)"
                 "  plane {:+.2f} um\n",
                 s.time() * 1e6, s.steps(), radius[0], radius[1], height[0], height[1], plane * 1e6);
      std::fflush(stdout);
      next_report += 0.1 * options.end_time;
    }
    o.plane_um = plane * 1e6, o.axis_um[0] = axis[0] * 1e6, o.axis_um[1] = axis[1] * 1e6;
  };
  solver.run(observe, 1);
  o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const auto x = solver.particle_positions();
  io::csv_writer shape(dir / fmt::format("shape_{}.csv", label), {"body", "r0_mm", "z0_mm", "r_mm", "z_mm"});
  for (std::size_t I = 0; I < x.size(); ++I)
    shape.row({static_cast<double>(body(I)), X[I][0] * 1e3, X[I][1] * 1e3, x[I][0] * 1e3, x[I][1] * 1e3});

  const auto m = rod_on_rod::measure(solver, p, {});
  o.height_mm[0] = measured(m, "lower_final_height_mm"), o.height_mm[1] = measured(m, "upper_final_height_mm");
  o.radius_mm[0] = measured(m, "lower_final_radius_mm"), o.radius_mm[1] = measured(m, "upper_final_radius_mm");
  o.penetration_mm = measured(m, "max_penetration_mm");
  o.steps = static_cast<long>(solver.steps());
  o.min_dt_ns = solver.min_time_step() * 1e9;
  o.particles = solver.model().particle_count();
  o.points = solver.model().point_count();
  fmt::print("  {} steps ({:.2f} to {:.2f} ns), {:.1f} s; largest momentum error {:.1e}, deepest penetration {:.2f} um "
             "({:.1f}% of the axial spacing)\n",
             o.steps, o.min_dt_ns, solver.max_time_step() * 1e9, o.seconds, o.momentum_error, o.penetration_mm * 1e3,
             100.0 * o.penetration_mm * 1e-3 / h);
  fmt::print("  centres of the impact faces (r = 0): lower rod z = {:+.1f} um, upper rod z = {:+.1f} um\n", o.axis_um[0],
             o.axis_um[1]);
  return o;
}

// ---------------------------------------------------------------------------------------
// Part 4: figures
// ---------------------------------------------------------------------------------------
void plot(const fs::path& dir) {
  if (!io::gnuplot_available()) {
    fmt::print("gnuplot not found: the CSV files are in {}\n", dir.string());
    return;
  }
  auto file = [&](const std::string& name) { return io::gnuplot_quote((dir / name).string()); };
  const std::string bar = file("history_taylor_bar.csv"), one = file("history_one_pass.csv"),
                    two = file("history_two_pass.csv");
  const std::string common = "set datafile separator ','\nset grid\n";

  // The final sections: the rods on the right (body 0 below z = 0, body 1 above), on the left
  // the Taylor bar and its mirror image in the wall, z -> -z, which the lower rod should match.
  const std::string sb = file("shape_taylor_bar.csv");
  auto sections = [&](const std::string& s1) {
    return "plot " + sb + " skip 1 u (-$1):2 w p pt 7 ps 0.3 lc rgb '#cccccc' t 'initial', " + sb +
        " skip 1 u (-$1):(-$2) w p pt 7 ps 0.3 lc rgb '#cccccc' notitle, " + s1 +
        " skip 1 u 2:3 w p pt 7 ps 0.3 lc rgb '#cccccc' notitle, " + sb +
        " skip 1 u (-$3):4 w p pt 7 ps 0.4 lc rgb 'black' t 'Taylor bar', " + sb +
        " skip 1 u (-$3):(-$4) w p pt 7 ps 0.4 lc rgb 'black' notitle, " + s1 +
        " skip 1 u ($1 == 0 ? $4 : 1/0):5 w p pt 7 ps 0.4 lc rgb '#1f77b4' t 'lower rod', " + s1 +
        " skip 1 u ($1 == 1 ? $4 : 1/0):5 w p pt 7 ps 0.4 lc rgb '#d62728' t 'upper rod'\n";
  };
  io::gnuplot_png(dir / "shape.png",
                  common + "set size ratio -1\nset key top left samplen 1\n"
                           "set xlabel 'r (mm): Taylor bar left, rods right'\nset ylabel 'z (mm)'\nset xrange [-9:9]\n"
                           "set yrange [-34:48]\n" + sections(file("shape_one_pass.csv")),
                  {.width = 700, .height = 1000});
  // The impact faces closer, one pass and two: the lips of the two rods against the Taylor bar's.
  for (const std::string run : {"one_pass", "two_pass"})
    io::gnuplot_png(dir / (run == "one_pass" ? "faces.png" : "faces_two_pass.png"),
                    common + "set size ratio -1\nset key bottom left box opaque\nset xlabel 'r (mm): Taylor bar left, "
                             "rods right (" + (run == "one_pass" ? "one pass" : "two passes") + ")'\n"
                             "set ylabel 'z (mm)'\nset xrange [-8:8]\nset yrange [-5:6]\n" +
                        sections(file("shape_" + run + ".csv")),
                    {.width = 900, .height = 700});

  io::gnuplot_png(dir / "history.png",
                  common + "set multiplot layout 2,1\nset xlabel 'time (us)'\nset key bottom right\n"
                           "set ylabel 'impact face radius (mm)'\nplot " + bar +
                      " skip 1 u 1:2 w l lw 4 lc rgb '#bbbbbb' t 'Taylor bar', " + one +
                      " skip 1 u 1:2 w l lw 2 lc rgb '#1f77b4' t 'lower rod', " + one +
                      " skip 1 u 1:3 w l lw 2 dt 2 lc rgb '#d62728' t 'upper rod'\n"
                      "set key top right\nset ylabel 'height (mm)'\nplot " + bar +
                      " skip 1 u 1:3 w l lw 4 lc rgb '#bbbbbb' t 'Taylor bar', " + one +
                      " skip 1 u 1:4 w l lw 2 lc rgb '#1f77b4' t 'lower rod', " + one +
                      " skip 1 u 1:5 w l lw 2 dt 2 lc rgb '#d62728' t 'upper rod'\nunset multiplot\n",
                  {.width = 800, .height = 900});

  io::gnuplot_png(dir / "momentum.png",
                  common + "set multiplot layout 2,1\nset xlabel 'time (us)'\n"
                           "set ylabel '(P - P_0) / sum m |v_0|  (1e-15)'\nset key top left\nplot " + one +
                      " skip 1 u 1:($6 * 1e15) w l lw 2 lc rgb '#1f77b4' t 'one pass', " + two +
                      " skip 1 u 1:($6 * 1e15) w l lw 2 dt 2 lc rgb '#d62728' t 'two passes'\n"
                      "set ylabel 'axial contact force (kN)'\nset key top right\nplot " + bar +
                      " skip 1 u 1:5 w l lw 4 lc rgb '#bbbbbb' t 'Taylor bar (wall)', " + one +
                      " skip 1 u 1:9 w l lw 2 lc rgb '#1f77b4' t 'one pass', " + two +
                      " skip 1 u 1:9 w l lw 2 dt 2 lc rgb '#d62728' t 'two passes'\nunset multiplot\n",
                  {.width = 800, .height = 800});

  io::gnuplot_png(dir / "two_pass.png",
                  common + "set multiplot layout 3,1\nset xlabel 'time (us)'\nset key bottom right\n"
                           "set ylabel 'impact face radius (mm)'\nplot " + bar +
                      " skip 1 u 1:2 w l lw 4 lc rgb '#bbbbbb' t 'Taylor bar', " + one +
                      " skip 1 u 1:2 w l lw 2 lc rgb '#1f77b4' t 'one pass, lower', " + one +
                      " skip 1 u 1:3 w l lw 2 dt 2 lc rgb '#1f77b4' t 'one pass, upper', " + two +
                      " skip 1 u 1:2 w l lw 2 lc rgb '#d62728' t 'two passes, lower', " + two +
                      " skip 1 u 1:3 w l lw 2 dt 2 lc rgb '#d62728' t 'two passes, upper'\n"
                      "set ylabel 'contact plane z (um)'\nset key top left\nplot 0 w l lw 4 lc rgb '#bbbbbb' t "
                      "'symmetry', " + one + " skip 1 u 1:7 w l lw 2 lc rgb '#1f77b4' t 'one pass', " + two +
                      " skip 1 u 1:7 w l lw 2 lc rgb '#d62728' t 'two passes'\n"
                      "set ylabel 'z at the centre of the faces (um)'\nset key top right\nplot " + bar +
                      " skip 1 u 1:4 w l lw 4 lc rgb '#bbbbbb' t 'Taylor bar (and mirrored)', " + bar +
                      " skip 1 u 1:(-$4) w l lw 4 lc rgb '#bbbbbb' notitle, " + one +
                      " skip 1 u 1:10 w l lw 2 lc rgb '#1f77b4' t 'one pass, lower', " + one +
                      " skip 1 u 1:11 w l lw 2 dt 2 lc rgb '#1f77b4' t 'one pass, upper', " + two +
                      " skip 1 u 1:10 w l lw 2 lc rgb '#d62728' t 'two passes, lower', " + two +
                      " skip 1 u 1:11 w l lw 2 dt 2 lc rgb '#d62728' t 'two passes, upper'\nunset multiplot\n",
                  {.width = 800, .height = 1200});
  fmt::print("figures: shape.png, faces.png, faces_two_pass.png, history.png, momentum.png, two_pass.png in {}\n",
             dir.string());
}

int main(int argc, char** argv) {
  try {
    const fs::path dir = argc > 1 ? fs::path(argv[1]) : fs::path("results/07_bodies_in_contact");
    fs::create_directories(dir);
    rod_on_rod::parameters params;  // the Taylor bar's data for both rods; change any field here
    if (argc > 2) params.end_time_s = std::strtod(argv[2], nullptr);
    const int resolution = argc > 3 ? std::atoi(argv[3]) : 1;
    if (resolution < 1) throw std::runtime_error("the resolution K must be a whole number >= 1");
    fmt::print("rod_on_rod against taylor_bar: {} x {} particles per rod (K = {}), {:g} us, method {}\n\n",
               cases::refined_count(params.radial_particles, resolution), cases::refined_count(params.axial_particles, resolution),
               resolution, params.end_time_s * 1e6, method::name());

    const outcome bar = run_taylor_bar(params, resolution, dir);
    const outcome one = run_rods(params, resolution, /*two_pass=*/false, dir);
    const outcome two = run_rods(params, resolution, /*two_pass=*/true, dir);

    // Each rod against the Taylor bar.
    fmt::print("\n{:<22} {:>11} {:>11} {:>16} {:>9} {:>11} {:>8} {:>7}\n", "", "height (mm)", "radius (mm)",
               "vs Taylor bar", "momentum", "plane (um)", "steps", "time");
    fmt::print("{:<22} {:>11.3f} {:>11.3f} {:>16} {:>9} {:>11} {:>8} {:>5.1f} s\n", "Taylor bar", bar.height_mm[0],
               bar.radius_mm[0], "", "", "", bar.steps, bar.seconds);
    for (const auto& [name, o] : {std::pair<const char*, const outcome*>{"one pass", &one}, {"two passes", &two}})
      for (int b = 0; b < 2; ++b)
        fmt::print("{:<22} {:>11.3f} {:>11.3f} {:>+7.2f}%, {:>+6.2f}% {:>9.1e} {:>+11.2f} {:>8} {:>5.1f} s\n",
                   fmt::format("{}, {}", name, b == 0 ? "lower rod" : "upper rod"), o->height_mm[b], o->radius_mm[b],
                   100.0 * (o->height_mm[b] / bar.height_mm[0] - 1.0),
                   100.0 * (o->radius_mm[b] / bar.radius_mm[0] - 1.0), o->momentum_error, o->plane_um, o->steps,
                   o->seconds);
    plot(dir);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tutorial_07_bodies_in_contact: %s\n", e.what());
    return 1;
  }
}
