// Tutorial 02: quadrature rules for the stiffness and the explicit step.
//
// ---------------------------------------------------------------------------------------
// Introduction
// ---------------------------------------------------------------------------------------
// Tutorial 01 built the RK shape functions N_I. The solver never integrates them exactly:
// every integral over the body (internal force, lumped mass) is a sum over quadrature points
// of background cells (docs/method.md section 3),
//
//   f_int,I = sum_q P(X_q) grad N_I(X_q) w_q,     m_I = rho sum_q N_I(X_q) w_q,
//
// and the rule that places the points is a policy: rkpm::quadrature::q1 (cell centre),
// q2 (the paper's two-point rule: the diagonal Gauss pair), q4 (2x2 Gauss, the paper's
// reference) and q9 (3x3 Gauss). The cost of a step is proportional to the number of points,
// so the paper's question is: how few points can we take without breaking the method?
//
// This program answers it in four parts:
//   0. which polynomials each rule integrates exactly on the reference square;
//   1. how far the assembled elastic stiffness K of each rule is from a fine 6x6 Gauss
//      reference, on a small square patch at three spacings;
//   2. the spectrum of M^-1 K (squared natural frequencies): a rule that is too poor leaves
//      deformation modes that cost no energy ("hourglass" modes), seen as extra zeros;
//   3. what a step of the explicit solver costs with each rule on the Taylor bar.
// The README explains the figures.
//
// Usage: tutorial_02_quadrature [output directory]   (default results/02_quadrature)

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <fmt/format.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include <rkpm/correction/polynomial_bases.hpp>
#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/discretization/background_mesh.hpp>
#include <rkpm/discretization/particle_set.hpp>
#include <rkpm/quadrature/cell_rules.hpp>
#include <rkpm/geometry/axisymmetric.hpp>
#include <rkpm/geometry/plane_strain.hpp>
#include <rkpm/io/csv.hpp>
#include <rkpm/io/gnuplot.hpp>
#include <rkpm/kernel/cubic_spline.hpp>
#include <rkpm/material/elastic_constants.hpp>
#include <rkpm/solver/discrete_model.hpp>
#include <rkpm/solver/make_solver.hpp>
#include <rkpm/solver/stable_time_step.hpp>

#include "cases/taylor_bar.hpp"

namespace fs = std::filesystem;
using namespace rkpm;

// ---------------------------------------------------------------------------------------
// A reference rule of our own: 6x6 Gauss
// ---------------------------------------------------------------------------------------
// A quadrature policy is nothing but a name, a point count and a table of (xi, eta, weight)
// on [-1, 1]^2 (concepts/quadrature.hpp). A user-defined rule is therefore a few lines; this
// one integrates every polynomial up to degree 11 in each variable exactly and serves as the
// "exact" stiffness below. (RK shape functions are rational, not polynomial, inside a cell, so
// no rule is exact; 6x6 Gauss is far finer than the rules we compare.)
struct gauss6 {
  static constexpr std::string_view name = "gauss6";
  static constexpr int points_per_cell = 36;
  static constexpr std::array<std::array<double, 3>, 36> rule = [] {
    constexpr double x[6] = {-0.93246951420315203, -0.66120938646626451, -0.23861918608319691,
                             0.23861918608319691,  0.66120938646626451,  0.93246951420315203};
    constexpr double w[6] = {0.17132449237917035, 0.36076157304813861, 0.46791393457269105,
                             0.46791393457269105, 0.36076157304813861, 0.17132449237917035};
    std::array<std::array<double, 3>, 36> r{};
    for (int j = 0; j < 6; ++j)
      for (int i = 0; i < 6; ++i) r[6 * j + i] = {x[i], x[j], w[i] * w[j]};
    return r;
  }();
};
static_assert(Quadrature<gauss6>);

// The discretization used throughout: cubic spline kernel, linear correction, support twice
// the particle spacing in each direction (the Taylor bar's choice).
using kernel_type = kernel::cubic_spline;
using correction_type = correction::linear;
constexpr double support_factor = 2.0;

// Copper, as in the Taylor bar; the elastic constants alone matter for K.
const material::elastic_constants copper{117e9, 0.35, 8930.0};

template <class Q, class G>
discrete_model make_model(const vec2& lo, const vec2& hi, const Eigen::Vector2i& n) {
  return build_discrete_model<kernel_type, correction_type, Q, G>(make_grid_particles<2>(lo, hi, n, support_factor),
                                                                  make_grid_mesh(lo, hi, n));
}

// ---------------------------------------------------------------------------------------
// Part 0: which monomials a rule integrates exactly
// ---------------------------------------------------------------------------------------
// The exact integral of xi^a eta^b over [-1, 1]^2 is 0 if a or b is odd, else
// 4 / ((a + 1)(b + 1)). q2's two points lie on the diagonal xi = eta, so it cannot tell xi*eta
// from xi^2: it integrates xi*eta as 4/3 instead of 0. Every other monomial up to degree 3 it
// gets right (by symmetry of the pair about the centre, all odd ones vanish as they should).
template <class Q>
double integrate_monomial(int a, int b) {
  double s = 0.0;
  for (const auto& [xi, eta, w] : Q::rule) s += w * std::pow(xi, a) * std::pow(eta, b);
  return s;
}

double exact_monomial(int a, int b) { return (a % 2 || b % 2) ? 0.0 : 4.0 / ((a + 1) * (b + 1)); }

void part0_monomials(const fs::path& out) {
  std::cout << "\nPart 0: error of each rule on xi^a eta^b over [-1,1]^2 (exact integral in brackets)\n";
  std::cout << fmt::format("  {:<10} {:>9} {:>10} {:>10} {:>10} {:>10}\n", "monomial", "exact", "q1", "q2", "q4", "q9");
  io::csv_writer csv(out / "monomials.csv", {"a", "b", "exact", "q1", "q2", "q4", "q9"});
  for (int degree = 0; degree <= 4; ++degree)
    for (int b = 0; b <= degree; ++b) {
      const int a = degree - b;
      const double e = exact_monomial(a, b);
      const double r1 = integrate_monomial<quadrature::q1>(a, b) - e, r2 = integrate_monomial<quadrature::q2>(a, b) - e;
      const double r4 = integrate_monomial<quadrature::q4>(a, b) - e, r9 = integrate_monomial<quadrature::q9>(a, b) - e;
      auto show = [](double r) { return std::abs(r) < 1e-14 ? std::string("0") : fmt::format("{:+.4f}", r); };
      std::cout << fmt::format("  xi^{} eta^{}  {:>9.4f} {:>10} {:>10} {:>10} {:>10}\n", a, b, e, show(r1), show(r2),
                               show(r4), show(r9));
      csv.row({double(a), double(b), e, r1, r2, r4, r9});
    }
}

// ---------------------------------------------------------------------------------------
// Assembling K column by column
// ---------------------------------------------------------------------------------------
// The solver never forms K: apply_elastic_stiffness<G> (solver/stable_time_step.hpp) returns
// the small-strain internal force K x for coefficients x, as the power iteration for the
// stable step needs. Applying it to each unit vector gives K one column at a time, which for
// a few hundred unknowns is instant. Unknowns are ordered (particle I, direction k) -> 2I + k.
template <class G>
Eigen::MatrixXd assemble_stiffness(const discrete_model& m) {
  const index_t n = m.particle_count();
  std::vector<vec2> x(n, vec2::Zero()), kx(n);
  Eigen::MatrixXd K(2 * n, 2 * n);
  for (index_t J = 0; J < n; ++J)
    for (int k = 0; k < 2; ++k) {
      x[J][k] = 1.0;
      apply_elastic_stiffness<G>(m, copper, x, kx);
      x[J][k] = 0.0;
      for (index_t I = 0; I < n; ++I) K.block<2, 1>(2 * I, 2 * J + k) = kx[I];
    }
  return K;
}

// Lumped masses per unknown, rho V_I with V_I = sum_q N_I(X_q) w_q (what the solver uses).
Eigen::VectorXd dof_masses(const discrete_model& m) {
  Eigen::VectorXd M(2 * m.particle_count());
  for (index_t I = 0; I < m.particle_count(); ++I) M[2 * I] = M[2 * I + 1] = copper.density * m.lumped_volume[I];
  return M;
}

// ---------------------------------------------------------------------------------------
// Part 1: integration error of the stiffness
// ---------------------------------------------------------------------------------------
// The patch is the unit square with n x n particles; the same particles and cells are
// integrated with every rule, so any difference in K is quadrature error alone. We report
// |K_Q - K_ref|_F / |K_ref|_F with K_ref from gauss6.
template <class Q>
double stiffness_error(const Eigen::Vector2i& n, const Eigen::MatrixXd& K_ref) {
  const Eigen::MatrixXd K = assemble_stiffness<geometry::plane_strain>(
      make_model<Q, geometry::plane_strain>(vec2(0, 0), vec2(1, 1), n));
  return (K - K_ref).norm() / K_ref.norm();
}

void part1_stiffness_error(const fs::path& out) {
  std::cout << "\nPart 1: |K_Q - K_6x6| / |K_6x6| on the unit square, plane strain\n";
  std::cout << fmt::format("  {:>9} {:>8} {:>11} {:>11} {:>11} {:>11}\n", "particles", "h", "q1", "q2", "q4", "q9");
  io::csv_writer csv(out / "stiffness_error.csv", {"per_side", "h", "q1", "q2", "q4", "q9"});
  for (int per_side : {5, 9, 17}) {
    const Eigen::Vector2i n(per_side, per_side);
    const Eigen::MatrixXd K_ref =
        assemble_stiffness<geometry::plane_strain>(make_model<gauss6, geometry::plane_strain>(vec2(0, 0), vec2(1, 1), n));
    const double h = 1.0 / (per_side - 1);
    const double e1 = stiffness_error<quadrature::q1>(n, K_ref), e2 = stiffness_error<quadrature::q2>(n, K_ref);
    const double e4 = stiffness_error<quadrature::q4>(n, K_ref), e9 = stiffness_error<quadrature::q9>(n, K_ref);
    std::cout << fmt::format("  {:>5}^2   {:>8.4f} {:>11.3e} {:>11.3e} {:>11.3e} {:>11.3e}\n", per_side, h, e1, e2, e4, e9);
    csv.row({double(per_side), h, e1, e2, e4, e9});
  }
  // The error does not fall with h: refining the particles refines the cells with them, and a
  // shape function looks the same relative to its cell at every spacing. The rule's relative
  // error is a property of (kernel, support/spacing, rule), not of h.
  io::gnuplot_png(out / "stiffness_error.png", fmt::format(R"(
set datafile separator ','
set title 'Relative stiffness error against a 6x6 Gauss rule (unit square, plane strain)'
set xlabel 'particle spacing h'
set ylabel '|K_Q - K_{{ref}}|_F / |K_{{ref}}|_F'
set logscale xy
set xrange [0.04:0.4]
set format y '10^{{%L}}'
set key outside right
set grid
plot for [c=3:6] '{}' using 2:c with linespoints lw 2 pt 7 title columnheader(c)
)", (out / "stiffness_error.csv").string()));
}

// ---------------------------------------------------------------------------------------
// Part 2: the spectrum of M^-1 K
// ---------------------------------------------------------------------------------------
// The squared natural frequencies omega^2 are the eigenvalues of K x = omega^2 M x; with a
// diagonal (lumped) M this is the symmetric problem (M^-1/2 K M^-1/2) y = omega^2 y. A free
// body has exactly as many zero frequencies as rigid motions: 3 in plane strain (two
// translations, one rotation), 1 in axisymmetry (translation along the axis; a radial
// translation stretches the hoops and a rotation is not axisymmetric). Every further zero is a
// displacement pattern whose strain vanishes at all quadrature points: the rule cannot see it,
// and in a dynamic run it grows unresisted.
struct spectrum_result {
  Eigen::VectorXd omega2;   // ascending
  Eigen::MatrixXd modes;    // coefficient vectors (M-orthonormal), one column per omega2
  int zero_modes = 0;       // |omega^2| < 1e-8 max omega^2: zero to round-off
};

template <class Q, class G>
spectrum_result spectrum(const vec2& lo, const vec2& hi, const Eigen::Vector2i& n, discrete_model* keep = nullptr) {
  discrete_model m = make_model<Q, G>(lo, hi, n);
  const Eigen::MatrixXd K = assemble_stiffness<G>(m);
  const Eigen::VectorXd s = dof_masses(m).cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd A = s.asDiagonal() * (0.5 * (K + K.transpose())) * s.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(A);
  spectrum_result r;
  r.omega2 = eig.eigenvalues();
  r.modes = s.asDiagonal() * eig.eigenvectors();
  const double top = r.omega2.cwiseAbs().maxCoeff();
  for (double w : r.omega2) r.zero_modes += std::abs(w) < 1e-8 * top;
  if (keep) *keep = std::move(m);
  return r;
}

// Exact zeros are not the whole story: on a finite patch the boundary particles' corrected
// shape functions break the symmetry that makes an hourglass pattern invisible to one point,
// so q1's hourglass modes come out tiny but not zero. We call a mode "soft" when its omega^2
// is below 1 % of the lowest elastic omega^2 of the well-integrated q9 discretization of the
// same particles: no physical mode of the body is that soft.
int soft_modes(const spectrum_result& s, int rigid_modes, double lowest_elastic_q9) {
  int k = 0;
  for (index_t i = rigid_modes; i < s.omega2.size(); ++i) k += s.omega2[i] < 0.01 * lowest_elastic_q9;
  return k;
}

struct layout {
  std::string name, title;
  vec2 lo, hi;
  Eigen::Vector2i n;
};

template <class G>
void spectrum_of_layout(const fs::path& out, const layout& L, int rigid_modes) {
  std::cout << fmt::format("\n  {} ({} x {} particles, {}; {} rigid modes)\n", L.title, L.n[0], L.n[1], G::name,
                           rigid_modes);
  discrete_model m1;
  const spectrum_result s1 = spectrum<quadrature::q1, G>(L.lo, L.hi, L.n, &m1);
  const spectrum_result s2 = spectrum<quadrature::q2, G>(L.lo, L.hi, L.n);
  const spectrum_result s4 = spectrum<quadrature::q4, G>(L.lo, L.hi, L.n);
  const spectrum_result s9 = spectrum<quadrature::q9, G>(L.lo, L.hi, L.n);
  const double top = s9.omega2.maxCoeff(), first = s9.omega2[rigid_modes];
  std::cout << fmt::format("    {:<4} {:>10} {:>10} {:>24} {:>15}\n", "rule", "zero modes", "soft modes",
                           "lowest elastic w^2 / q9's", "max w^2 / q9's");
  for (auto [name, s] : {std::pair{"q1", &s1}, std::pair{"q2", &s2}, std::pair{"q4", &s4}, std::pair{"q9", &s9}})
    std::cout << fmt::format("    {:<4} {:>10} {:>10} {:>24.3e} {:>15.4f}\n", name, s->zero_modes,
                             soft_modes(*s, rigid_modes, first), s->omega2[rigid_modes] / first,
                             s->omega2.maxCoeff() / top);
  // How closely q2's low end follows q4's and q9's: the lowest 10 elastic modes.
  double d24 = 0.0, d29 = 0.0;
  for (int k = rigid_modes; k < rigid_modes + 10; ++k) {
    d24 = std::max(d24, std::abs(s2.omega2[k] / s4.omega2[k] - 1.0));
    d29 = std::max(d29, std::abs(s2.omega2[k] / s9.omega2[k] - 1.0));
  }
  std::cout << fmt::format("    lowest 10 elastic modes: q2 differs from q4 by at most {:.2f} %, from q9 by {:.2f} %\n",
                           100 * d24, 100 * d29);

  const auto csv_path = out / fmt::format("spectrum_{}.csv", L.name);
  {
    io::csv_writer csv(csv_path, {"mode", "q1", "q2", "q4", "q9"});
    for (index_t k = 0; k < s9.omega2.size(); ++k)
      csv.row({double(k), s1.omega2[k] / top, s2.omega2[k] / top, s4.omega2[k] / top, s9.omega2[k] / top});
  }
  // Two panels: the whole spectrum, and its low end on a log scale, where a zero mode shows as
  // a point at round-off level (~1e-16) instead of on the curve. |w^2| because round-off can
  // make a zero slightly negative.
  const std::string plot_body = fmt::format(R"(
set datafile separator ','
set multiplot layout 1,2 title '{} - eigenvalues of M^{{-1}}K, scaled by the largest of q9'
set xlabel 'mode number'
set ylabel '{{/Symbol w}}^2 / {{/Symbol w}}^2_{{max}}'
set grid
set key top left
plot for [c=2:5] '{}' using 1:c with lines lw 2 title columnheader(c)
set logscale y
set format y '10^{{%L}}'
set yrange [1e-18:1]
set xrange [-0.5:24.5]
set title 'lowest 25 modes ({} rigid)'
set key bottom right
plot for [c=2:5] '{}' using 1:(abs(column(c))) with linespoints lw 2 pt 7 ps 0.8 title columnheader(c)
unset multiplot
)",
                                            L.title, csv_path.string(), rigid_modes, csv_path.string());
  io::gnuplot_png(out / fmt::format("spectrum_{}.png", L.name), plot_body, {.width = 1200, .height = 500});

  // q1's softest non-rigid mode, drawn as physical displacements u(X_I) = sum_J N_J(X_I) d_J.
  if (soft_modes(s1, rigid_modes, first) > 0) {
    std::vector<vec2> d(m1.particle_count());
    for (index_t I = 0; I < m1.particle_count(); ++I) d[I] = s1.modes.col(rigid_modes).segment<2>(2 * I);
    double umax = 0.0;
    std::vector<vec2> u(m1.particle_count());
    for (index_t I = 0; I < m1.particle_count(); ++I) {
      u[I] = m1.at_particles.interpolate(I, d);
      umax = std::max(umax, u[I].norm());
    }
    const double scale = 0.6 * (L.hi - L.lo).minCoeff() / (std::max(L.n[0], L.n[1]) - 1) / umax;
    const auto mode_csv = out / fmt::format("q1_mode_{}.csv", L.name);
    {
      io::csv_writer csv(mode_csv, {"X", "Y", "ux", "uy"});
      for (index_t I = 0; I < m1.particle_count(); ++I) {
        const vec2& X = m1.particles.position[I];
        csv.row({X[0], X[1], scale * u[I][0], scale * u[I][1]});
      }
    }
    io::gnuplot_png(out / fmt::format("q1_mode_{}.png", L.name), fmt::format(R"(
set datafile separator ','
set title '{}: softest non-rigid mode of q1 (physical displacement, scaled)'
set size ratio -1
unset key
set xlabel 'x'
set ylabel 'y'
plot '{}' skip 1 using 1:2:3:4 with vectors head filled size screen 0.01,20 lw 1.5 lc rgb '#c03030', \
     '' skip 1 using 1:2 with points pt 7 ps 0.5 lc rgb 'black'
)", L.title, mode_csv.string()), {.width = 700, .height = L.name == "square" ? 700 : 900});
  }
}

void part2_spectra(const fs::path& out) {
  std::cout << "\nPart 2: spectrum of M^-1 K. zero: |w^2| < 1e-8 max w^2; soft: non-rigid w^2 below 1 % of\n"
               "        q9's lowest elastic w^2\n";
  // Square: 9 x 9 particles on the unit square, square cells.
  spectrum_of_layout<geometry::plane_strain>(out, {"square", "Unit square", vec2(0, 0), vec2(1, 1), {9, 9}}, 3);
  // The Taylor bar's layout: its 21 x 51 particles on R0 = 3.2 mm by L0 = 32.4 mm give cells of
  // aspect 4.05 : 1 (0.16 x 0.648 mm). A coarse copy with the same cell shape: 6 x 11 particles
  // on 0.8 x 6.48 mm (cells 0.16 x 0.648 mm), in plane strain and, as the bar is, axisymmetric.
  const layout bar{"taylor", "Taylor bar cells (4:1)", vec2(0, 0), vec2(0.8e-3, 6.48e-3), {6, 11}};
  spectrum_of_layout<geometry::plane_strain>(out, bar, 3);
  layout axi = bar;
  axi.name = "taylor_axisymmetric";
  axi.title = "Taylor bar cells (4:1), axisymmetric";
  spectrum_of_layout<geometry::axisymmetric>(out, axi, 1);
}

// ---------------------------------------------------------------------------------------
// Part 3: what a step costs
// ---------------------------------------------------------------------------------------
// The explicit solver on the Taylor bar (cases/taylor_bar.hpp: 21 x 51 particles,
// axisymmetric, J2 plasticity with linear hardening, the paper's contact against the wall),
// built as everything builds it, by make_solver (the time loop it returns does not depend on
// the rule; only the discrete model does). We take 100 steps to get into the impact, then time 200 with
// std::chrono (wall clock) and std::clock (CPU time of the process), on one thread so that the
// two agree on an idle machine and the CPU time stays meaningful on a busy one. This is
// indicative only: one measurement each. `tools/rkpm bench` runs the Google Benchmark version
// with repetitions and thread counts.
using bar_case = cases::taylor_bar;
using wall = contact::particle_to_segment<contact::enforcement::paper, contact::friction::frictionless>;
template <class Q>
using bar_method = config<kernel_type, correction_type, Q, bar_case::geometry_type, bar_case::material_type, wall>;

struct step_timing {
  std::string rule;
  int points_per_cell = 0;
  index_t points = 0;
  double ms_per_step = 0.0;      // wall clock
  double cpu_ms_per_step = 0.0;  // process CPU time: what the step costs, whatever else runs
  std::string note;
};

template <class Q>
step_timing time_steps() {
  step_timing t{std::string(Q::name), Q::points_per_cell};
  try {
    run_options options;
    options.end_time = bar_case::end_time({});
    auto s = make_solver<bar_method<Q>>(bar_case::build<wall>({}, 1), options);
    t.points = s.model().point_count();
    for (int k = 0; k < 100; ++k) s.step();
    const int steps = 200;
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpu_start = std::clock();
    for (int k = 0; k < steps; ++k) s.step();
    t.cpu_ms_per_step = 1e3 * double(std::clock() - cpu_start) / CLOCKS_PER_SEC / steps;
    t.ms_per_step = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() / steps;
  } catch (const rkpm::error& e) {
    t.note = e.what();
  }
  return t;
}

void part3_time_per_step(const fs::path& out) {
  std::cout << "\nPart 3: time per explicit step, Taylor bar 21 x 51, 1 thread (indicative; see tools/rkpm bench)\n";
#ifdef _OPENMP
  omp_set_num_threads(1);
#endif
  const std::vector<step_timing> timings = {time_steps<quadrature::q1>(), time_steps<quadrature::q2>(),
                                            time_steps<quadrature::q4>(), time_steps<quadrature::q9>()};
  io::csv_writer csv(out / "time_per_step.csv", {"points_per_cell", "points", "ms_per_step", "cpu_ms_per_step"});
  const double q4_time = timings[2].cpu_ms_per_step;
  for (const auto& t : timings) {
    if (!t.note.empty()) {
      std::cout << fmt::format("  {:<3} failed: {}\n", t.rule, t.note);
      continue;
    }
    std::cout << fmt::format("  {:<3} {:>6} points  wall {:>7.3f} ms/step  CPU {:>7.3f} ms/step  (CPU {:.2f} x q4)\n",
                             t.rule, t.points, t.ms_per_step, t.cpu_ms_per_step, t.cpu_ms_per_step / q4_time);
    csv.row({double(t.points_per_cell), double(t.points), t.ms_per_step, t.cpu_ms_per_step});
  }
  csv.close();
  io::gnuplot_png(out / "time_per_step.png", fmt::format(R"(
set datafile separator ','
set title 'Taylor bar 21 x 51: time per explicit step, 1 thread (one run, indicative)'
set xlabel 'quadrature points'
set ylabel 'ms per step'
set grid
set key top left

set yrange [0:*]
set xtics 1000
set xrange [0:9500]
plot '{0}' skip 1 using 2:4 with linespoints lw 2 pt 7 ps 1.5 title 'CPU time', \
     '' skip 1 using 2:3 with linespoints lw 2 pt 6 ps 1.5 dt 2 title 'wall clock', \
     '' skip 1 using 2:4:(sprintf('q%d', int($1))) with labels offset 0,1.2 notitle
)", (out / "time_per_step.csv").string()));
}

// ---------------------------------------------------------------------------------------
// main
// ---------------------------------------------------------------------------------------
int main(int argc, char** argv) {
  try {
    const fs::path out = argc > 1 ? fs::path(argv[1]) : fs::path("results/02_quadrature");
    fs::create_directories(out);
    // Small dense eigenproblems: Eigen's own threading only adds spin-waiting here.
    Eigen::setNbThreads(1);
    part0_monomials(out);
    part1_stiffness_error(out);
    part2_spectra(out);
    part3_time_per_step(out);
    std::cout << "\nwrote CSV and PNG files to " << out.string() << "\n";
  } catch (const std::exception& e) {
    std::cerr << "tutorial_02_quadrature: " << e.what() << "\n";
    return 1;
  }
}
