#pragma once
// The one traversal of the force loop (docs/method.md section 5.3): at every quadrature point
// a gather over its neighbours,
//   H_q = sum_I x_I (x) grad_X N_I(X_q),   u_q = sum_I N_I(X_q) x_I,
// a point rule that turns (H_q, u_q) into the weighted first Piola stress S_q = P_q w_q and
// the weighted hoop term h_q = P33_q w_q / R_q, and at once the scatter of that point to its
// neighbours,
//   f_I += S_q g_I(X_q) + e_r h_q N_I(X_q),
// with the test gradients g_I = grad_X N_I, or the corrected ones of variationally consistent
// integration (discrete_model::test_gradients(), docs/method.md section 3.5), chosen once per
// call; the gather always uses the trial gradients grad_X N_I.
// The gather, the point rule and the scatter of a point share its table row while it is in
// cache: the table is read once per evaluation and nothing is stored per point. The points are
// visited tile by tile in the order of discrete_model::traversal (discretization/
// point_traversal.hpp): tiles of one colour share no particle and run in parallel, colours one
// after the other (point_traversal::for_each_tile), so no atomics are needed and
// every f_I is summed in the same order whatever the thread count.
// The internal force (solver/point_materials.hpp) and the matrix-free stiffness of the stable
// time step (solver/stable_time_step.hpp) both go through it.

#include <algorithm>
#include <array>
#include <vector>

#include <rkpm/concepts/geometry.hpp>
#include <rkpm/core/error.hpp>
#include <rkpm/core/execution.hpp>
#include <rkpm/core/hot_inline.hpp>
#include <rkpm/solver/discrete_model.hpp>

namespace rkpm {

// Gradient H_q and value u_q at quadrature point q of the field with coefficients x.
struct point_gradient {
  mat2 H = mat2::Zero();
  vec2 u = vec2::Zero();
};

namespace detail {

// The table as the traversal reads it: through local pointers, so that the scatter's stores into
// f cannot alias it (the compiler would otherwise reload the pointers for every entry).
struct point_rows {
  const stored_index* offset;
  const particle_index* neighbor;
  const double* N;
  const vec2* grad;
  const vec2* test;
};

// Sets g[0..P) to the gathers of the P points whose rows start at entries b[0..P), all with the
// neighbours of the first (len entries): each x_I is loaded once for the P points.
template <std::size_t P>
RKPM_HOT_INLINE void gather_rows(const point_rows& t, const std::array<index_t, P>& b, index_t len, const vec2* xs,
                                 point_gradient* g) {
  std::array<point_gradient, P> sum;  // in registers: g could alias the table for all the compiler knows
  for (index_t j = 0; j < len; ++j) {
    const vec2 xI = xs[t.neighbor[b[0] + j]];
    for (std::size_t k = 0; k < P; ++k) {
      sum[k].H.noalias() += xI * t.grad[b[k] + j].transpose();
      sum[k].u += t.N[b[k] + j] * xI;
    }
  }
  for (std::size_t k = 0; k < P; ++k) g[k] = sum[k];
}

// The scatter of the P points whose rows start at b[0..P), neighbours of the first: each f_I
// gets the first point's terms, then the second's, as P separate visits would add them.
template <Geometry G, std::size_t P>
RKPM_HOT_INLINE void scatter_rows(const point_rows& t, const std::array<index_t, P>& b, index_t len, const mat2* S,
                                  const double* hoop, vec2* fs) {
  std::array<mat2, P> Sk;  // copies: the stores into f could alias S and hoop for all the compiler knows
  std::array<double, P> hk;
  for (std::size_t k = 0; k < P; ++k) {
    Sk[k] = S[k];
    hk[k] = hoop[k];
  }
  for (index_t j = 0; j < len; ++j) {
    // f_I's components summed in scalars, as the vector additions would sum them: the hoop
    // term's half-width add would otherwise make the next point's full-width load of f_I wait
    // for both stores to retire (a failed store forwarding, which stalls the whole loop).
    double* const fI = fs[t.neighbor[b[0] + j]].data();
    double f0 = fI[0], f1 = fI[1];
    for (std::size_t k = 0; k < P; ++k) {
      const vec2 term = Sk[k] * t.test[b[k] + j];
      f0 += term[0];
      f1 += term[1];
      if constexpr (G::is_axisymmetric) f0 += hk[k] * t.N[b[k] + j];
    }
    fI[0] = f0;
    fI[1] = f1;
  }
}

// Gather, rule and scatter of the points first .. last-1, W consecutive points at a time: the
// rule(tile, q, n, g, S, h) gets the gathered gradients g[0..n) of points q .. q+n-1 (n = W but
// at a range's end) and sets their S and h. The scatter adds each point's terms in point order,
// so f does not depend on W. With `paired` (point_traversal::paired_rows; W even, first the
// tile's first point) points k, k+1 of a batch share one row and are gathered and scattered
// together: the same sums in the same order, each neighbour visited once for both.
template <Geometry G, int W, class BatchRule>
void traverse_points(const discrete_model& m, const std::vector<vec2>& test_grad, index_t tile, index_t first,
                     index_t last, bool paired, const std::vector<vec2>& x, std::vector<vec2>& f, BatchRule& rule) {
  const point_rows t{m.at_points.offset.data(), m.at_points.neighbor.data(), m.at_points.N.data(),
                     m.at_points.grad.data(), test_grad.data()};
  const vec2* const xs = x.data();
  vec2* const fs = f.data();
  const bool pairs = paired && W % 2 == 0;
  for (index_t q0 = first; q0 < last; q0 += W) {
    const int n = static_cast<int>(std::min<index_t>(W, last - q0));
    // visit(k, b, len) for the batch's points k, k+1 (b: their rows' first entries) where paired,
    // else for each point k alone (b: its row's first entry).
    const auto for_each_group = [&](auto&& visit) {
      int k = 0;
      for (; pairs && k + 1 < n; k += 2) {
        const index_t b = t.offset[q0 + k], len = t.offset[q0 + k + 1] - b;
        visit(k, std::array<index_t, 2>{b, b + len}, len);
      }
      for (; k < n; ++k) visit(k, std::array<index_t, 1>{t.offset[q0 + k]}, t.offset[q0 + k + 1] - t.offset[q0 + k]);
    };
    std::array<point_gradient, W> g;
    std::array<mat2, W> S;
    std::array<double, W> hoop;
    for (int k = 0; k < n; ++k) {
      S[k].setZero();
      hoop[k] = 0.0;
    }
    for_each_group([&]<std::size_t P>(int k, const std::array<index_t, P>& b, index_t len) {
      gather_rows<P>(t, b, len, xs, &g[k]);
    });
    rule(tile, q0, n, g.data(), S.data(), hoop.data());
    for_each_group([&]<std::size_t P>(int k, const std::array<index_t, P>& b, index_t len) {
      scatter_rows<G, P>(t, b, len, &S[k], &hoop[k], fs);
    });
  }
}

}  // namespace detail

// The whole traversal with a rule of W points at a time (detail::traverse_points): f = sum over
// the points of the scattered stresses that rule(tile, q, n, g, S, h) sets for points q .. q+n-1
// of tile `tile` from their gathered gradients of x (S, h start at zero; the rule runs in
// parallel and must not throw). A batch never spans two tiles.
template <Geometry G, int W, class BatchRule>
void assemble_point_batches(const discrete_model& m, const std::vector<vec2>& x, std::vector<vec2>& f,
                            BatchRule&& rule) {
  const point_traversal& tr = m.traversal;
  // A model whose table was changed after its traversal was made would silently skip points.
  if (tr.tile_start.back() != m.point_count())
    fail("force loop: the point traversal covers {} points but the model has {}: call "
         "make_point_traversal(at_points, particles) after building or changing the table",
         tr.tile_start.back(), m.point_count());
  const std::vector<vec2>& grad = m.test_gradients();
  exec::parallel_for(m.particle_count(), [&](index_t I) { f[I] = vec2::Zero(); });
  tr.for_each_tile([&](index_t tile, index_t first, index_t last) {
    detail::traverse_points<G, W>(m, grad, tile, first, last, tr.paired_rows, x, f, rule);
  });
}

// One point at a time: rule(tile, q, gradient, S_q, h_q) for point q of tile `tile` (the
// traversal goes two points at a time, so that paired rows are read once).
template <Geometry G, class PointRule>
void assemble_point_forces(const discrete_model& m, const std::vector<vec2>& x, std::vector<vec2>& f,
                           PointRule&& rule) {
  assemble_point_batches<G, 2>(m, x, f,
                               [&](index_t tile, index_t q, int n, const point_gradient* g, mat2* S, double* hoop) {
                                 for (int k = 0; k < n; ++k) rule(tile, q + k, g[k], S[k], hoop[k]);
                               });
}

}  // namespace rkpm
