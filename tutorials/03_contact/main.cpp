// Tutorial 03: contact with rigid tools.
//
// ---------------------------------------------------------------------------------------
// Introduction
// ---------------------------------------------------------------------------------------
// The paper's contact algorithm (docs/method.md section 6, (P4)-(P7) = (56)-(59)) runs inside every
// explicit step, after the velocities v(n+1/2) and coefficients d(n+1) have been predicted:
//
//   1. find the slave particles (the body's boundary particles) whose PHYSICAL position
//      x_J = X_J + sum_I N_I(X_J) d_I lies behind a tool segment, with penetration g_J;
//   2. normal force f_n = m g / dt^2 (P4), sticking force f_st = -m v_T / dt (P6), Coulomb
//      cap |f_t| <= mu f_n (P5);
//   3. redistribute to the RK coefficients, f_I = sum_J N_I(X_J) f_J (P7), and correct
//      v_I += dt f_I / m_I, d_I += dt^2 f_I / m_I.
//
// RK shape functions are not interpolating (tutorial 01: N_J(X_J) is about 0.5), so a force
// put on coefficient I moves particle J by only a part of what it would move a lone particle.
// With the paper's mass m = m_J, one step closes only part of an isolated gap. The policy
// contact::enforcement::effective_mass uses the effective mass of J among the slaves in contact
// in the step, m_sh = 1 / sum_I |N_I(X_J)| S_I / m_I with S_I = sum_K |N_I(X_K)| (method (61a)):
// neighbouring slaves share coefficients, so a force on one also moves the others, and m_sh
// counts them. An isolated slave, or a uniformly penetrating row, lands on the tool in one step,
// and no correction is overshot; the sweeps (`sweeps`, 5 by default, `relaxation` 1) repeat the
// correction on the corrected configuration for the non-uniform rest, such as a row's ends.
//
// This program runs two problems with three policies side by side:
//   A. an elastic-plastic block (J2, linear hardening) dropped onto a fixed wall;
//   B. an elastic block sliding on the wall with Coulomb friction mu = 0.3.
// It writes CSV time histories and gnuplot PNGs; the README explains the figures.
//
// Usage: tutorial_03_contact [output directory]   (default results/03_contact)

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/io/csv.hpp>
#include <rkpm/io/gnuplot.hpp>
#include <rkpm/material/elastic.hpp>
#include <rkpm/material/j2_plasticity.hpp>
#include <rkpm/solver/make_solver.hpp>

namespace fs = std::filesystem;
using namespace rkpm;

// ---------------------------------------------------------------------------------------
// The body
// ---------------------------------------------------------------------------------------
// A 0.1 m square, 11 x 11 particles (spacing h = 0.01 m), in plane strain. The material is
// soft (E = 1 MPa, rho = 1000 kg/m^3, wave speed ~ 37 m/s) so that the impact takes a few
// hundred steps; everything scales to metals with the same number of steps per wave transit.
constexpr double E = 1e6, nu = 0.3, rho = 1000.0, W = 0.1, H = 0.1, h = 0.01;
constexpr int n = 11;

// The three enforcement policies compared. The contact type is a template parameter of the
// configuration; its run-time parameters (here the number of sweeps) go to the constructor.
using paper_contact = contact::particle_to_segment<contact::enforcement::paper, contact::friction::coulomb>;
using effective_contact =
    contact::particle_to_segment<contact::enforcement::effective_mass, contact::friction::coulomb>;

// The default effective_mass{} is 5 sweeps with relaxation 1; the one-sweep variant shows what
// the later sweeps add. Labels name the sweeps: "effective_mass_1_sweep", "effective_mass_5_sweeps".
struct policy {
  std::string label;  // file names and plot titles
  bool effective;
  contact::enforcement::effective_mass enforcement;  // used if effective
};
constexpr contact::enforcement::effective_mass one_sweep{.sweeps = 1}, default_sweeps{};
const std::vector<policy> policies = {{"paper", false, {}},
                                      {"effective_mass_1_sweep", true, one_sweep},
                                      {fmt::format("effective_mass_{}_sweeps", default_sweeps.sweeps), true, default_sweeps}};

// The wall: a one-segment polyline along y = 0, body on its left (above it), fixed.
contact::rigid_tool wall() {
  return contact::rigid_tool("wall", {vec2(-1.0, 0.0), vec2(2.0, 0.0)}, contact::side::left,
                             contact::tool_motion::fixed());
}

template <class Contact>
Contact make_contact(const policy& p, double mu) {
  if constexpr (std::is_same_v<Contact, effective_contact>)
    return Contact({wall()}, contact::friction::coulomb{mu}, p.enforcement);
  else
    return Contact({wall()}, contact::friction::coulomb{mu});
}

// ---------------------------------------------------------------------------------------
// A. An elastic-plastic block dropped on the wall
// ---------------------------------------------------------------------------------------
// J2 plasticity with linear hardening: yield 20 kPa (2% of E), hardening modulus 0.1 MPa. The
// block starts 0.2 h above the wall at 5 m/s, so the impact strain V / c ~ 14% is well past
// yield. Frictionless. Each step we record:
//   - the largest penetration found on the PREDICTED configuration, before the correction
//     (s.last_contact().max_penetration): what the contact had to undo;
//   - the physical gap of the lowest slave particle AFTER the step (negative = still inside
//     the wall): what the policy left;
//   - the energy terms of the balance  kinetic + internal = K0 + external + contact.
template <class Contact>
void drop(const policy& pol, const fs::path& out) {
  using hardening = material::hardening::linear;
  using material_t = material::j2_plasticity<hardening>;
  using cfg = config<kernel::cubic_spline, correction::linear, quadrature::q4, geometry::plane_strain, material_t,
                     Contact>;
  const double V0 = 5.0, gap0 = 0.2 * h;
  const vec2 lo(0.0, gap0), hi(W, gap0 + H);
  problem_for<cfg> p{.particles = make_grid_particles<2>(lo, hi, Eigen::Vector2i(n, n), 2.0),
                     .mesh = make_grid_mesh(lo, hi, Eigen::Vector2i(n, n)),
                     .material = material_t(material::elastic_constants{E, nu, rho}, hardening{2e4, 1e5}),
                     .contact = make_contact<Contact>(pol, 0.0),
                     .initial_velocity = [V0](const vec2&) { return vec2(0.0, -V0); },
                     .body_force = vec2(0.0, -9.81)};
  run_options o;
  o.end_time = 0.02;
  auto s = make_solver<cfg>(std::move(p), o);

  io::csv_writer csv(out / fmt::format("drop_{}.csv", pol.label),
                     {"t", "predicted_penetration_over_h", "lowest_gap_over_h", "active", "kinetic", "internal",
                      "plastic", "external", "contact", "imbalance"});
  double deepest = 0.0;
  s.run(
      [&](const auto& s) {
        const auto x = s.particle_positions();
        double lowest = INFINITY;
        for (index_t J : s.slave_particles()) lowest = std::min(lowest, x[J].y());
        deepest = std::max(deepest, -lowest);
        const auto& e = s.energy();
        csv.row({s.time(), s.last_contact().max_penetration / h, lowest / h,
                 static_cast<double>(s.last_contact().active), e.kinetic, e.internal, e.plastic, e.external,
                 e.contact, e.imbalance()});
      },
      1);
  const auto& e = s.energy();
  std::cout << fmt::format(
      "  drop  {:<24} {} steps; largest predicted penetration {:.4f} h, deepest after a step {:.4f} h; "
      "K0 {:.3f} J, contact work {:.3f} J, plastic {:.3f} J, balance error {:.2g}\n",
      pol.label, s.steps(), s.max_penetration() / h, deepest / h, e.initial_kinetic, e.contact, e.plastic,
      e.balance_error());
}

// ---------------------------------------------------------------------------------------
// B. A block sliding with friction
// ---------------------------------------------------------------------------------------
// An elastic block resting on the wall, launched sideways at v0 = 3 m/s, pressed down by a
// body force g = 100 m/s^2 (a strong "gravity" keeps the run short). Coulomb friction mu = 0.3
// decelerates it at mu g = 30 m/s^2; it stops after v0 / (mu g) = 0.1 s, at v0^2 / (2 mu g) =
// 0.15 m. We record the centre-of-mass velocity and position (sum m_I v_I / M, sum m_I d_I / M).
template <class Contact>
void slide(const policy& pol, const fs::path& out) {
  using cfg = config<kernel::cubic_spline, correction::linear, quadrature::q4, geometry::plane_strain,
                     material::elastic, Contact>;
  const double v0 = 3.0, g = 100.0, mu = 0.3;
  const vec2 lo(0.0, 0.0), hi(W, H);
  problem_for<cfg> p{.particles = make_grid_particles<2>(lo, hi, Eigen::Vector2i(n, n), 2.0),
                     .mesh = make_grid_mesh(lo, hi, Eigen::Vector2i(n, n)),
                     .material = material::elastic(material::elastic_constants{E, nu, rho}),
                     .contact = make_contact<Contact>(pol, mu),
                     .initial_velocity = [v0](const vec2&) { return vec2(v0, 0.0); },
                     .body_force = vec2(0.0, -g)};
  run_options o;
  o.end_time = 0.13;
  auto s = make_solver<cfg>(std::move(p), o);
  double M = 0.0;
  for (double m : s.mass()) M += m;
  io::csv_writer csv(out / fmt::format("slide_{}.csv", pol.label),
                     {"t", "v_cm", "x_cm", "v_theory", "x_theory", "contact_work"});
  s.run(
      [&](const auto& s) {
        vec2 d = vec2::Zero(), v = vec2::Zero();
        for (index_t I = 0; I < s.model().particle_count(); ++I) {
          d += s.mass()[I] * s.coefficients()[I];
          v += s.mass()[I] * s.coefficient_velocities()[I];
        }
        const double t = s.time(), ts = std::min(t, v0 / (mu * g));
        csv.row({t, v.x() / M, d.x() / M, std::max(0.0, v0 - mu * g * t), v0 * ts - 0.5 * mu * g * ts * ts,
                 s.energy().contact});
      },
      1);
  vec2 d = vec2::Zero();
  for (index_t I = 0; I < s.model().particle_count(); ++I) d += s.mass()[I] * s.coefficients()[I];
  std::cout << fmt::format("  slide {:<24} stopped at {:.4f} m (theory {:.4f} m); friction work {:.3f} J "
                           "(theory -M v0^2 / 2 = {:.3f} J)\n",
                           pol.label, d.x() / M, v0 * v0 / (2.0 * mu * g), s.energy().contact, -0.5 * M * v0 * v0);
}

// ---------------------------------------------------------------------------------------
// Figures
// ---------------------------------------------------------------------------------------
void figures(const fs::path& out) {
  if (!io::gnuplot_available()) {
    std::cout << "gnuplot not found: CSV files written, no figures (apt-get install gnuplot-nox)\n";
    return;
  }
  const std::string common =
      "set datafile separator ','\nset key autotitle columnhead\nset grid\nset key top right\n";
  auto file = [&](const std::string& name) { return "'" + (out / name).string() + "'"; };
  // policies[1] is the one-sweep variant, policies[2] the default effective_mass{}.
  const std::string P = file("drop_paper.csv"), E1 = file("drop_" + policies[1].label + ".csv"),
                    ED = file("drop_" + policies[2].label + ".csv");
  const std::string one = "effective mass, 1 sweep",
                    dflt = fmt::format("effective mass, {} sweeps (default)", default_sweeps.sweeps);

  // Gap history: before the correction (what each step had to undo) and after it (what is left).
  io::gnuplot_png(out / "drop_gap.png",
                  common + "set multiplot layout 2,1\n"
                           "set xlabel 't (ms)'\nset ylabel 'penetration / h'\n"
                           "set title 'Largest penetration on the predicted configuration (before the correction)'\n"
                           "plot " + P + " u ($1*1e3):2 w l lw 2 t 'paper', " + E1 +
                           " u ($1*1e3):2 w l lw 2 t '" + one + "', " + ED +
                           " u ($1*1e3):2 w l lw 2 dt 2 t '" + dflt + "'\n"
                           "set title 'Physical gap of the lowest slave particle after the step (< 0: inside the wall)'\n"
                           "set ylabel 'gap / h'\nset yrange [-0.04:0.1]\n"
                           "plot " + P + " u ($1*1e3):3 w l lw 2 t 'paper', " + E1 +
                           " u ($1*1e3):3 w l lw 2 t '" + one + "', " + ED +
                           " u ($1*1e3):3 w l lw 2 dt 2 t '" + dflt + "', 0 w l lc 'black' notitle\n"
                           "unset multiplot\n",
                  {.width = 1000, .height = 800});

  // Energy balance: kinetic, internal (elastic + plastic), plastic, contact work, imbalance.
  io::gnuplot_png(out / "drop_energy.png",
                  common + "set multiplot layout 1,2\nset xlabel 't (ms)'\nset ylabel 'energy (J per m)'\n"
                           "set key center right\n"
                           "set title 'paper'\n"
                           "plot for [c in '5 6 7 9 10'] " + P + " u ($1*1e3):(column(int(c))) w l lw 2 t columnhead(int(c))\n"
                           "set title '" + dflt + "'\n"
                           "plot for [c in '5 6 7 9 10'] " + ED + " u ($1*1e3):(column(int(c))) w l lw 2 t columnhead(int(c))\n"
                           "unset multiplot\n",
                  {.width = 1200, .height = 500});

  // Sliding: centre-of-mass velocity against the Coulomb line v0 - mu g t.
  const std::string SP = file("slide_paper.csv"), S1 = file("slide_" + policies[1].label + ".csv"),
                    SD = file("slide_" + policies[2].label + ".csv");
  io::gnuplot_png(out / "slide.png",
                  common + "set multiplot layout 1,2\nset xlabel 't (ms)'\n"
                           "set ylabel 'v (m/s)'\nset title 'centre-of-mass velocity'\n"
                           "plot " + SP + " u ($1*1e3):2 w l lw 2 t 'paper', " + S1 + " u ($1*1e3):2 w l lw 2 t '" +
                           one + "', " + SD + " u ($1*1e3):2 w l lw 2 dt 2 t '" + dflt + "', " + SP +
                           " u ($1*1e3):4 w l lw 1 lc 'black' t 'v0 - mu g t'\n"
                           "set ylabel 'x (m)'\nset title 'centre-of-mass position'\nset key bottom right\n"
                           "plot " + SP + " u ($1*1e3):3 w l lw 2 t 'paper', " + S1 + " u ($1*1e3):3 w l lw 2 t '" +
                           one + "', " + SD + " u ($1*1e3):3 w l lw 2 dt 2 t '" + dflt + "', " + SP +
                           " u ($1*1e3):5 w l lw 1 lc 'black' t 'theory'\n"
                           "unset multiplot\n",
                  {.width = 1200, .height = 450});
  std::cout << "figures: drop_gap.png, drop_energy.png, slide.png in " << out.string() << "\n";
}

// ---------------------------------------------------------------------------------------
// Running everything
// ---------------------------------------------------------------------------------------
int main(int argc, char** argv) {
  try {
    const fs::path out = argc > 1 ? fs::path(argv[1]) : fs::path("results/03_contact");
    fs::create_directories(out);
    for (const policy& pol : policies) {
      if (pol.effective) {
        drop<effective_contact>(pol, out);
        slide<effective_contact>(pol, out);
      } else {
        drop<paper_contact>(pol, out);
        slide<paper_contact>(pol, out);
      }
    }
    figures(out);
  } catch (const std::exception& e) {
    std::cerr << "tutorial_03_contact: " << e.what() << "\n";
    return 1;
  }
}
