// Tutorial 08: the integration constraint and the patch test, made visible.
//
// ---------------------------------------------------------------------------------------
// Introduction
// ---------------------------------------------------------------------------------------
// Tutorial 02 compared the paper's two-point rule q2 with q4 by what a rule does to the
// stiffness and to its spectrum. It left a question open: why does q2, whose spectrum is clean,
// lose an order of accuracy? The answer is a property no cell rule has with RK functions, the
// integration constraint (docs/method.md (19a)): for every particle I,
//
//   sum_q [g_I(X_q) + e_r N_I(X_q) / R_q] w_q  =  b_I  =  integral over the boundary of N_I n omega ds
//
// (the hoop term e_r N_I / R and omega = 2 pi R in axisymmetry only). It is the divergence
// theorem for the test functions, computed with the rule. If it holds, a homogeneous stress
// gives zero internal force at every particle whose support does not reach the boundary (the
// linear patch test); if it fails, the rule injects spurious forces everywhere, and the method
// converges at first order only.
//
// Variationally consistent integration (VCI, docs/method.md section 3.5) repairs any rule by
// adding one constant vector per particle to its test-function gradients, so that the
// constraint holds exactly. The rules here are the policies of quadrature/cell_rules.hpp,
// quadrature/shaped_rules.hpp and quadrature/vci.hpp:
//   q2        the paper's two-point rule (the diagonal Gauss pair)
//   q4, q9    2x2 and 3x3 Gauss
//   q2_split  the cell halved across its longer side, one point at each half's centroid
//   q2_tri    the cell cut along its shorter diagonal, one point at each triangle's centroid
//   q2+vci, q4+vci   q2 and q4 with VCI-corrected test gradients
//   scni      stabilized conforming nodal integration (docs/method.md section 3.6): no rule
//             per cell, but one smoothing cell per particle, on which the gradients are
//             smoothed by boundary integrals, with the modified-SCNI stabilization
//
// The program has four parts:
//   1. the per-particle violation of the constraint, for every rule, on a 9 x 9 patch with
//      jittered particles, read as a plane-strain body and as a section of revolution;
//   2. the linear patch test on the same particles: the internal force of a homogeneous stress;
//   3. convergence on two static problems with analytic solutions, at three resolutions;
//   4. what a step costs with each rule on the Taylor bar.
// Only part 4 runs the explicit solver, and the solver's type does not depend on the rule
// (solver/make_solver.hpp), so the whole program compiles one time loop. Parts 1 to 3 build
// discrete models (one small instantiation per rule and geometry: the rule only changes the
// tables) and use the solver's own force loop through apply_elastic_stiffness.
//
// Usage: tutorial_08_integration [output directory] [--taylor-bar]
//        (default results/08_integration; --taylor-bar runs part 4's Taylor bar to the end with
//        every rule, about two minutes more)

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseLU>
#include <fmt/format.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/correction/polynomial_bases.hpp>
#include <rkpm/discretization/background_mesh.hpp>
#include <rkpm/discretization/integration_constraint.hpp>
#include <rkpm/discretization/particle_set.hpp>
#include <rkpm/geometry/axisymmetric.hpp>
#include <rkpm/geometry/plane_strain.hpp>
#include <rkpm/io/csv.hpp>
#include <rkpm/io/gnuplot.hpp>
#include <rkpm/kernel/cubic_spline.hpp>
#include <rkpm/material/elastic_constants.hpp>
#include <rkpm/discretization/smoothing_cells.hpp>
#include <rkpm/quadrature/cell_rules.hpp>
#include <rkpm/quadrature/scni.hpp>
#include <rkpm/quadrature/shaped_rules.hpp>
#include <rkpm/quadrature/vci.hpp>
#include <rkpm/solver/discrete_model.hpp>
#include <rkpm/solver/make_solver.hpp>
#include <rkpm/solver/stable_time_step.hpp>

#include "cases/taylor_bar.hpp"

namespace fs = std::filesystem;
using namespace rkpm;

// ---------------------------------------------------------------------------------------
// The discretization and the rules
// ---------------------------------------------------------------------------------------
// Cubic spline kernel, linear correction, support twice the spacing: the Taylor bar's choice,
// as in tutorial 02. Everything below is repeated for every rule of `rules`, a plain list of
// types walked by a fold expression; the rule's name is its policy's `name` ("q2+vci", ...).
using kernel_type = kernel::cubic_spline;
using correction_type = correction::linear;
constexpr double support_factor = 2.0;

template <class... Q>
struct rule_list {};

using rules = rule_list<quadrature::q2, quadrature::q4, quadrature::q9, quadrature::q2_split, quadrature::q2_tri,
                        quadrature::q2_vci, quadrature::q4_vci, quadrature::scni<>>;

template <class... Q, class F>
void for_each_rule(rule_list<Q...>, F&& f) {
  (f(std::type_identity<Q>{}), ...);
}

std::vector<std::string> rule_names() {
  std::vector<std::string> names;
  for_each_rule(rules{}, [&]<class Q>(std::type_identity<Q>) { names.emplace_back(Q::name); });
  return names;
}

template <class Q, class G>
discrete_model make_model(const particle_set<2>& particles, const background_mesh& mesh) {
  return build_discrete_model<kernel_type, correction_type, Q, G>(particles, mesh);
}

// ---------------------------------------------------------------------------------------
// The patch
// ---------------------------------------------------------------------------------------
// 9 x 9 particles on [0, 1.6] x [0, 2] mm; the particles are the nodes of the background cells.
// Every interior particle (and with it the cell node it is) is moved by up to 20% of the
// spacing, in a fixed pseudo-random pattern, so that no symmetry of the grid can hide a
// violation. Read in plane strain it is a block; read in axisymmetry, a section of revolution
// about x = 0, whose left edge lies on the axis.
struct body {
  particle_set<2> particles;
  background_mesh mesh;
};

body jittered_patch(double fraction = 0.2) {
  const vec2 lo(0.0, 0.0), hi(1.6e-3, 2.0e-3);
  const Eigen::Vector2i n(9, 9);
  const vec2 h((hi - lo)[0] / (n[0] - 1), (hi - lo)[1] / (n[1] - 1));
  body b{make_grid_particles<2>(lo, hi, n, support_factor), make_grid_mesh(lo, hi, n)};
  std::vector<char> on_boundary(b.mesh.node.size(), 0);
  for (index_t i : b.mesh.boundary_nodes()) on_boundary[i] = 1;
  for (index_t i = 0; i < static_cast<index_t>(b.mesh.node.size()); ++i) {
    if (on_boundary[i]) continue;
    const vec2 shift(fraction * h[0] * std::sin(1.7 * i + 0.3), fraction * h[1] * std::cos(2.3 * i + 0.1));
    b.mesh.node[i] += shift;
    b.particles.position[i] += shift;
  }
  return b;
}

// The cells as gnuplot line data (mm): each cell a closed polygon, cells separated by a blank line.
void write_cells(const fs::path& path, const background_mesh& mesh) {
  std::ofstream f(path);
  for (const auto& c : mesh.cell) {
    for (int k = 0; k <= 4; ++k) {
      const vec2& X = mesh.node[c[k % 4]];
      f << 1e3 * X[0] << ',' << 1e3 * X[1] << '\n';
    }
    f << '\n';
  }
}

// ---------------------------------------------------------------------------------------
// Part 1: the integration constraint, particle by particle
// ---------------------------------------------------------------------------------------
// b_I comes from Gauss points on the boundary edges of the cells (5 per edge, the boundary
// rule VCI itself uses; edges on the axis weigh nothing in axisymmetry). The residual r_I is
// the left side minus b_I; measure_integration_constraint also returns a scale per particle,
// the sum of the magnitudes of the terms that make up r_I, so that |r_I| / scale_I is a
// relative violation, 1e-16 meaning "exact to round-off". The gradients measured are those the
// internal force is scattered with: the trial gradients grad N_I for a plain rule, the
// corrected ones for a VCI rule (discrete_model::test_gradients()).
//
// Each rule is held to b_I as it integrates the boundary itself: 5 Gauss points per boundary
// edge for the cell rules (the rule VCI uses), and for scni the points its smoothing cells place
// on the boundary (3 per half edge, make_split_boundary_points). Both are approximations of
// the exact b_I (N_I is rational); part 1 also prints how far scni's b_I is from the 5-point one.
template <class Q, class G>
std::vector<vec2> rule_boundary_integrals(const discrete_model& m) {
  if constexpr (NodalRule<Q>) {
    const boundary_points bp = make_split_boundary_points<G>(m.mesh, Q::edge_points);
    return boundary_integrals(
        build_shape_table<kernel_type, correction_type, 2>(neighbor_search<2>(m.particles), bp.position), bp,
        m.particle_count());
  } else {
    return boundary_integrals<kernel_type, correction_type, G>(m.particles, m.mesh, 5);
  }
}

template <class G>
std::vector<double> relative_violation(const discrete_model& m, const std::vector<vec2>& boundary_integral) {
  const integration_constraint c =
      measure_integration_constraint(m.points, m.at_points, m.test_gradients(), boundary_integral, G::is_axisymmetric);
  std::vector<double> e(c.residual.size());
  for (std::size_t I = 0; I < e.size(); ++I) e[I] = c.residual[I].cwiseAbs().maxCoeff() / c.scale[I];
  return e;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

template <class G>
void constraint_of_geometry(const fs::path& out, const body& b, const std::string& tag) {
  const std::vector<vec2> five_point = boundary_integrals<kernel_type, correction_type, G>(b.particles, b.mesh, 5);
  std::map<std::string, std::vector<double>> violation;
  std::string other_boundary_rule;
  for_each_rule(rules{}, [&]<class Q>(std::type_identity<Q>) {
    const discrete_model m = make_model<Q, G>(b.particles, b.mesh);
    violation[std::string(Q::name)] = relative_violation<G>(m, rule_boundary_integrals<Q, G>(m));
    if constexpr (NodalRule<Q>) {
      const auto e = relative_violation<G>(m, five_point);
      other_boundary_rule += fmt::format("  {} against b_I of 5 points per whole edge: worst {:.2e}, median {:.2e}\n",
                                         Q::name, *std::max_element(e.begin(), e.end()), median(e));
    }
  });

  const auto names = rule_names();
  std::vector<std::string> columns{"x_mm", "y_mm"};
  columns.insert(columns.end(), names.begin(), names.end());
  const fs::path csv_path = out / fmt::format("constraint_{}.csv", tag);
  {
    io::csv_writer csv(csv_path, columns);
    for (index_t I = 0; I < b.particles.size(); ++I) {
      std::vector<double> row{1e3 * b.particles.position[I][0], 1e3 * b.particles.position[I][1]};
      for (const auto& n : names) row.push_back(violation[n][I]);
      csv.row(row);
    }
  }
  std::cout << fmt::format("\n  {} ({} particles)\n  {:<10} {:>12} {:>12}\n", G::name, b.particles.size(), "rule",
                           "worst", "median");
  for (const auto& n : names)
    std::cout << fmt::format("  {:<10} {:>12.2e} {:>12.2e}\n", n, *std::max_element(violation[n].begin(), violation[n].end()),
                             median(violation[n]));
  std::cout << other_boundary_rule;

  // One panel per rule: the cells, and each particle coloured by log10 of its violation
  // (a violation below 1e-17 is drawn at -17). The colour scale is the same in every panel.
  std::string script = fmt::format(R"(
set datafile separator ','
set multiplot layout 2,4 title '{}: integration-constraint violation |r_I| / scale_I per particle (log10), 9 x 9 jittered particles'
set size ratio -1
set palette defined (-17 '#203080', -13 '#4090e0', -9 '#60c0a0', -4 '#c0e060', -3 '#f0d020', -2 '#f08020', -1 '#d02010', 0 '#600000')
set cbrange [-17:0]
set cbtics 2
set xrange [-0.15:1.75]
set yrange [-0.15:2.15]
set xtics 0.4
set ytics 0.4
unset key
v(x) = x > 1e-17 ? log10(x) : -17
)",
                                   G::is_axisymmetric ? "Axisymmetric" : "Plane strain");
  for (std::size_t k = 0; k < names.size(); ++k) {
    const auto& e = violation[names[k]];
    script += fmt::format(
        "set title '{} (worst {:.1e})' noenhanced\n"
        "plot '{}' using 1:2 with lines lc rgb '#b0b0b0' notitle, '{}' skip 1 using 1:2:(v(column({}))) with points pt 7 "
        "ps 1.6 lc palette notitle\n",
        names[k], *std::max_element(e.begin(), e.end()), (out / "cells.dat").string(), csv_path.string(), k + 3);
  }
  script += "unset multiplot\n";
  io::gnuplot_png(out / fmt::format("constraint_{}.png", tag), script, {.width = 1600, .height = 1000});
}

void part1_constraint(const fs::path& out, const body& b) {
  std::cout << "\nPart 1: integration-constraint violation max_I |r_I| / scale_I on 9 x 9 jittered particles\n";
  write_cells(out / "cells.dat", b.mesh);
  constraint_of_geometry<geometry::plane_strain>(out, b, "plane_strain");
  constraint_of_geometry<geometry::axisymmetric>(out, b, "axisymmetric");
}

// ---------------------------------------------------------------------------------------
// Part 2: the linear patch test
// ---------------------------------------------------------------------------------------
// A linear displacement u(X) = A X + c is reproduced exactly by the linearly corrected RK
// functions, so with coefficients d_J = u(X_J) the strain is the same at every point and the
// stress sigma is homogeneous. The internal force is then f_I = sum_q [sigma g_I + sigma_tt e_r
// N_I / R_q] w_q, and the exact integral gives sigma b_I: zero for a particle whose support
// does not reach the boundary, the boundary traction's share where it does. We compute f_I with
// the solver's own force loop (apply_elastic_stiffness: the small-strain stress at each point,
// scattered with discrete_model::test_gradients(), the traversal the explicit step uses). In
// axisymmetry the homogeneous state in equilibrium is u = (a r, b z + c), for which
// sigma_rr = sigma_tt.
struct patch_result {
  double interior = 0.0;  // max over particles with b_I = 0 of |f_I| / (|sigma| scale_I)
  double all = 0.0;       // max over all particles of |f_I - sigma b_I| / (|sigma| scale_I)
  int interior_count = 0;
};

const material::elastic_constants steel{200e9, 0.3, 7800.0};

template <class Q, class G>
patch_result patch_test(const body& b) {
  const discrete_model m = make_model<Q, G>(b.particles, b.mesh);
  const std::vector<vec2> bI = rule_boundary_integrals<Q, G>(m);
  mat2 A;
  if constexpr (G::is_axisymmetric) A << 0.012, 0.0, 0.0, -0.007;
  else A << 0.012, -0.004, 0.009, -0.007;
  const vec2 c(G::is_axisymmetric ? 0.0 : 1e-6, 2e-6);
  std::vector<vec2> d(m.particle_count()), f(m.particle_count());
  for (index_t J = 0; J < m.particle_count(); ++J) d[J] = A * m.particles.position[J] + c;
  apply_elastic_stiffness<G>(m, steel, d, f);

  // The homogeneous stress: eps = sym(A), eps_33 = a in axisymmetry (u_r / r), 0 in plane strain.
  const mat2 eps = 0.5 * (A + A.transpose());
  const double tr = eps.trace() + (G::is_axisymmetric ? A(0, 0) : 0.0);
  const mat2 sigma = steel.lame_lambda() * tr * mat2::Identity() + 2.0 * steel.shear_modulus() * eps;
  const double sigma_scale = sigma.cwiseAbs().maxCoeff();
  const auto scale = measure_integration_constraint(m.points, m.at_points, m.test_gradients(), bI, G::is_axisymmetric).scale;
  patch_result r;
  for (index_t I = 0; I < m.particle_count(); ++I) {
    const double s = sigma_scale * scale[I];
    r.all = std::max(r.all, (f[I] - sigma * bI[I]).cwiseAbs().maxCoeff() / s);
    if (bI[I].isZero(0.0)) {
      r.interior = std::max(r.interior, f[I].cwiseAbs().maxCoeff() / s);
      ++r.interior_count;
    }
  }
  return r;
}

template <class G>
std::map<std::string, patch_result> patch_of_geometry(const body& b) {
  std::map<std::string, patch_result> r;
  for_each_rule(rules{}, [&]<class Q>(std::type_identity<Q>) { r[std::string(Q::name)] = patch_test<Q, G>(b); });
  return r;
}

void part2_patch_test(const fs::path& out, const body& b) {
  const auto ps = patch_of_geometry<geometry::plane_strain>(b);
  const auto ax = patch_of_geometry<geometry::axisymmetric>(b);
  std::cout << fmt::format(
      "\nPart 2: linear patch test on the same particles; force relative to |sigma| scale_I\n"
      "  interior: max |f_I| over the particles whose support misses the boundary ({} in plane strain, {} "
      "axisymmetric);\n  all: max |f_I - sigma b_I| over every particle\n",
      ps.at("q2").interior_count, ax.at("q2").interior_count);
  std::cout << fmt::format("  {:<10} {:>20} {:>20} {:>20} {:>20}\n", "rule", "plane strain interior", "plane strain all",
                           "axisym. interior", "axisym. all");
  // CSV holds numbers only: rule_index counts the rules in the order printed (rule_names()).
  io::csv_writer csv(out / "patch_test.csv",
                     {"rule_index", "plane_strain_interior", "plane_strain_all", "axisymmetric_interior", "axisymmetric_all"});
  int k = 0;
  for (const auto& n : rule_names()) {
    const auto &p = ps.at(n), &a = ax.at(n);
    std::cout << fmt::format("  {:<10} {:>20.2e} {:>20.2e} {:>20.2e} {:>20.2e}\n", n, p.interior, p.all, a.interior, a.all);
    csv.row({double(k++), p.interior, p.all, a.interior, a.all});
  }
}

// ---------------------------------------------------------------------------------------
// Part 3: convergence
// ---------------------------------------------------------------------------------------
// Static, small-strain problems solved with the stiffness of the same force loop. K is probed
// column by column, K e_J = apply_elastic_stiffness(e_J); columns whose particles share no
// quadrature point with a common particle cannot overlap in any row, so they are probed
// together (a greedy colouring), and a few dozen force evaluations give all of K. Values of
// the displacement at particles, u_h(X_I) = sum_J N_J(X_I) d_J = value, are imposed with
// Lagrange multipliers; Eigen's SparseLU solves the whole system.
//
//   manufactured  plane strain, unit square, u a cubic polynomial (not reproduced by the
//                 linear basis), loaded by its body force -div sigma (integrated with q9,
//                 whatever the rule tested, so that only the stiffness changes) and by
//                 consistent tractions sum_b N_I sigma n w_b on the boundary (the boundary
//                 points of part 1); three values remove the rigid motions. The error is the
//                 approximation's plus the rule's, nothing else.
//   expansion     axisymmetric cylinder R0 = 3.2 mm, height 6.4 mm (the section of
//                 tests/numeric/axisymmetric_expansion.cpp, copper), uniform expansion
//                 u = (e r, 0), with the essential conditions of that dynamic test: u_r = e R0 on
//                 the outer radius, u_z = 0 on both ends, u_r = 0 on the axis, imposed on the
//                 physical values at those particles. Its exact solution is linear, which every
//                 rule would reproduce if the equations were consistent; what remains is the
//                 price of the conditions and of the rule.
// Error: max_I |u_h(X_I) - u(X_I)| / max |u| (the manufactured one modulo a rigid motion), at
// 9, 17 and 33 particles per side; the observed order between two resolutions is
// log2(e_coarse / e_fine) (h halves).
template <class G>
Eigen::SparseMatrix<double> sparse_stiffness(const discrete_model& m, const material::elastic_constants& c) {
  const index_t n = m.particle_count();
  std::vector<std::vector<index_t>> touches(n);  // particles sharing a point with I
  for (index_t q = 0; q < m.point_count(); ++q)
    for (index_t a = m.at_points.offset[q]; a < m.at_points.offset[q + 1]; ++a)
      for (index_t e = m.at_points.offset[q]; e < m.at_points.offset[q + 1]; ++e)
        touches[m.at_points.neighbor[a]].push_back(m.at_points.neighbor[e]);
  for (auto& t : touches) {
    std::sort(t.begin(), t.end());
    t.erase(std::unique(t.begin(), t.end()), t.end());
  }
  std::vector<int> colour(n, -1);
  int colours = 0;
  for (index_t J = 0; J < n; ++J) {
    std::vector<char> taken(colours + 1, 0);
    for (index_t I : touches[J])
      for (index_t J2 : touches[I])
        if (colour[J2] >= 0) taken[colour[J2]] = 1;
    int k = 0;
    while (taken[k]) ++k;
    colour[J] = k;
    colours = std::max(colours, k + 1);
  }
  std::vector<Eigen::Triplet<double>> entries;
  std::vector<vec2> x(n), kx(n);
  for (int col = 0; col < colours; ++col)
    for (int k = 0; k < 2; ++k) {
      for (index_t J = 0; J < n; ++J) x[J] = colour[J] == col ? vec2(vec2::Unit(k)) : vec2(vec2::Zero());
      apply_elastic_stiffness<G>(m, c, x, kx);
      for (index_t J = 0; J < n; ++J)
        if (colour[J] == col)
          for (index_t I : touches[J])
            for (int i = 0; i < 2; ++i)
              if (kx[I][i] != 0.0) entries.emplace_back(2 * I + i, 2 * J + k, kx[I][i]);
    }
  Eigen::SparseMatrix<double> K(2 * n, 2 * n);
  K.setFromTriplets(entries.begin(), entries.end());
  return K;
}

struct value_row {
  index_t particle;
  int direction;
  double value;
};

std::vector<vec2> solve(const discrete_model& m, const Eigen::SparseMatrix<double>& K, const Eigen::VectorXd& f,
                        const std::vector<value_row>& rows) {
  const index_t nd = K.rows(), nr = static_cast<index_t>(rows.size());
  double scale = 0.0;  // multiplier rows scaled like K
  std::vector<Eigen::Triplet<double>> t;
  for (index_t j = 0; j < K.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(K, j); it; ++it) {
      t.emplace_back(it.row(), it.col(), it.value());
      scale = std::max(scale, std::abs(it.value()));
    }
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(nd + nr);
  rhs.head(nd) = f;
  for (index_t r = 0; r < nr; ++r) {
    const auto& row = rows[r];
    for (index_t e = m.at_particles.offset[row.particle]; e < m.at_particles.offset[row.particle + 1]; ++e) {
      const index_t col = 2 * m.at_particles.neighbor[e] + row.direction;
      t.emplace_back(nd + r, col, scale * m.at_particles.N[e]);
      t.emplace_back(col, nd + r, scale * m.at_particles.N[e]);
    }
    rhs[nd + r] = scale * row.value;
  }
  Eigen::SparseMatrix<double> A(nd + nr, nd + nr);
  A.setFromTriplets(t.begin(), t.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu(A);
  if (lu.info() != Eigen::Success) fail("static solve: the factorization failed ({})", lu.lastErrorMessage());
  const Eigen::VectorXd x = lu.solve(rhs);
  std::vector<vec2> d(m.particle_count());
  for (index_t I = 0; I < m.particle_count(); ++I) d[I] = x.segment<2>(2 * I);
  return d;
}

template <class Exact>
double max_error(const discrete_model& m, const std::vector<vec2>& d, Exact&& exact, bool modulo_rigid) {
  const index_t n = m.particle_count();
  Eigen::MatrixXd rigid(2 * n, 3);
  Eigen::VectorXd r(2 * n);
  double scale = 0.0;
  for (index_t I = 0; I < n; ++I) {
    const vec2& X = m.particles.position[I];
    r.segment<2>(2 * I) = m.at_particles.interpolate(I, d) - exact(X);
    rigid.row(2 * I) << 1, 0, -X[1];
    rigid.row(2 * I + 1) << 0, 1, X[0];
    scale = std::max(scale, exact(X).norm());
  }
  if (modulo_rigid) r -= rigid * rigid.colPivHouseholderQr().solve(r);
  double e = 0.0;
  for (index_t I = 0; I < n; ++I) e = std::max(e, r.segment<2>(2 * I).norm());
  return e / scale;
}

// The cubic field, its gradient, stress and body force in closed form.
vec2 cubic_field(const vec2& X) {
  const double x = X[0], y = X[1];
  return 1e-3 * vec2(x * x * y + 0.5 * y * y * y - 0.7 * x * x * x + 0.3 * x * y,
                     -0.4 * x * x * x + 0.4 * x * y * y + 0.2 * y * y);
}
mat2 cubic_stress(const vec2& X) {
  const double x = X[0], y = X[1];
  mat2 g;  // grad u
  g << 2 * x * y - 2.1 * x * x + 0.3 * y, x * x + 1.5 * y * y + 0.3 * x, -1.2 * x * x + 0.4 * y * y, 0.8 * x * y + 0.4 * y;
  const mat2 e = 0.5e-3 * (g + g.transpose());
  return steel.lame_lambda() * e.trace() * mat2::Identity() + 2.0 * steel.shear_modulus() * e;
}
vec2 cubic_body_force(const vec2& X) {
  // -div sigma = -(mu lap u + (lambda + mu) grad div u)
  const double x = X[0], y = X[1];
  const vec2 lap = 1e-3 * vec2(5 * y - 4.2 * x, -1.6 * x + 0.4);
  const vec2 grad_div = 1e-3 * vec2(2.8 * y - 4.2 * x, 2.8 * x + 0.7);
  return -(steel.shear_modulus() * lap + (steel.lame_lambda() + steel.shear_modulus()) * grad_div);
}

// Loads that do not depend on the rule: consistent tractions on the boundary points, and the
// body force integrated with q9.
Eigen::VectorXd manufactured_load(const particle_set<2>& p, const background_mesh& mesh) {
  using G = geometry::plane_strain;
  Eigen::VectorXd f = Eigen::VectorXd::Zero(2 * p.size());
  const boundary_points bp = make_boundary_points<G>(mesh, 5);
  const neighbor_search<2> search(p);
  const shape_table<2> at_boundary = build_shape_table<kernel_type, correction_type, 2>(search, bp.position);
  for (index_t b = 0; b < bp.size(); ++b) {
    const vec2 t = cubic_stress(bp.position[b]) * bp.normal[b] * bp.weight[b];
    for (index_t e = at_boundary.offset[b]; e < at_boundary.offset[b + 1]; ++e)
      f.segment<2>(2 * at_boundary.neighbor[e]) += at_boundary.N[e] * t;
  }
  const discrete_model fine = make_model<quadrature::q9, G>(p, mesh);
  for (index_t q = 0; q < fine.point_count(); ++q) {
    const vec2 load = cubic_body_force(fine.points.position[q]) * fine.points.weight[q];
    for (index_t e = fine.at_points.offset[q]; e < fine.at_points.offset[q + 1]; ++e)
      f.segment<2>(2 * fine.at_points.neighbor[e]) += fine.at_points.N[e] * load;
  }
  return f;
}

template <class Q>
double manufactured_error(const particle_set<2>& p, const background_mesh& mesh, const Eigen::VectorXd& f, int n) {
  using G = geometry::plane_strain;
  const discrete_model m = make_model<Q, G>(p, mesh);
  const auto d = solve(m, sparse_stiffness<G>(m, steel), f, {{0, 0, 0.0}, {0, 1, 0.0}, {n - 1, 1, 0.0}});
  return max_error(m, d, cubic_field, true);
}

const material::elastic_constants copper{117e9, 0.35, 8930.0};

// The expansion twice: with the collocated conditions above, and with consistent tractions
// instead (the exact stress sigma_rr = sigma_tt = 2 (lambda + mu) e, sigma_zz = 2 lambda e on
// the boundary points, only u_r = 0 on the axis and one u_z value held), which takes the
// conditions out of the comparison.
struct expansion_errors {
  double collocated = 0.0, traction = 0.0;
};

template <class Q>
expansion_errors expansion_error(int n) {
  using G = geometry::axisymmetric;
  const double R0 = 3.2e-3, Lz = 6.4e-3, e = 1e-3;
  const Eigen::Vector2i counts(n, n);
  const discrete_model m = make_model<Q, G>(make_grid_particles<2>(vec2(0, 0), vec2(R0, Lz), counts, support_factor),
                                            make_grid_mesh(vec2(0, 0), vec2(R0, Lz), counts));
  std::vector<value_row> collocated, axis;
  for (index_t I = 0; I < m.particle_count(); ++I) {
    const vec2& X = m.particles.position[I];
    if (X[0] == 0.0) collocated.push_back({I, 0, 0.0});
    if (X[0] == R0) collocated.push_back({I, 0, e * R0});
    if (X[1] == 0.0 || X[1] == Lz) collocated.push_back({I, 1, 0.0});
    if (X[0] == 0.0) axis.push_back({I, 0, 0.0});
  }
  axis.push_back({0, 1, 0.0});
  const auto K = sparse_stiffness<G>(m, copper);
  const auto exact = [e](const vec2& X) { return vec2(e * X[0], 0.0); };
  expansion_errors r;
  r.collocated = max_error(m, solve(m, K, Eigen::VectorXd::Zero(2 * m.particle_count()), collocated), exact, false);

  mat2 sigma;
  sigma << 2.0 * (copper.lame_lambda() + copper.shear_modulus()) * e, 0.0, 0.0, 2.0 * copper.lame_lambda() * e;
  const boundary_points bp = make_boundary_points<G>(m.mesh, 5);
  const shape_table<2> at_boundary =
      build_shape_table<kernel_type, correction_type, 2>(neighbor_search<2>(m.particles), bp.position);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(2 * m.particle_count());
  for (index_t b = 0; b < bp.size(); ++b)
    for (index_t k = at_boundary.offset[b]; k < at_boundary.offset[b + 1]; ++k)
      f.segment<2>(2 * at_boundary.neighbor[k]) += at_boundary.N[k] * (sigma * bp.normal[b] * bp.weight[b]);
  r.traction = max_error(m, solve(m, K, f, axis), exact, false);
  return r;
}

std::string rates(const std::vector<double>& e) {
  std::string s;
  for (std::size_t k = 1; k < e.size(); ++k) s += fmt::format("{}{:5.2f}", k > 1 ? ", " : "", std::log2(e[k - 1] / e[k]));
  return s;
}

void part3_convergence(const fs::path& out) {
  const std::vector<int> resolutions{9, 17, 33};
  const auto names = rule_names();
  std::map<std::string, std::vector<double>> manufactured, expansion, expansion_traction;
  for (int n : resolutions) {
    const Eigen::Vector2i counts(n, n);
    const auto p = make_grid_particles<2>(vec2(0, 0), vec2(1, 1), counts, support_factor);
    const auto mesh = make_grid_mesh(vec2(0, 0), vec2(1, 1), counts);
    const Eigen::VectorXd f = manufactured_load(p, mesh);
    for_each_rule(rules{}, [&]<class Q>(std::type_identity<Q>) {
      manufactured[std::string(Q::name)].push_back(manufactured_error<Q>(p, mesh, f, n));
      const expansion_errors e = expansion_error<Q>(n);
      expansion[std::string(Q::name)].push_back(e.collocated);
      expansion_traction[std::string(Q::name)].push_back(e.traction);
    });
  }

  std::cout << "\nPart 3: static convergence, max_I |u_h - u| / max |u| at 9, 17, 33 particles per side "
               "(observed orders)\n";
  std::cout << fmt::format("  {:<10} {:>34}   {:>12}   {:>34}   {:>12}\n", "rule", "manufactured (plane strain)", "orders",
                           "expansion, collocated (axisym.)", "orders");
  for (const auto& n : names) {
    const auto &a = manufactured[n], &b = expansion[n];
    std::cout << fmt::format("  {:<10} {:>10.3e} {:>10.3e} {:>10.3e}   {:>12}   {:>10.3e} {:>10.3e} {:>10.3e}   {:>12}\n", n,
                             a[0], a[1], a[2], rates(a), b[0], b[1], b[2], rates(b));
  }
  std::cout << "  the expansion again, with consistent tractions instead of the collocated conditions:\n";
  for (const auto& n : names) {
    const auto& c = expansion_traction[n];
    std::cout << fmt::format("  {:<10} {:>10.3e} {:>10.3e} {:>10.3e}\n", n, c[0], c[1], c[2]);
  }
  // The ratio the issue asked about: q2+vci against q4.
  std::cout << "  q2+vci / q4:  manufactured";
  for (std::size_t k = 0; k < resolutions.size(); ++k)
    std::cout << fmt::format(" {:.2f}", manufactured["q2+vci"][k] / manufactured["q4"][k]);
  std::cout << ";  expansion";
  for (std::size_t k = 0; k < resolutions.size(); ++k)
    std::cout << fmt::format(" {:.2f}", expansion["q2+vci"][k] / expansion["q4"][k]);
  std::cout << "\n";

  std::vector<std::string> columns{"n", "h"};
  for (const auto& n : names) columns.push_back("manufactured_" + n);
  for (const auto& n : names) columns.push_back("expansion_" + n);
  for (const auto& n : names) columns.push_back("expansion_traction_" + n);
  const fs::path csv_path = out / "convergence.csv";
  {
    io::csv_writer csv(csv_path, columns);
    for (std::size_t k = 0; k < resolutions.size(); ++k) {
      std::vector<double> row{double(resolutions[k]), 1.0 / (resolutions[k] - 1)};
      for (const auto& n : names) row.push_back(manufactured[n][k]);
      for (const auto& n : names) row.push_back(expansion[n][k]);
      for (const auto& n : names) row.push_back(expansion_traction[n][k]);
      csv.row(row);
    }
  }
  // Log-log, error against h / side length, with slopes 1 and 2 for reference; the plain cell
  // rules dashed, the VCI rules solid.
  auto panel = [&](const std::string& title, int first_column, double anchor) {
    std::string s = fmt::format("set title '{}' noenhanced\nplot ", title);
    for (std::size_t k = 0; k < names.size(); ++k)
      s += fmt::format("'{}' skip 1 using 2:{} with linespoints lw 2 pt 7 ps 1.2 dt {} title '{}' noenhanced, \\\n  ",
                       csv_path.string(), first_column + k, names[k].find("vci") != std::string::npos ? 1 : 2,
                       names[k]);
    return s + fmt::format("{:g}*x title 'slope 1' lc rgb '#909090' dt 3, {:g}*x**2 title 'slope 2' lc rgb '#909090' dt 4\n",
                           anchor, 4 * anchor);
  };
  std::string script = R"(
set datafile separator ','
set multiplot layout 1,2 title 'Static convergence: max |u_h - u| / max |u| against h (9, 17, 33 particles per side)'
set logscale xy
set format y '10^{%L}'
set xlabel 'h / side length'
set ylabel 'relative error'
set xrange [0.025:0.16]
set xtics ('1/32' 0.03125, '1/16' 0.0625, '1/8' 0.125)
set grid
set key bottom right font ',9'
)";
  script += panel("manufactured cubic field, plane strain, consistent tractions", 3, 0.05);
  script += panel("uniform expansion, axisymmetric, collocated conditions", 3 + static_cast<int>(names.size()), 0.1);
  script += "unset multiplot\n";
  io::gnuplot_png(out / "convergence.png", script, {.width = 1500, .height = 650});
}

// ---------------------------------------------------------------------------------------
// Part 4: what a step costs
// ---------------------------------------------------------------------------------------
// As in tutorial 02: the Taylor bar (cases/taylor_bar.hpp, 21 x 51 particles, axisymmetric,
// J2 plasticity, the paper's contact), built by make_solver for each rule; 100 steps into the
// impact, then 200 timed steps on one thread, process CPU time. The solver type is the same for
// every rule (solver_for<Config> depends on geometry, material and contact only), so this part
// compiles one time loop. The set-up time (make_solver: shape tables, masses and, for VCI, the
// boundary integrals and the corrected gradients) is measured too. With --taylor-bar each run
// goes on to the end (80 us), for the final radius and height of every rule; the runner gives
// the same numbers for the rules it takes (tools/rkpm paper --cases taylor_bar, README.md).
using bar_case = cases::taylor_bar;
using wall = contact::particle_to_segment<contact::enforcement::paper, contact::friction::frictionless>;
template <class Q>
using bar_method = config<kernel_type, correction_type, Q, bar_case::geometry_type, bar_case::material_type, wall>;

struct step_timing {
  std::string rule;
  index_t points = 0;
  double setup_ms = 0.0;  // CPU time of make_solver
  double cpu_ms_per_step = 0.0;
  double dt = 0.0;  // the mean step over the timed steps (s)
  // With --taylor-bar: the whole run (80 us).
  index_t steps = 0;
  double run_cpu_s = 0.0, radius_mm = 0.0, height_mm = 0.0, max_plastic_strain = 0.0, balance_error = 0.0;
};

template <class Q>
step_timing time_steps(bool full_run) {
  step_timing t{std::string(Q::name)};
  run_options options;
  options.end_time = bar_case::end_time({});
  const std::clock_t setup_start = std::clock();
  auto s = make_solver<bar_method<Q>>(bar_case::build<wall>({}, 1), options);
  t.setup_ms = 1e3 * double(std::clock() - setup_start) / CLOCKS_PER_SEC;
  t.points = s.model().point_count();
  const std::clock_t run_start = std::clock();
  for (int k = 0; k < 100; ++k) s.step();
  const int steps = 200;
  const double t0 = s.time();
  const std::clock_t cpu_start = std::clock();
  for (int k = 0; k < steps; ++k) s.step();
  t.cpu_ms_per_step = 1e3 * double(std::clock() - cpu_start) / CLOCKS_PER_SEC / steps;
  t.dt = (s.time() - t0) / steps;
  if (full_run) {
    // On to the end time; the case's own measures (cases/taylor_bar.hpp), as the runner reports them.
    s.run();
    t.run_cpu_s = double(std::clock() - run_start) / CLOCKS_PER_SEC;
    t.steps = s.steps();
    for (const auto& [key, value] : bar_case::measure(s, {}, {})) {
      if (key == "radius_mm") t.radius_mm = value;
      if (key == "height_mm") t.height_mm = value;
      if (key == "max_equivalent_plastic_strain") t.max_plastic_strain = value;
    }
    t.balance_error = s.energy().balance_error();
  }
  return t;
}

void part4_cost(const fs::path& out, bool full_run) {
  std::cout << "\nPart 4: Taylor bar 21 x 51, 200 steps after 100, 1 thread, CPU time (indicative)\n";
  std::vector<step_timing> timings;
  for_each_rule(rules{}, [&]<class Q>(std::type_identity<Q>) { timings.push_back(time_steps<Q>(full_run)); });
  const double q2_time = timings.front().cpu_ms_per_step, q2_dt = timings.front().dt;
  std::cout << fmt::format("  {:<10} {:>7} {:>10} {:>12} {:>10} {:>14}\n", "rule", "points", "set-up ms", "CPU ms/step",
                           "/ q2", "mean dt / q2's");
  io::csv_writer csv(out / "cost.csv", {"rule_index", "points", "setup_ms", "cpu_ms_per_step", "relative_to_q2", "dt_s"});
  int k = 0;
  for (const auto& t : timings) {
    std::cout << fmt::format("  {:<10} {:>7} {:>10.0f} {:>12.3f} {:>10.2f} {:>14.3f}\n", t.rule, t.points, t.setup_ms,
                             t.cpu_ms_per_step, t.cpu_ms_per_step / q2_time, t.dt / q2_dt);
    csv.row({double(k++), double(t.points), t.setup_ms, t.cpu_ms_per_step, t.cpu_ms_per_step / q2_time, t.dt});
  }
  if (!full_run) return;
  std::cout << fmt::format("\n  the whole run (80 us), as tools/rkpm paper reports it:\n  {:<10} {:>11} {:>11} {:>9} {:>14} {:>7} "
                           "{:>8} {:>12}\n",
                           "rule", "radius mm", "height mm", "max eps_p", "energy error", "steps", "CPU s", "per step/q2");
  io::csv_writer bar(out / "taylor_bar.csv", {"rule_index", "radius_mm", "height_mm", "max_equivalent_plastic_strain",
                                               "balance_error", "steps", "cpu_s"});
  const double q2_per_step = timings.front().run_cpu_s / double(timings.front().steps);
  k = 0;
  for (const auto& t : timings) {
    std::cout << fmt::format("  {:<10} {:>11.3f} {:>11.3f} {:>9.2f} {:>14.2e} {:>7} {:>8.2f} {:>12.2f}\n", t.rule,
                             t.radius_mm, t.height_mm, t.max_plastic_strain, t.balance_error, t.steps, t.run_cpu_s,
                             t.run_cpu_s / double(t.steps) / q2_per_step);
    bar.row({double(k++), t.radius_mm, t.height_mm, t.max_plastic_strain, t.balance_error, double(t.steps), t.run_cpu_s});
  }
}

// ---------------------------------------------------------------------------------------
// main
// ---------------------------------------------------------------------------------------
int main(int argc, char** argv) {
  try {
    fs::path out = "results/08_integration";
    bool full_taylor_bar = false;
    for (int a = 1; a < argc; ++a) {
      const std::string arg = argv[a];
      if (arg == "--taylor-bar") full_taylor_bar = true;
      else if (arg.starts_with("--")) fail("unknown option '{}'; usage: tutorial_08_integration [output directory] [--taylor-bar]", arg);
      else out = arg;
    }
    fs::create_directories(out);
    // One thread throughout: the problems are small, so threads would only add start-up and
    // barrier costs (on a busy machine a two-thread run took 7 times longer), and part 4's CPU
    // time per step is then the cost of a step, whatever else the machine does.
#ifdef _OPENMP
    omp_set_num_threads(1);
#endif
    Eigen::setNbThreads(1);
    const auto start = std::chrono::steady_clock::now();
    const body patch = jittered_patch();
    part1_constraint(out, patch);
    part2_patch_test(out, patch);
    part3_convergence(out);
    part4_cost(out, full_taylor_bar);
    std::cout << fmt::format("\nwrote CSV and PNG files to {} ({:.1f} s)\n", out.string(),
                             std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  } catch (const std::exception& e) {
    std::cerr << "tutorial_08_integration: " << e.what() << "\n";
    return 1;
  }
}
