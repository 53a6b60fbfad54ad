#pragma once
// The integration constraint and variationally consistent integration (VCI; Chen, Hillman,
// Rueter 2013, IJNME 95:387; docs/method.md section 3.5, (19a)-(19c)).
//
// A quadrature passes the linear patch test only if, for every particle I, the domain sum of
// its test-function gradient equals the boundary integral of N_I n (the discrete divergence
// theorem):
//   sum_q [g_I(X_q) + e_r N_I(X_q) / R_q] w_q = b_I,   b_I = integral over the boundary of N_I n omega ds
// (the hoop term e_r N_I / R and omega = 2 pi R in axisymmetry only). This header
//   boundary_points                  Gauss points on the body's boundary: the edges that belong
//                                    to exactly one background cell, outward normals, weights
//                                    ds * omega (edges on the axis r = 0 weigh nothing and are left out)
//   boundary_integrals               b_I  #particles
//   measure_integration_constraint   the residual of the constraint for any gradient table
// The corrected gradients that make the residual zero are built in
// discretization/vci_gradients.hpp.
// The tables are those of discretization/shape_table.hpp; everything is computed once, in the
// reference configuration.

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include <rkpm/approximation/rk_shape_functions.hpp>
#include <rkpm/concepts/correction.hpp>
#include <rkpm/concepts/geometry.hpp>
#include <rkpm/concepts/kernel.hpp>
#include <rkpm/core/error.hpp>
#include <rkpm/discretization/background_mesh.hpp>
#include <rkpm/discretization/neighbor_search.hpp>
#include <rkpm/discretization/particle_set.hpp>
#include <rkpm/discretization/quadrature_points.hpp>
#include <rkpm/discretization/shape_table.hpp>

namespace rkpm {

// Points of a Gauss-Legendre rule on the body's boundary.
//   position  #points
//   normal    #points outward unit normal
//   weight    #points (edge length / 2) * Gauss weight * G::weight_factor(X)
struct boundary_points {
  std::vector<vec2> position;
  std::vector<vec2> normal;
  std::vector<double> weight;
  index_t size() const { return static_cast<index_t>(position.size()); }
};

namespace detail {

// Gauss-Legendre abscissae and weights on [-1, 1], n = 2..6.
inline std::pair<std::array<double, 6>, std::array<double, 6>> gauss_legendre(int n) {
  switch (n) {
    case 2: return {{-0.5773502691896257645, 0.5773502691896257645}, {1.0, 1.0}};
    case 3: return {{-0.7745966692414833770, 0.0, 0.7745966692414833770}, {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0}};
    case 4:
      return {{-0.8611363115940525752, -0.3399810435848562648, 0.3399810435848562648, 0.8611363115940525752},
              {0.3478548451374538574, 0.6521451548625461426, 0.6521451548625461426, 0.3478548451374538574}};
    case 5:
      return {{-0.9061798459386639928, -0.5384693101056830910, 0.0, 0.5384693101056830910, 0.9061798459386639928},
              {0.2369268850561890875, 0.4786286704993664680, 0.5688888888888888889, 0.4786286704993664680,
               0.2369268850561890875}};
    case 6:
      return {{-0.9324695142031520278, -0.6612093864662645137, -0.2386191860831969086, 0.2386191860831969086,
               0.6612093864662645137, 0.9324695142031520278},
              {0.1713244923791703450, 0.3607615730481386076, 0.4679139345726910474, 0.4679139345726910474,
               0.3607615730481386076, 0.1713244923791703450}};
    default: fail("boundary integrals: {} Gauss points per edge; give 2 to 6", n);
  }
}

}  // namespace detail

namespace detail {
// Gauss points of the segment A -> B (body to the left, outward normal to the right). Points
// with zero weight (on the axis, 2 pi R = 0) are dropped unless `keep_axis_points`, which keeps
// `points` entries per segment.
template <Geometry G>
void add_segment_points(const vec2& A, const vec2& B, int points, boundary_points& out, bool keep_axis_points) {
  const auto [abscissa, gauss_weight] = gauss_legendre(points);
  const vec2 t = B - A;
  const double length = t.norm();
  const vec2 n(t[1] / length, -t[0] / length);
  for (int g = 0; g < points; ++g) {
    const vec2 X = 0.5 * (A + B) + 0.5 * abscissa[g] * t;
    const double w = 0.5 * length * gauss_weight[g] * G::weight_factor(X);
    if (w == 0.0 && !keep_axis_points) continue;
    out.position.push_back(X);
    out.normal.push_back(n);
    out.weight.push_back(w);
  }
}
}  // namespace detail

template <Geometry G>
boundary_points make_boundary_points(const background_mesh& mesh, int points_per_edge) {
  mesh.validate();
  boundary_points b;
  for (const auto& [i, j] : mesh.boundary_edges())
    detail::add_segment_points<G>(mesh.node[i], mesh.node[j], points_per_edge, b, /*keep_axis_points=*/false);
  return b;
}

// b_I = sum over the boundary points of N_I n w, #particles.
inline std::vector<vec2> boundary_integrals(const shape_table<2>& at_boundary, const boundary_points& b,
                                            index_t particles) {
  std::vector<vec2> out(particles, vec2::Zero());
  for (index_t p = 0; p < b.size(); ++p)
    for (index_t e = at_boundary.offset[p]; e < at_boundary.offset[p + 1]; ++e)
      out[at_boundary.neighbor[e]] += at_boundary.N[e] * b.weight[p] * b.normal[p];
  return out;
}

// b_I of the particles on the boundary of the cells, with the RK functions of (K, C).
template <Kernel K, Correction C, Geometry G>
std::vector<vec2> boundary_integrals(const particle_set<2>& particles, const background_mesh& mesh,
                                     int points_per_edge, double max_condition = default_max_moment_condition) {
  const boundary_points b = make_boundary_points<G>(mesh, points_per_edge);
  const neighbor_search<2> search(particles, &mesh.cracks);
  const shape_table<2> at_boundary = build_shape_table<K, C, 2>(search, b.position, rk_shape_functions<K, C, 2>(max_condition));
  return boundary_integrals(at_boundary, b, particles.size());
}

// Residual of the integration constraint for the gradients `gradient` (#entries of at_points,
// the trial gradients at_points.grad or corrected ones).
//   residual  #particles  sum_q [g_I + e_r N_I / R_q] w_q - b_I
//   scale     #particles  sum_q |g_I + e_r N_I / R_q| w_q + sum |terms of b_I| (max norm per term)
struct integration_constraint {
  std::vector<vec2> residual;
  std::vector<double> scale;
  // Worst violation over the particles, each relative to its own terms: max_I |r_I| / scale_I.
  double worst() const {
    double w = 0.0;
    for (std::size_t I = 0; I < residual.size(); ++I)
      if (scale[I] > 0.0) w = std::max(w, residual[I].cwiseAbs().maxCoeff() / scale[I]);
    return w;
  }
};

namespace detail {
// Domain sums per particle: sum_q [g_I + e_r N_I / R_q] w_q and the sum of the magnitudes.
inline void domain_sums(const quadrature_points& points, const shape_table<2>& at_points,
                        const std::vector<vec2>& gradient, bool axisymmetric, std::vector<vec2>& sum,
                        std::vector<double>& magnitude) {
  for (index_t q = 0; q < points.size(); ++q) {
    const double w = points.weight[q];
    const double hoop = axisymmetric ? w / points.position[q][0] : 0.0;
    for (index_t e = at_points.offset[q]; e < at_points.offset[q + 1]; ++e) {
      vec2 term = gradient[e] * w;
      term[0] += at_points.N[e] * hoop;
      sum[at_points.neighbor[e]] += term;
      magnitude[at_points.neighbor[e]] += term.cwiseAbs().maxCoeff();
    }
  }
}
}  // namespace detail

inline integration_constraint measure_integration_constraint(const quadrature_points& points,
                                                             const shape_table<2>& at_points,
                                                             const std::vector<vec2>& gradient,
                                                             const std::vector<vec2>& boundary_integral,
                                                             bool axisymmetric) {
  const auto n = static_cast<index_t>(boundary_integral.size());
  integration_constraint c{std::vector<vec2>(n, vec2::Zero()), std::vector<double>(n, 0.0)};
  detail::domain_sums(points, at_points, gradient, axisymmetric, c.residual, c.scale);
  for (index_t I = 0; I < n; ++I) {
    c.residual[I] -= boundary_integral[I];
    c.scale[I] += boundary_integral[I].cwiseAbs().maxCoeff();
  }
  return c;
}

}  // namespace rkpm
