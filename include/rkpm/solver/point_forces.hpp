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
#include <rkpm/solver/discrete_model.hpp>

namespace rkpm {

// Gradient H_q and value u_q at quadrature point q of the field with coefficients x.
struct point_gradient {
  mat2 H = mat2::Zero();
  vec2 u = vec2::Zero();
};

namespace detail {

// Gather, rule and scatter of the points first .. last-1, W consecutive points at a time: the
// rule(tile, q, n, g, S, h) gets the gathered gradients g[0..n) of points q .. q+n-1 (n = W but
// at a range's end) and sets their S and h. The scatter adds each point's terms in point order,
// so f does not depend on W. The table is read through local pointers and the row bounds are
// held in locals: the scatter's stores into f could otherwise alias the table, and the compiler
// would reload its pointers for every entry.
template <Geometry G, int W, class BatchRule>
void traverse_points(const discrete_model& m, const std::vector<vec2>& test_grad, index_t tile, index_t first,
                     index_t last, const std::vector<vec2>& x, std::vector<vec2>& f, BatchRule& rule) {
  const stored_index* const offset = m.at_points.offset.data();
  const particle_index* const neighbor = m.at_points.neighbor.data();
  const double* const N = m.at_points.N.data();
  const vec2* const grad = m.at_points.grad.data();
  const vec2* const test = test_grad.data();
  const vec2* const xs = x.data();
  vec2* const fs = f.data();
  for (index_t q0 = first; q0 < last; q0 += W) {
    const int n = static_cast<int>(std::min<index_t>(W, last - q0));
    std::array<point_gradient, W> g;
    std::array<mat2, W> S;
    std::array<double, W> hoop;
    for (int k = 0; k < n; ++k) {
      for (index_t e = offset[q0 + k], end = offset[q0 + k + 1]; e < end; ++e) {
        const vec2 xI = xs[neighbor[e]];
        g[k].H.noalias() += xI * grad[e].transpose();
        g[k].u += N[e] * xI;
      }
      S[k].setZero();
      hoop[k] = 0.0;
    }
    rule(tile, q0, n, g.data(), S.data(), hoop.data());
    for (int k = 0; k < n; ++k) {
      for (index_t e = offset[q0 + k], end = offset[q0 + k + 1]; e < end; ++e) {
        vec2& fI = fs[neighbor[e]];
        fI.noalias() += S[k] * test[e];
        if constexpr (G::is_axisymmetric) fI[0] += hoop[k] * N[e];
      }
    }
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
    detail::traverse_points<G, W>(m, grad, tile, first, last, x, f, rule);
  });
}

// One point at a time: rule(tile, q, gradient, S_q, h_q) for point q of tile `tile`.
template <Geometry G, class PointRule>
void assemble_point_forces(const discrete_model& m, const std::vector<vec2>& x, std::vector<vec2>& f,
                           PointRule&& rule) {
  assemble_point_batches<G, 1>(m, x, f,
                               [&](index_t tile, index_t q, int /*n*/, const point_gradient* g, mat2* S, double* hoop) {
                                 rule(tile, q, g[0], S[0], hoop[0]);
                               });
}

}  // namespace rkpm
