// Tutorial 09: your own problem, from a Gmsh geometry to a solver and figures.
//
// ---------------------------------------------------------------------------------------
// Introduction
// ---------------------------------------------------------------------------------------
// Tutorials 04 to 06 took their bodies from cases/*.hpp: rectangles of particles on a grid. A
// body of your own has a shape of its own, most easily drawn in Gmsh. This program takes
// cases/projectile/projectile.geo (a plane-strain copper projectile with a rounded nose, half
// of the section, the symmetry line x = 0 named "symmetry"), lets Gmsh mesh it into
// quadrilaterals (the particles are the cell nodes), builds the rkpm::problem by hand
// (material, a rigid wall, the impact velocity, the symmetry constraint on the named curve) and
// runs it. cases/projectile/projectile.json is the same problem as a case file for
// `tools/rkpm run`, without C++; README.md walks through both, and this program prints the
// numbers that run gives, to the last digit.
//
// Usage: tutorial_09_your_own_problem [output directory] [end time in s] [resolution K]
//        (defaults: results/09_your_own_problem, the case file's 40e-6 s and K = 1: the .geo's
//        sizes; K = 2 meshes it with sizes / 2, as `--resolution 2` does to the case file)

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/geometry/plane_strain.hpp>
#include <rkpm/io/csv.hpp>
#include <rkpm/io/gmsh_mesh.hpp>
#include <rkpm/io/gnuplot.hpp>
#include <rkpm/material/j2_plasticity.hpp>
#include <rkpm/solver/make_solver.hpp>

namespace fs = std::filesystem;
using namespace rkpm;

// ---------------------------------------------------------------------------------------
// The method, as types
// ---------------------------------------------------------------------------------------
// The case file's "method" block (cubic, linear, q2, paper) and geometry "plane_strain", with
// the material its "material" block names: J2 plasticity with linear hardening.
using material_t = material::j2_plasticity<material::hardening::linear>;
using contact_t = contact::particle_to_segment<contact::enforcement::paper, contact::friction::coulomb>;
using method = config<kernel::cubic_spline, correction::linear, quadrature::q2, geometry::plane_strain, material_t,
                      contact_t>;

// The numbers of projectile.geo (R, L) and projectile.json (everything else), SI units.
constexpr double nose_radius = 5e-3, straight_length = 20e-3;
constexpr double support_factor = 2.0, impact_speed = 150.0;

using polyline = std::vector<std::pair<double, double>>;  // (x, y) in mm

class projectile_impact {
 public:
  projectile_impact(fs::path dir, double end_time, int resolution)
      : dir_(std::move(dir)), end_time_(end_time), resolution_(resolution) {}

  void run() {
    mesh_geometry();
    describe_mesh();
    solve();
    write_tables();
    plot();
  }

 private:
  // -------------------------------------------------------------------------------------
  // Meshing the .geo
  // -------------------------------------------------------------------------------------
  // Gmsh runs the script (its points, arc, physical curves and all-quad options) and meshes it
  // in 2D; the size factor multiplies every size in it (0.5 gives about twice the particles per
  // direction: what `--resolution 2` does to a case file). Node i of the quadrilaterals is
  // particle i, with a quarter of each adjacent cell's area as its volume and a support of
  // support_factor x the longest edge component around it (discretization/mesh_particles.hpp).
  void mesh_geometry() {
    const fs::path geo = fs::path(RKPM_SOURCE_DIR) / "cases" / "projectile" / "projectile.geo";
    body_ = io::mesh_geo_file(geo, /*size_factor=*/1.0 / resolution_, support_factor);
    fmt::print("meshed {} with its sizes / {}\n", geo.string(), resolution_);
  }

  // What came out: the physical curves of the .geo are node groups (sorted particle indices)
  // and edge groups (the mesh segments). The cells' straight edges replace the arc by chords,
  // so the mesh is a little smaller than the section.
  void describe_mesh() const {
    const auto& m = body_.mesh;
    fmt::print("{} particles, {} quadrilateral cells\n", body_.particles.size(), m.cells());
    for (const auto& [name, nodes] : body_.node_groups)
      fmt::print("  physical curve {:<9} {:>3} nodes, {:>3} segments\n", name, nodes.size(),
                 body_.edge_groups.at(name).size());
    const double exact = nose_radius * straight_length + std::numbers::pi * nose_radius * nose_radius / 4;
    double volume = 0.0;
    for (double v : body_.particles.volume) volume += v;
    fmt::print("area of the cells {:.6f} mm^2 (particle volumes {:.6f}), exact R L + pi R^2 / 4 = {:.6f} mm^2: "
               "relative difference {:.2e}\n",
               m.area() * 1e6, volume * 1e6, exact * 1e6, m.area() / exact - 1.0);
  }

  // -------------------------------------------------------------------------------------
  // The problem, by hand
  // -------------------------------------------------------------------------------------
  // Each field is one block of projectile.json. The contact slaves are left empty: the solver
  // then takes the boundary nodes of the cells, as the file's "slaves": "boundary" does.
  problem_for<method> build_problem() const {
    problem_for<method> p{
        .particles = body_.particles,
        .mesh = body_.mesh,
        .material = material_t({/*E*/ 117e9, /*nu*/ 0.35, /*rho*/ 8930.0},
                               material::hardening::linear{/*sigma_y*/ 400e6, /*H*/ 100e6}),
        .contact = contact_t({contact::rigid_tool("wall", {vec2(-5e-3, 0.0), vec2(40e-3, 0.0)}, contact::side::left,
                                                  contact::tool_motion::fixed())},
                             contact::friction::coulomb{.coefficient = 0.0}),
        .initial_velocity = [](const vec2&) { return vec2(0.0, -impact_speed); },
    };
    // The symmetry line: the physical velocity v_x = 0 (an empty function holds it at rest) at
    // every particle of the curve "symmetry". The solver imposes it on the RK field, not on the
    // coefficients (solver/constraints.hpp).
    for (index_t I : body_.node_groups.at("symmetry")) p.constraints.push_back({I, /*direction=*/0, {}});
    return p;
  }

  // -------------------------------------------------------------------------------------
  // The run
  // -------------------------------------------------------------------------------------
  // The observer sees the solver after every step; at 400 times in the run (as the case file's
  // "history_rows") it records the length (largest y; the nose stays on the wall at y = 0), the
  // half width (largest x) and the wall force averaged since the last record (one step's
  // reaction is noisy): the wall's impulse since t = 0 (tool_impulses()) less its reading at the
  // last record, over the time between.
  void solve() {
    run_options options;
    options.end_time = end_time_;
    const auto start = std::chrono::steady_clock::now();
    auto solver = make_solver<method>(build_problem(), options);  // built in place, never moved
    fmt::print("{} quadrature points, {} constraints, first time step {:.3g} ns\n", solver.model().point_count(),
               solver.constraints().size(), solver.time_step() * 1e9);

    double interval_impulse = 0.0, interval_start = 0.0, next_row = 0.0, next_print = 0.0;
    auto observe = [&](const auto& s) {
      const double t = s.time();
      if (t < next_row && t < end_time_ * (1 - 1e-12)) return;
      next_row += end_time_ / 400;
      const double impulse = -s.tool_impulses()[0].y();  // the force on the wall, downward
      const double force = t > interval_start ? (impulse - interval_impulse) / (t - interval_start) : 0.0;
      interval_impulse = impulse, interval_start = t;
      const auto x = s.particle_positions();
      double length = 0.0, half_width = 0.0;
      for (const vec2& p : x) length = std::max(length, p.y()), half_width = std::max(half_width, p.x());
      history_.push_back({t * 1e6, length * 1e3, half_width * 1e3, force * 1e-6});
      if (t >= next_print) {
        fmt::print("  {:>4.1f} us  step {:>5}  length {:.3f} mm  half width {:.3f} mm  wall {:.3f} MN/m\n", t * 1e6,
                   s.steps(), length * 1e3, half_width * 1e3, force * 1e-6);
        std::fflush(stdout);
        next_print += 0.1 * end_time_;
      }
    };
    solver.run(observe, 1);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    final_x_ = solver.particle_positions();

    const auto& last = history_.back();
    // Shortest round-trip form, as summary.json writes doubles: equal text is the same double.
    fmt::print("\nafter {} steps ({:.2f} s), {:g} us:\n  length_mm      {}\n  half_width_mm  {}\n", solver.steps(),
               seconds, solver.time() * 1e6, last[1], last[2]);
    fmt::print("  energy balance error {:.1e} of the initial kinetic energy {:.1f} J/m\n",
               solver.energy().balance_error(), solver.energy().initial_kinetic);
  }

  // -------------------------------------------------------------------------------------
  // Output: CSV and figures
  // -------------------------------------------------------------------------------------
  void write_tables() const {
    io::csv_writer history(dir_ / "history.csv", {"time_us", "length_mm", "half_width_mm", "wall_force_MN_per_m"});
    for (const auto& r : history_) history.row({r[0], r[1], r[2], r[3]});
    io::csv_writer nodes(dir_ / "particles.csv", {"X_mm", "Y_mm", "x_mm", "y_mm"});
    const auto& X = body_.mesh.node;  // node I is particle I
    for (std::size_t I = 0; I < X.size(); ++I)
      nodes.row({X[I].x() * 1e3, X[I].y() * 1e3, final_x_[I].x() * 1e3, final_x_[I].y() * 1e3});
  }

  // The cells as closed outlines (one gnuplot block each), at the positions given (m -> mm).
  std::vector<polyline> outlines(const std::vector<vec2>& x) const {
    std::vector<polyline> cells;
    for (const auto& c : body_.mesh.cell) {
      polyline& line = cells.emplace_back();
      for (int k = 0; k <= 4; ++k) line.emplace_back(x[c[k % 4]].x() * 1e3, x[c[k % 4]].y() * 1e3);
    }
    return cells;
  }

  void plot() const {
    if (!io::gnuplot_available()) {
      fmt::print("gnuplot not found: the CSV files are in {}\n", dir_.string());
      return;
    }
    auto group = [&](const std::string& curve) {  // the nodes of a physical curve, mm
      polyline g;
      const auto& X = body_.mesh.node;
      for (index_t I : body_.node_groups.at(curve)) g.emplace_back(X[I].x() * 1e3, X[I].y() * 1e3);
      return g;
    };
    {
      io::gnuplot_figure fig(dir_ / "mesh.png", {.width = 600, .height = 900});
      fig << fmt::format("set size ratio -1\nset xlabel 'x (mm)'\nset ylabel 'y (mm)'\nset xrange [-1:10]\n"
                         "set title 'projectile.geo meshed by Gmsh: {} cells, {} particles'\nset key top right\n"
                         "plot '-' w l lc rgb 'gray30' notitle, '-' w p pt 7 ps 0.6 lc rgb 'red' t 'symmetry', "
                         "'-' w p pt 7 ps 0.6 lc rgb 'web-blue' t 'nose'\n",
                         body_.mesh.cells(), body_.particles.size());
      fig.send2d(outlines(body_.mesh.node)).send1d(group("symmetry")).send1d(group("nose"));
      fig.render();
    }
    {
      io::gnuplot_figure fig(dir_ / "deformed.png", {.width = 800, .height = 800});
      fig << fmt::format("set size ratio -1\nset xlabel 'x (mm)'\nset ylabel 'y (mm)'\nset grid\nset xrange [-3:12]\n"
                         "set yrange [-1:26]\nset title 'cells at t = 0 (grey) and at {:g} us'\n"
                         "plot '-' w l lc rgb 'gray80' notitle, '-' w l lc rgb 'web-blue' notitle, "
                         "'-' w l lw 3 lc rgb 'black' t 'wall'\n",
                         end_time_ * 1e6);
      fig.send2d(outlines(body_.mesh.node)).send2d(outlines(final_x_)).send1d(polyline{{-3.0, 0.0}, {12.0, 0.0}});
      fig.render();
    }
    const std::string h = io::gnuplot_quote((dir_ / "history.csv").string());
    io::gnuplot_png(dir_ / "history.png",
                    "set datafile separator ','\nset grid\nset multiplot layout 2,1\nset xlabel 'time (us)'\n"
                    "set ylabel 'length (mm)'\nset y2label 'half width (mm)'\nset y2tics\nset ytics nomirror\n"
                    "set key center right\nplot " + h + " skip 1 u 1:2 w l lw 2 t 'length', " + h +
                        " skip 1 u 1:3 axes x1y2 w l lw 2 t 'half width'\n"
                        "unset y2label\nunset y2tics\nset ytics mirror\nset ylabel 'wall force (MN/m)'\n"
                        "plot " + h + " skip 1 u 1:4 w l lw 2 notitle\nunset multiplot\n",
                    {.width = 800, .height = 800});
    fmt::print("figures: mesh.png, deformed.png, history.png in {}\n", dir_.string());
  }

  fs::path dir_;
  double end_time_;
  int resolution_;
  io::gmsh_body body_;
  std::vector<std::array<double, 4>> history_;  // time (us), length (mm), half width (mm), wall force (MN/m)
  std::vector<vec2> final_x_;
};

int main(int argc, char** argv) {
  try {
    const fs::path dir = argc > 1 ? fs::path(argv[1]) : fs::path("results/09_your_own_problem");
    fs::create_directories(dir);
    const int resolution = argc > 3 ? std::atoi(argv[3]) : 1;
    if (resolution < 1) throw std::runtime_error("the resolution K must be a whole number >= 1");
    projectile_impact(dir, argc > 2 ? std::strtod(argv[2], nullptr) : 40e-6, resolution).run();
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tutorial_09_your_own_problem: %s\n", e.what());
    return 1;
  }
}
