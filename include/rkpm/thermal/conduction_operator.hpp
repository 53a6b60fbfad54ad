#pragma once
// The conduction operator of heat_conduction (docs/method.md section 5.9, (87)): at every
// quadrature point a gather of the temperature and its reference gradient,
//   T_q = sum_I N_I(X_q) T_I,   G_q = sum_I T_I grad_X N_I(X_q),
// a point rule that turns them into the weighted flux w_q D_q G_q, with the conductance of the
// current configuration D_q = k(T_q) J_q C_q^-1 (C = F^T F, in-plane block; J = det F with F_33),
// and at once the scatter R_I += g_I(X_q) . (w_q D_q G_q), with the test gradients of the force
// loop (discrete_model::test_gradients(): grad_X N_I, or VCI's, which also add up to zero at every
// point, so sum_I R_I = 0 to round-off). It visits the points in the force loop's tiles and
// colours (discrete_model::traversal, discretization/point_traversal.hpp; solver/point_forces.hpp
// is the same traversal for vector fields): tiles of a colour share no particle and run in
// parallel, so R_I is summed in a fixed order whatever the thread count.
//   x     #particles coefficients
//   out   #particles, out = sum over points of the scattered fluxes
//   rule  rule(tile, q, T_q, G_q) -> the weighted flux w_q D_q G_q (vec2); runs in parallel and
//         must not throw

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <rkpm/core/error.hpp>
#include <rkpm/core/execution.hpp>
#include <rkpm/solver/discrete_model.hpp>

namespace rkpm::thermal {

template <class Rule>
void conduction_traversal(const discrete_model& m, const std::vector<double>& x, std::vector<double>& out,
                          Rule&& rule) {
  const point_traversal& tr = m.traversal;
  if (tr.tile_start.back() != m.point_count())
    fail("heat conduction: the point traversal covers {} points but the model has {}: call "
         "make_point_traversal(at_points, particles) after building or changing the table",
         tr.tile_start.back(), m.point_count());
  const stored_index* offset = m.at_points.offset.data();
  const particle_index* neighbor = m.at_points.neighbor.data();
  const double* N = m.at_points.N.data();
  const vec2* grad = m.at_points.grad.data();
  const vec2* test = m.test_gradients().data();
  const double* xs = x.data();
  double* os = out.data();
  exec::parallel_for(m.particle_count(), [&](index_t I) { os[I] = 0.0; });
  tr.for_each_tile([&](index_t tile, index_t first, index_t last) {
    for (index_t q = first; q < last; ++q) {
      double T = 0.0;
      vec2 G = vec2::Zero();
      for (index_t e = offset[q]; e < offset[q + 1]; ++e) {
        const double xI = xs[neighbor[e]];
        T += N[e] * xI;
        G += xI * grad[e];
      }
      const vec2 flux = rule(tile, q, T, G);
      for (index_t e = offset[q]; e < offset[q + 1]; ++e) os[neighbor[e]] += test[e].dot(flux);
    }
  });
}

// R = K(T) T, (87): the traversal with the point rule D_q = conductance(q, T_q) (kept in D, #points),
// returning the largest ratio(q, D_q) (the bound's growth, (90)). A conductance that throws (a
// property function out of range) is thrown again after the traversal, from one thread.
//   tile_max, tile_bad  #tiles scratch
template <class Conductance, class Ratio>
double conduction_residual(const discrete_model& m, const std::vector<double>& T, std::vector<double>& R,
                           std::vector<mat2>& D, std::vector<double>& tile_max, std::vector<index_t>& tile_bad,
                           Conductance&& conductance, Ratio&& ratio) {
  std::fill(tile_max.begin(), tile_max.end(), 0.0);
  std::fill(tile_bad.begin(), tile_bad.end(), -1);
  conduction_traversal(m, T, R, [&](index_t tile, index_t q, double Tq, const vec2& G) -> vec2 {
    try {
      D[q] = conductance(q, Tq);
      tile_max[tile] = std::max(tile_max[tile], ratio(q, D[q]));
      return m.points.weight[q] * (D[q] * G);
    } catch (...) {
      if (tile_bad[tile] < 0) tile_bad[tile] = q;
      return vec2::Zero();
    }
  });
  for (const index_t q : tile_bad)
    if (q >= 0) {
      conductance(q, m.at_points.interpolate(q, T));  // throws the error here
      fail("heat conduction: the conductance at point {} could not be evaluated", q);
    }
  return tile_max.empty() ? 1.0 : *std::max_element(tile_max.begin(), tile_max.end());
}

// The in-plane conductance per unit k of the current configuration, J C^-1 (F block diagonal:
// the in-plane 2x2 and F_33), (87).
inline mat2 current_conductance(const mat3& F) {
  const mat2 F2 = F.topLeftCorner<2, 2>();
  return F.determinant() * (F2.transpose() * F2).inverse();
}

// The largest mu with det(A - mu B) = 0 for symmetric 2x2 A >= 0 and B > 0: how much A exceeds B
// in the worst direction (A <= mu B). B singular (k = 0 when B was taken): 0 if A is zero too,
// infinite otherwise.
inline double largest_ratio(const mat2& A, const mat2& B) {
  const double detB = B(0, 0) * B(1, 1) - B(0, 1) * B(1, 0);
  const double detA = A(0, 0) * A(1, 1) - A(0, 1) * A(1, 0);
  const double b = A(0, 0) * B(1, 1) + A(1, 1) * B(0, 0) - A(0, 1) * B(1, 0) - A(1, 0) * B(0, 1);
  if (!(detB > 0.0)) return A.cwiseAbs().maxCoeff() == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
  const double disc = std::max(0.0, b * b - 4.0 * detA * detB);
  return (b + std::sqrt(disc)) / (2.0 * detB);
}

}  // namespace rkpm::thermal
