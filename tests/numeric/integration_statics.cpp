// Static convergence of every cell rule, with and without VCI, where the integration is the
// only error beyond the approximation (docs/method.md sections 3.4-3.5): small-strain elastic
// problems solved with the stiffness of the solver's own force loop (apply_elastic_stiffness,
// probed column by column and solved sparse), loaded by consistent boundary tractions
// sum_b N_I(X_b) sigma(X_b) n_b w_b (the boundary points of the VCI correction) and held only
// against rigid motion, so that no essential condition imposes a reaction:
//   manufactured  plane strain, a cubic displacement field on the unit square with the body
//                 force -div sigma (integrated with q9, whatever the rule tested)
//   lame          axisymmetric thick-walled cylinder under internal pressure, ends loaded by
//                 their uniform axial stress: u_r = A r + B / r, u_z = 0
//   expansion     the uniform expansion of numeric/axisymmetric_expansion.cpp (u_r = e r), with
//                 consistent tractions, and with the dynamic test's essential conditions:
//                 the physical values u_r(R0) = e R0 and u_z = 0 on the ends imposed by
//                 collocation (docs/method.md (50)); copper as in the dynamic test, whose errors
//                 these static ones reproduce to 2-3 digits (the run is a slow, quasi-static
//                 loading).
// Error: max_I |u_h(X_I) - u(X_I)| / max |u| (modulo a rigid motion in plane strain), at 9, 17
// and 33 particles per side (the expansion at 9 and 17). Theory: a rule that violates the integration constraint converges
// at first order only; VCI restores the second order of the linear basis and is exact for the
// linear field. What this shows about issue 10's claim (q2+vci at least as accurate as q4) is
// in numeric/integration_convergence.cpp.

#include <doctest/doctest.h>

#include <Eigen/Sparse>
#include <Eigen/SparseLU>
#include <algorithm>

#include "support/solver_fixtures.hpp"

namespace test_numeric_integration_statics {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

namespace {

using K = kernel::cubic_spline;
using C = correction::linear;
const material::elastic_constants steel = test::steel_like();
const material::elastic_constants copper{117e9, 0.35, 8930.0};  // as numeric/axisymmetric_expansion.cpp

// Sparse stiffness of the force loop. Columns J whose rows cannot overlap (no particle shares a
// quadrature point with both) are probed together; greedy colouring over the point graph.
template <class G>
Eigen::SparseMatrix<double> sparse_stiffness(const discrete_model& m, const material::elastic_constants& constants = steel) {
  const index_t n = m.particle_count();
  std::vector<std::vector<index_t>> touches(n);  // particles sharing a point with I (I included)
  for (index_t q = 0; q < m.point_count(); ++q)
    for (index_t a = m.at_points.offset[q]; a < m.at_points.offset[q + 1]; ++a)
      for (index_t b = m.at_points.offset[q]; b < m.at_points.offset[q + 1]; ++b)
        touches[m.at_points.neighbor[a]].push_back(m.at_points.neighbor[b]);
  for (auto& t : touches) {
    std::sort(t.begin(), t.end());
    t.erase(std::unique(t.begin(), t.end()), t.end());
  }
  std::vector<int> colour(n, -1);
  std::vector<char> taken;
  int colours = 0;
  for (index_t J = 0; J < n; ++J) {
    taken.assign(static_cast<std::size_t>(colours) + 1, 0);
    for (index_t I : touches[J])
      for (index_t J2 : touches[I])
        if (colour[J2] >= 0) taken[colour[J2]] = 1;
    int c = 0;
    while (taken[c]) ++c;
    colour[J] = c;
    colours = std::max(colours, c + 1);
  }
  std::vector<Eigen::Triplet<double>> entries;
  std::vector<vec2> x(n), kx(n);
  for (int c = 0; c < colours; ++c)
    for (int k = 0; k < 2; ++k) {
      for (index_t J = 0; J < n; ++J) x[J] = colour[J] == c ? vec2(vec2::Unit(k)) : vec2(vec2::Zero());
      apply_elastic_stiffness<G>(m, constants, x, kx);
      for (index_t J = 0; J < n; ++J)
        if (colour[J] == c)
          for (index_t I : touches[J])
            for (int i = 0; i < 2; ++i)
              if (kx[I][i] != 0.0) entries.emplace_back(2 * I + i, 2 * J + k, kx[I][i]);
    }
  Eigen::SparseMatrix<double> Kmat(2 * n, 2 * n);
  Kmat.setFromTriplets(entries.begin(), entries.end());
  return Kmat;
}

// Physical value rows: component `direction` of u at particle `particle` equals `value`.
struct value_row {
  index_t particle;
  int direction;
  double value;
};

// Coefficients d of K d = f under the rows (Lagrange multipliers, rows scaled like K).
std::vector<vec2> solve(const discrete_model& m, const Eigen::SparseMatrix<double>& Kmat, const Eigen::VectorXd& f,
                        const std::vector<value_row>& rows) {
  const index_t nd = Kmat.rows(), nr = static_cast<index_t>(rows.size());
  double scale = 0.0;
  for (index_t j = 0; j < Kmat.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(Kmat, j); it; ++it) scale = std::max(scale, std::abs(it.value()));
  std::vector<Eigen::Triplet<double>> t;
  for (index_t j = 0; j < Kmat.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(Kmat, j); it; ++it) t.emplace_back(it.row(), it.col(), it.value());
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
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::AMDOrdering<int>> lu(A);
  REQUIRE(lu.info() == Eigen::Success);
  const Eigen::VectorXd x = lu.solve(rhs);
  std::vector<vec2> d(m.particle_count());
  for (index_t I = 0; I < m.particle_count(); ++I) d[I] = x.segment<2>(2 * I);
  return d;
}

// Consistent traction load sum_b N_I sigma n w for a stress field sigma(X).
template <class G, class Stress>
Eigen::VectorXd traction_load(const discrete_model& m, Stress&& sigma) {
  const auto bp = make_boundary_points<G>(m.mesh, 5);
  const auto table = build_shape_table<K, C, 2>(neighbor_search<2>(m.particles), bp.position);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(2 * m.particle_count());
  for (index_t b = 0; b < bp.size(); ++b) {
    const vec2 t = sigma(bp.position[b]) * bp.normal[b] * bp.weight[b];
    for (index_t e = table.offset[b]; e < table.offset[b + 1]; ++e) f.segment<2>(2 * table.neighbor[e]) += table.N[e] * t;
  }
  return f;
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

// ---- the problems ---------------------------------------------------------------------------
vec2 cubic_field(const vec2& X) {
  const double x = X[0], y = X[1];
  return 1e-3 * vec2(x * x * y + 0.5 * y * y * y - 0.7 * x * x * x + 0.3 * x * y,
                     -0.4 * x * x * x + 0.4 * x * y * y + 0.2 * y * y);
}
// Its gradient and stress in closed form; the body force -div sigma likewise.
mat2 cubic_gradient(const vec2& X) {
  const double x = X[0], y = X[1];
  mat2 g;
  g << 2 * x * y - 2.1 * x * x + 0.3 * y, x * x + 1.5 * y * y + 0.3 * x, -1.2 * x * x + 0.4 * y * y, 0.8 * x * y + 0.4 * y;
  return 1e-3 * g;
}
mat2 stress_of(const mat2& g) {
  const mat2 e = 0.5 * (g + g.transpose());
  return steel.lame_lambda() * e.trace() * mat2::Identity() + 2.0 * steel.shear_modulus() * e;
}
vec2 cubic_body_force(const vec2& X) {
  // div sigma = mu lap u + (lambda + mu) grad div u, from the second derivatives of the field.
  const double x = X[0], y = X[1];
  const vec2 lap = 1e-3 * vec2(2 * y - 4.2 * x + 3 * y, -2.4 * x + 0.8 * x + 0.4);
  const vec2 grad_div = 1e-3 * vec2(2.8 * y - 4.2 * x, 2.8 * x + 0.7);  // div u = 2.8 x y - 2.1 x^2 + 0.7 y
  return -(steel.shear_modulus() * lap + (steel.lame_lambda() + steel.shear_modulus()) * grad_div);
}

template <class Q>
double manufactured(int n) {
  using G = geometry::plane_strain;
  auto p = make_grid_particles<2>(vec2(0, 0), vec2(1, 1), Eigen::Vector2i(n, n), 2.0);
  auto mesh = make_grid_mesh(vec2(0, 0), vec2(1, 1), Eigen::Vector2i(n, n));
  const discrete_model m = build_discrete_model<K, C, Q, G>(p, mesh);
  const discrete_model load = build_discrete_model<K, C, quadrature::q9, G>(p, mesh);
  Eigen::VectorXd f = traction_load<G>(m, [](const vec2& X) { return stress_of(cubic_gradient(X)); });
  for (index_t q = 0; q < load.point_count(); ++q) {
    const vec2 b = cubic_body_force(load.points.position[q]) * load.points.weight[q];
    for (index_t e = load.at_points.offset[q]; e < load.at_points.offset[q + 1]; ++e)
      f.segment<2>(2 * load.at_points.neighbor[e]) += load.at_points.N[e] * b;
  }
  const auto d = solve(m, sparse_stiffness<G>(m), f, {{0, 0, 0.0}, {0, 1, 0.0}, {n - 1, 1, 0.0}});
  return max_error(m, d, cubic_field, true);
}

template <class Q>
double lame(int n) {
  using G = geometry::axisymmetric;
  const double Ri = 1e-3, Ro = 2e-3, Lz = 1e-3, p = 1e8;
  const double lam = steel.lame_lambda(), mu = steel.shear_modulus();
  const double C1 = p * Ri * Ri / (Ro * Ro - Ri * Ri), C2 = C1 * Ro * Ro;
  const double A = C1 / (2 * (lam + mu)), B = C2 / (2 * mu);
  const discrete_model m = build_discrete_model<K, C, Q, G>(make_grid_particles<2>(vec2(Ri, 0), vec2(Ro, Lz), Eigen::Vector2i(n, n), 2.0),
                                                            make_grid_mesh(vec2(Ri, 0), vec2(Ro, Lz), Eigen::Vector2i(n, n)));
  const auto f = traction_load<G>(m, [&](const vec2& X) {
    mat2 s;
    s << C1 - C2 / (X[0] * X[0]), 0, 0, 2 * lam * A;
    return s;
  });
  const auto d = solve(m, sparse_stiffness<G>(m), f, {{0, 1, 0.0}});
  return max_error(m, d, [&](const vec2& X) { return vec2(A * X[0] + B / X[0], 0.0); }, false);
}

struct expansion_errors {
  double traction = 0.0, collocation = 0.0;
};

template <class Q>
expansion_errors expansion(int n) {
  using G = geometry::axisymmetric;
  const double R0 = 3.2e-3, Lz = 6.4e-3, e = 1e-3;
  const discrete_model m = build_discrete_model<K, C, Q, G>(make_grid_particles<2>(vec2(0, 0), vec2(R0, Lz), Eigen::Vector2i(n, n), 2.0),
                                                            make_grid_mesh(vec2(0, 0), vec2(R0, Lz), Eigen::Vector2i(n, n)));
  const auto Kmat = sparse_stiffness<G>(m, copper);
  const double lam = copper.lame_lambda(), mu = copper.shear_modulus();
  mat2 sigma;
  sigma << (2 * lam + 2 * mu) * e, 0, 0, 2 * lam * e;
  std::vector<value_row> axis, collocated;
  for (index_t I = 0; I < m.particle_count(); ++I) {
    const vec2& X = m.particles.position[I];
    if (X[0] == 0.0) axis.push_back({I, 0, 0.0});
    if (X[0] == 0.0) collocated.push_back({I, 0, 0.0});
    if (X[0] == R0) collocated.push_back({I, 0, e * R0});
    if (X[1] == 0.0 || X[1] == Lz) collocated.push_back({I, 1, 0.0});
  }
  axis.push_back({0, 1, 0.0});
  const auto exact = [&](const vec2& X) { return vec2(e * X[0], 0.0); };
  expansion_errors r;
  r.traction = max_error(m, solve(m, Kmat, traction_load<G>(m, [&](const vec2&) { return sigma; }), axis), exact, false);
  r.collocation = max_error(m, solve(m, Kmat, Eigen::VectorXd::Zero(Kmat.rows()), collocated), exact, false);
  return r;
}

const std::vector<int> resolutions{9, 17, 33};

std::string list(const std::vector<double>& e) {
  std::string s;
  for (std::size_t k = 0; k < e.size(); ++k) s += (k ? ", " : "") + fmt::format("{:.3g}", e[k]);
  s += "; rates";
  for (std::size_t k = 1; k < e.size(); ++k) s += fmt::format(" {:.2f}", std::log2(e[k - 1] / e[k]));
  return s;
}

double last_rate(const std::vector<double>& e) { return std::log2(e[e.size() - 2] / e.back()); }

template <class Q>
std::vector<double> manufactured_errors() {
  std::vector<double> e;
  for (int n : resolutions) e.push_back(manufactured<Q>(n));
  MESSAGE("manufactured (plane strain) " << Q::name << ": " << list(e));
  return e;
}

template <class Q>
std::vector<double> lame_errors() {
  std::vector<double> e;
  for (int n : resolutions) e.push_back(lame<Q>(n));
  MESSAGE("Lame cylinder (axisymmetric) " << Q::name << ": " << list(e));
  return e;
}

}  // namespace

TEST_CASE("consistent tractions: the uncorrected rules converge at first order, VCI at second") {
  test::run_serially();
  const auto q4 = manufactured_errors<quadrature::q4>();
  manufactured_errors<quadrature::q9>();
  const auto q2 = manufactured_errors<quadrature::q2>();
  const auto split = manufactured_errors<quadrature::q2_split>();
  const auto tri = manufactured_errors<quadrature::q2_tri>();
  const auto q2v = manufactured_errors<quadrature::q2_vci>();
  const auto q4v = manufactured_errors<quadrature::q4_vci>();
  for (const auto* e : {&q4, &q2, &split, &tri}) CHECK(last_rate(*e) < 1.3);
  for (const auto* e : {&q2v, &q4v}) CHECK(last_rate(*e) > 1.6);
  for (std::size_t k = 0; k < resolutions.size(); ++k) {
    CAPTURE(resolutions[k]);
    CHECK(q2v[k] < 0.4 * q2[k]);
    CHECK(q4v[k] < q4[k]);
  }

  lame_errors<quadrature::q4>();
  lame_errors<quadrature::q9>();
  const auto lq2 = lame_errors<quadrature::q2>();
  lame_errors<quadrature::q2_split>();
  lame_errors<quadrature::q2_tri>();
  const auto lq2v = lame_errors<quadrature::q2_vci>();
  const auto lq4v = lame_errors<quadrature::q4_vci>();
  CHECK(last_rate(lq2) < 1.3);
  CHECK(last_rate(lq2v) > 1.6);
  CHECK(last_rate(lq4v) > 1.6);
  for (std::size_t k = 0; k < resolutions.size(); ++k) CHECK(lq2v[k] < lq2[k]);
}

TEST_CASE("uniform expansion: exact with VCI under tractions; the collocated conditions set the error") {
  test::run_serially();
  auto show = [](std::string_view rule, const std::vector<expansion_errors>& r) {
    MESSAGE("expansion " << rule << " at 9, 17: consistent tractions " << r[0].traction << ", " << r[1].traction
                         << "; collocated conditions " << r[0].collocation << ", " << r[1].collocation);
  };
  auto all = [](auto rule) {
    std::vector<expansion_errors> r;
    for (int n : {9, 17}) r.push_back(expansion<typename decltype(rule)::type>(n));
    return r;
  };
  const auto q4 = all(boost::hana::type_c<quadrature::q4>);
  const auto q9 = all(boost::hana::type_c<quadrature::q9>);
  const auto q2 = all(boost::hana::type_c<quadrature::q2>);
  const auto q2v = all(boost::hana::type_c<quadrature::q2_vci>);
  const auto q4v = all(boost::hana::type_c<quadrature::q4_vci>);
  show("q4", q4);
  show("q9", q9);
  show("q2", q2);
  show("q2+vci", q2v);
  show("q4+vci", q4v);
  const double rate = std::log2(q2v[0].collocation / q2v[1].collocation);
  CHECK(rate > 0.8);
  CHECK(rate < 1.3);
  for (std::size_t k = 0; k < 2; ++k) {
    CAPTURE(k);
    // Under consistent tractions the linear field is the discrete solution with VCI only.
    CHECK(q2v[k].traction < 1e-10);
    CHECK(q4v[k].traction < 1e-10);
    CHECK(q4[k].traction > 1e-4);
    CHECK(q2[k].traction > 1e-2);
    // Under the collocated conditions every rule errs by O(h), q9 (the most accurate
    // integration) included, ten times more than under tractions, and q4 is below q9: the
    // conditions, not the integration, set the error, and q4's integration error partly
    // cancels theirs.
    CHECK(q9[k].collocation > 5.0 * q9[k].traction);
    CHECK(q2v[k].collocation > 1e-4);
    CHECK(q4v[k].collocation > 1e-4);
    CHECK(q4[k].collocation < q9[k].collocation);
  }
}

// scni (docs/method.md section 3.6) passes the integration constraint (19a) to round-off, so its
// linear basis passes the patch test and converges as an exactly integrated one: at second order
// in displacement (first in energy). The error here is the largest nodal one, whose observed
// rates at 9, 17, 33 are still below 2: measured, scni 1.73, 1.78 (manufactured) and 1.22, 1.48
// (Lame), scni_plain 1.67, 1.61 and 1.55, 1.69. scni's Lame rate is still rising: Puso's
// stabilization (Beta^2 times the parts' gradient differences) perturbs the strain by O(h),
// which the coarser grids still feel. Asserted: a last rate above 1.45 (1.4 for scni's Lame,
// and rising), clear of the first order (below 1.3) of the rules that violate the constraint
// in the same problems (the first test case).
TEST_CASE("scni: second order in the manufactured and Lame problems, as the integration constraint promises") {
  test::run_serially();
  const auto m = manufactured_errors<quadrature::scni<>>();
  const auto mp = manufactured_errors<quadrature::scni_plain>();
  const auto l = lame_errors<quadrature::scni<>>();
  const auto lp = lame_errors<quadrature::scni_plain>();
  CHECK(last_rate(m) > 1.45);
  CHECK(last_rate(mp) > 1.45);
  CHECK(last_rate(lp) > 1.45);
  CHECK(last_rate(l) > 1.4);
  CHECK(last_rate(l) > std::log2(l[0] / l[1]));
}

}  // namespace test_numeric_integration_statics
