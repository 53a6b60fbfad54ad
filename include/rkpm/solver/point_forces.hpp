#pragma once
// The one traversal of the force loop (docs/method.md section 5): at every quadrature point
// a gather over its neighbours,
//   H_q = sum_I x_I (x) grad_X N_I(X_q),   u_q = sum_I N_I(X_q) x_I,
// a point rule that turns (H_q, u_q) into the weighted first Piola stress S_q = P_q w_q and
// the weighted hoop term h_q = P33_q w_q / R_q, and a scatter to the particles through the
// transposed table,
//   f_I = sum_q [S_q g_I(X_q) + e_r h_q N_I(X_q)],
// with the test gradients g_I = grad_X N_I, or the corrected ones of variationally consistent
// integration (discrete_model::test_gradients(), docs/method.md section 3.5), chosen once per
// call; the gather always uses the trial gradients grad_X N_I.
// The internal force (solver/point_materials.hpp) and the matrix-free stiffness of the stable
// time step (solver/stable_time_step.hpp) both go through it. Both loops are parallel over
// their outputs, so no atomics are needed and the sums do not depend on the thread count.

#include <vector>

#include <rkpm/concepts/geometry.hpp>
#include <rkpm/solver/discrete_model.hpp>

namespace rkpm {

// S_q and h_q of every quadrature point, sized once.
struct point_stresses {
  std::vector<mat2> weighted;
  std::vector<double> hoop;
  explicit point_stresses(index_t points = 0) : weighted(points, mat2::Zero()), hoop(points, 0.0) {}
};

// Gradient H_q and value u_q at quadrature point q of the field with coefficients x.
struct point_gradient {
  mat2 H = mat2::Zero();
  vec2 u = vec2::Zero();
};

inline point_gradient gather(const shape_table<2>& t, index_t q, const std::vector<vec2>& x) {
  point_gradient g;
  for (index_t e = t.offset[q]; e < t.offset[q + 1]; ++e) {
    g.H.noalias() += x[t.neighbor[e]] * t.grad[e].transpose();
    g.u += t.N[e] * x[t.neighbor[e]];
  }
  return g;
}

// f = scatter of the stresses in s (the second half of the traversal).
template <Geometry G>
void scatter(const discrete_model& m, const point_stresses& s, std::vector<vec2>& f) {
  const auto& t = m.at_points;
  const std::vector<vec2>& grad = m.test_gradients();
  const auto& tt = m.particles_of_points;
  const index_t n = m.particle_count();
#pragma omp parallel for schedule(static)
  for (index_t I = 0; I < n; ++I) {
    vec2 sum = vec2::Zero();
    for (index_t k = tt.offset[I]; k < tt.offset[I + 1]; ++k) {
      const index_t e = tt.entry[k], q = tt.point[k];
      sum.noalias() += s.weighted[q] * grad[e];
      if constexpr (G::is_axisymmetric) sum[0] += s.hoop[q] * t.N[e];
    }
    f[I] = sum;
  }
}

// The whole traversal: rule(q, gradient, S_q, h_q) sets the point's stresses from the gathered
// gradient of x (it runs in parallel and must not throw), then f is scattered.
template <Geometry G, class PointRule>
void assemble_point_forces(const discrete_model& m, const std::vector<vec2>& x, point_stresses& s,
                           std::vector<vec2>& f, PointRule&& rule) {
  const index_t nq = m.point_count();
#pragma omp parallel for schedule(static)
  for (index_t q = 0; q < nq; ++q) rule(q, gather(m.at_points, q, x), s.weighted[q], s.hoop[q]);
  scatter<G>(m, s, f);
}

}  // namespace rkpm
