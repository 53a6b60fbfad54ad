// The integration constraint (docs/method.md (19a)) and the linear patch test, for the cell
// rules, their VCI corrections and stabilized conforming nodal integration (docs/method.md
// sections 3.4-3.6). For scni (with and without its stabilization) b_I is integrated on the
// body's boundary split at the edge midpoints, with the Gauss points of its smoothing cells
// (make_split_boundary_points): the constraint is a discrete divergence theorem of that rule;
// the difference from the five-point rule on whole edges (the quadrature error of b_I itself)
// is printed.
// Theory: for every particle I the discrete divergence theorem
//   sum_q [g_I(X_q) + e_r N_I(X_q) / R_q] w_q = b_I = sum_b N_I(X_b) n_b w_b
// holds to round-off when g_I are the VCI test gradients (q2+vci, q4+vci), whatever the
// particles and the cells; no cell rule satisfies it with the trial gradients g_I = grad N_I
// (RK functions are rational, and the cells do not follow their supports), so the same measure
// must find a violation for q2, q4, q2_split and q2_tri. Settings: a 9 x 9 grid, the same with
// the interior particles (and the cell nodes, which are the particles) moved by up to 20% of
// the spacing, and grid particles on cells whose interior nodes are moved by up to 25% (cells
// not aligned with the supports); plane strain and axisymmetric (the section touching the axis).
// The linear patch test through the solver: a linear displacement field imposed as
// coefficients (RK reproduces it, so F and the stress are uniform) gives f_int,I = P b_I for
// every particle (zero where the support does not reach the boundary, the boundary traction's
// resultant where it does) to round-off with VCI, on the jittered particles; q2 fails it. In
// axisymmetry the homogeneous state is u = (a r, b z + c), for which sigma_rr = sigma_theta.

#include <doctest/doctest.h>

#include <numbers>

#include "support/solver_fixtures.hpp"

namespace test_numeric_integration_constraint {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

namespace {

using K = kernel::cubic_spline;
using C = correction::linear;

enum class layout { grid, jittered, distorted_cells };
const char* layout_name(layout l) {
  return l == layout::grid ? "grid" : l == layout::jittered ? "jittered 20%" : "distorted cells";
}

template <class G>
struct body {
  particle_set<2> particles;
  background_mesh mesh;
};

// 9 x 9 particles on [lo, hi]; the axisymmetric section starts on the axis.
template <class G>
body<G> make_body(layout l, const Eigen::Vector2i& n = Eigen::Vector2i(9, 9)) {
  const vec2 lo(G::is_axisymmetric ? 0.0 : -0.3e-3, 0.2e-3), hi(lo[0] + 1.6e-3, lo[1] + 2.0e-3);
  const vec2 h((hi - lo)[0] / (n[0] - 1), (hi - lo)[1] / (n[1] - 1));
  body<G> b{make_grid_particles<2>(lo, hi, n, 2.0), make_grid_mesh(lo, hi, n)};
  if (l == layout::jittered) test::distort_interior(b.particles, b.mesh, h, 0.2);
  if (l == layout::distorted_cells) {
    particle_set<2> moved = b.particles;  // only the cells move
    background_mesh m = b.mesh;
    // A pattern other than the jitter's: the cells do not follow the particles.
    for (auto& x : m.node) x = vec2(x[1], x[0]);
    for (auto& x : moved.position) x = vec2(x[1], x[0]);
    test::distort_interior(moved, m, vec2(h[1], h[0]), 0.25);
    for (auto& x : m.node) x = vec2(x[1], x[0]);
    b.mesh = m;
  }
  return b;
}

struct measured {
  double worst = 0.0;   // max_I |r_I| / scale_I
  double median = 0.0;  // of |r_I| / scale_I over the particles
  double point_sum = 0.0;  // max_q |sum_I g_I(X_q)| / sum_I |g_I(X_q)|: the net force of a stress at q
};

// Linear momentum needs sum_I g_I(X_q) = 0 at every point: the forces (37) of any stress field
// then cancel. Trial gradients have it (RK reproduces constants); so must the VCI ones
// (docs/method.md (19c')).
inline double largest_point_sum(const shape_table<2>& table, const std::vector<vec2>& gradient) {
  double worst = 0.0;
  for (index_t q = 0; q < table.points(); ++q) {
    vec2 sum = vec2::Zero();
    double magnitude = 0.0;
    for (index_t e = table.offset[q]; e < table.offset[q + 1]; ++e) {
      sum += gradient[e];
      magnitude += gradient[e].norm();
    }
    worst = std::max(worst, sum.norm() / magnitude);
  }
  return worst;
}

// b_I as the rule Q integrates it: five Gauss points per edge (VCI), or the smoothing cells'
// points on the half edges (scni).
template <class Q, class G>
std::vector<vec2> rule_boundary_integrals(const discrete_model& m) {
  if constexpr (NodalRule<Q>) {
    const auto bp = make_split_boundary_points<G>(m.mesh, Q::edge_points);
    return boundary_integrals(build_shape_table<K, C, 2>(neighbor_search<2>(m.particles), bp.position), bp,
                              m.particle_count());
  } else {
    return boundary_integrals<K, C, G>(m.particles, m.mesh, 5);
  }
}

template <class Q, class G>
measured constraint_violation(layout l, bool five_point_edges = false) {
  auto b = make_body<G>(l);
  const discrete_model m = build_discrete_model<K, C, Q, G>(b.particles, b.mesh);
  const auto bi = five_point_edges ? boundary_integrals<K, C, G>(m.particles, m.mesh, 5) : rule_boundary_integrals<Q, G>(m);
  const auto c = measure_integration_constraint(m.points, m.at_points, m.test_gradients(), bi, G::is_axisymmetric);
  std::vector<double> e;
  for (std::size_t I = 0; I < c.residual.size(); ++I) e.push_back(c.residual[I].cwiseAbs().maxCoeff() / c.scale[I]);
  std::sort(e.begin(), e.end());
  return {c.worst(), e[e.size() / 2], largest_point_sum(m.at_points, m.test_gradients())};
}

template <class G>
void check_constraint(layout l) {
  const std::string what = std::string(G::name) + ", " + layout_name(l);
  const auto q2 = constraint_violation<quadrature::q2, G>(l);
  const auto q4 = constraint_violation<quadrature::q4, G>(l);
  const auto split = constraint_violation<quadrature::q2_split, G>(l);
  const auto tri = constraint_violation<quadrature::q2_tri, G>(l);
  const auto q2v = constraint_violation<quadrature::q2_vci, G>(l);
  const auto q4v = constraint_violation<quadrature::q4_vci, G>(l);
  const auto scni = constraint_violation<quadrature::scni<>, G>(l);
  const auto plain = constraint_violation<quadrature::scni_plain, G>(l);
  const auto scni5 = constraint_violation<quadrature::scni<>, G>(l, true);
  MESSAGE(what << ": scni " << scni.worst << ", scni_plain " << plain.worst
               << "; scni against b_I by 5 points per whole edge " << scni5.worst << " (median " << scni5.median << ")");
  CHECK(scni.worst < 1e-12);
  CHECK(plain.worst < 1e-12);
  MESSAGE(what << ": integration-constraint violation max_I |r_I| / scale_I (median): q2 " << q2.worst << " ("
               << q2.median << "), q4 " << q4.worst << " (" << q4.median << "), q2_split " << split.worst << " ("
               << split.median << "), q2_tri " << tri.worst << " (" << tri.median << "), q2+vci " << q2v.worst
               << ", q4+vci " << q4v.worst);
  CHECK(q2v.worst < 1e-12);
  CHECK(q4v.worst < 1e-12);
  const auto split_v = constraint_violation<quadrature::vci<quadrature::q2_split>, G>(l);
  const auto tri_v = constraint_violation<quadrature::vci<quadrature::q2_tri>, G>(l);
  CHECK(split_v.worst < 1e-12);
  CHECK(tri_v.worst < 1e-12);
  MESSAGE(what << ": largest |sum_I g_I| at a point, relative: q2 " << q2.point_sum << ", q2+vci " << q2v.point_sum
               << ", q4+vci " << q4v.point_sum << ", q2_split+vci " << split_v.point_sum << ", q2_tri+vci "
               << tri_v.point_sum);
  for (const auto* v : {&q2, &q4, &q2v, &q4v, &split_v, &tri_v}) CHECK(v->point_sum < 1e-13);
  // The measure sees the violation of the uncorrected rules, far above round-off.
  CHECK(q2.worst > 1e-4);
  CHECK(q4.worst > 1e-6);
  CHECK(split.worst > 1e-4);
  CHECK(tri.worst > 1e-4);
}

}  // namespace

TEST_CASE("boundary points: closed boundary, outward normals, the axis left out") {
  for (layout l : {layout::grid, layout::jittered, layout::distorted_cells}) {
    CAPTURE(layout_name(l));
    const auto ps = make_body<geometry::plane_strain>(l);
    const auto bp = make_boundary_points<geometry::plane_strain>(ps.mesh, 5);
    CHECK(bp.size() == 4 * 8 * 5);
    vec2 sum_n = vec2::Zero();
    double perimeter = 0.0, flux = 0.0;  // flux of X: int X . n ds = 2 * area
    for (index_t p = 0; p < bp.size(); ++p) {
      sum_n += bp.normal[p] * bp.weight[p];
      perimeter += bp.weight[p];
      flux += bp.position[p].dot(bp.normal[p]) * bp.weight[p];
    }
    CHECK(sum_n.norm() < 1e-15 * perimeter);
    CHECK(perimeter == doctest::Approx(2 * (1.6e-3 + 2.0e-3)).epsilon(1e-14));
    CHECK(flux == doctest::Approx(2.0 * ps.mesh.area()).epsilon(1e-14));
    // Partition of unity: sum_I b_I = sum_b n_b w_b = 0.
    vec2 sum_b = vec2::Zero();
    for (const vec2& bI : boundary_integrals<K, C, geometry::plane_strain>(ps.particles, ps.mesh, 5)) sum_b += bI;
    CHECK(sum_b.norm() < 1e-14 * perimeter);

    // Axisymmetric: the axis edges carry no weight; int n_r 2 pi r ds = 2 pi area (the
    // divergence of (r, 0) in the section is 1), int n_z 2 pi r ds = 0.
    const auto ax = make_body<geometry::axisymmetric>(l);
    const auto ba = make_boundary_points<geometry::axisymmetric>(ax.mesh, 5);
    CHECK(ba.size() == 3 * 8 * 5);
    vec2 s = vec2::Zero();
    for (index_t p = 0; p < ba.size(); ++p) s += ba.normal[p] * ba.weight[p];
    CHECK(s[0] == doctest::Approx(2.0 * std::numbers::pi * ax.mesh.area()).epsilon(1e-14));
    CHECK(std::abs(s[1]) < 1e-14 * s[0]);
  }
}

TEST_CASE("integration constraint: exact with VCI and scni, violated by every cell rule") {
  for (layout l : {layout::grid, layout::jittered, layout::distorted_cells}) {
    check_constraint<geometry::plane_strain>(l);
    check_constraint<geometry::axisymmetric>(l);
  }
}

namespace {

template <class Q, class G>
using patch_config = config<K, C, Q, G, material::elastic, contact::none>;

struct patch_result {
  double worst = 0.0;     // max_I |f_I - P b_I| / (|P| scale_I)
  double interior = 0.0;  // max |f_I| / (|P| scale_I) over the particles with b_I = 0
  index_t interior_count = 0;
  double hoop_mismatch = 0.0;  // |P_rr - P_33| / |P| (axisymmetric: must be round-off)
};

template <class Q, class G>
patch_result patch_test() {
  using Cfg = patch_config<Q, G>;
  const auto c = test::steel_like();
  auto b = make_body<G>(layout::jittered);
  auto p = test::grid_problem<Cfg>(vec2(0, 0), vec2(1, 1), Eigen::Vector2i(2, 2), c);
  p.particles = b.particles;
  p.mesh = b.mesh;
  mat2 A;
  if constexpr (G::is_axisymmetric) A << 0.012, 0.0, 0.0, -0.007;  // u = (a r, b z + c)
  else A << 0.012, -0.004, 0.009, -0.007;
  const vec2 shift(G::is_axisymmetric ? 0.0 : 1e-6, 2e-6);
  auto s = test::solver_at<Cfg>(std::move(p), [&](const vec2& X) -> vec2 { return A * X + shift; },
                                test::tiny_step(0.2e-3, c));
  const auto& m = s.model();
  // The uniform first Piola stress from the solver's stress at a point (uniform to round-off,
  // numeric/linear_fields.cpp): P = tau F^-T, P33 = tau33 / F33.
  mat3 F = mat3::Identity();
  F.topLeftCorner<2, 2>() += A;
  if (G::is_axisymmetric) F(2, 2) = 1.0 + A(0, 0);
  const mat3 tau = s.point_cauchy_stress(0) * F.determinant();
  const mat2 P = tau.topLeftCorner<2, 2>() * F.topLeftCorner<2, 2>().inverse().transpose();
  const double Pscale = P.cwiseAbs().maxCoeff();
  patch_result r;
  if (G::is_axisymmetric) r.hoop_mismatch = std::abs(P(0, 0) - tau(2, 2) / F(2, 2)) / Pscale;
  const auto bi = rule_boundary_integrals<Q, G>(m);
  const auto scale = measure_integration_constraint(m.points, m.at_points, m.at_points.grad, bi, G::is_axisymmetric).scale;
  for (index_t I = 0; I < m.particle_count(); ++I) {
    const double e = (s.internal_force()[I] - P * bi[I]).cwiseAbs().maxCoeff() / (Pscale * scale[I]);
    r.worst = std::max(r.worst, e);
    if (bi[I].isZero(0.0)) {
      r.interior = std::max(r.interior, s.internal_force()[I].cwiseAbs().maxCoeff() / (Pscale * scale[I]));
      ++r.interior_count;
    }
  }
  return r;
}

template <class G>
void check_patch() {
  const auto q2v = patch_test<quadrature::q2_vci, G>();
  const auto q4v = patch_test<quadrature::q4_vci, G>();
  // q2 on the same particles, measured against the same boundary resultant.
  const auto q2 = patch_test<quadrature::q2, G>();
  const auto sc = patch_test<quadrature::scni<>, G>();
  MESSAGE(G::name << ", jittered particles: patch test, scni " << sc.worst << " (interior " << sc.interior << ", "
                  << sc.interior_count << " particles)");
  CHECK(sc.interior_count > 0);
  CHECK(sc.worst < 1e-12);
  CHECK(sc.interior < 1e-12);
  if (G::is_axisymmetric) CHECK(sc.hoop_mismatch < 1e-13);
  MESSAGE(G::name << ", jittered particles: patch test max_I |f_I - P b_I| / (|P| scale_I): q2+vci " << q2v.worst
                  << " (interior " << q2v.interior << ", " << q2v.interior_count << " particles), q4+vci " << q4v.worst
                  << " (interior " << q4v.interior << "), q2 " << q2.worst << " (interior " << q2.interior << ")");
  CHECK(q2v.interior_count > 0);
  CHECK(q2v.worst < 1e-12);
  CHECK(q4v.worst < 1e-12);
  CHECK(q2v.interior < 1e-12);
  CHECK(q4v.interior < 1e-12);
  if (G::is_axisymmetric) CHECK(q2v.hoop_mismatch < 1e-13);
  CHECK(q2.worst > 1e-4);
  CHECK(q2.interior > 1e-4);
}

}  // namespace

TEST_CASE("linear patch test through the solver: f_int = P b_I with VCI and scni") {
  test::run_serially();
  check_patch<geometry::plane_strain>();
  check_patch<geometry::axisymmetric>();
}

}  // namespace test_numeric_integration_constraint
