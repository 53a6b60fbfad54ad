#pragma once
// Quadrature points of a background mesh for a rule Q (docs/method.md (15)-(16), section 3.4):
//   position  #points X_q: sum_a N_a(xi_q) X_a (bilinear map of the cell) for a reference rule,
//             where the rule puts it for a shaped rule (q2_split, q2_tri)
//   weight    #points w_q = W_q * det J(xi_q) * G::weight_factor(X_q) for a reference rule,
//             w_q = (area of the point's part) * G::weight_factor(X_q) for a shaped rule
//             (2 pi R in axisymmetric)
//   cell      #points the cell each point belongs to
// A corrected rule (vci<Rule>) takes the points of the rule it wraps; a nodal rule (scni) has
// its own builder (discretization/smoothing_cells.hpp).

#include <array>
#include <vector>

#include <rkpm/concepts/geometry.hpp>
#include <rkpm/concepts/quadrature.hpp>
#include <rkpm/discretization/background_mesh.hpp>

namespace rkpm {

struct quadrature_points {
  std::vector<vec2> position;
  std::vector<double> weight;
  std::vector<stored_index> cell;
  index_t size() const { return static_cast<index_t>(position.size()); }
};

template <Quadrature Q, Geometry G>
  requires(!NodalRule<Q>)
quadrature_points make_quadrature_points(const background_mesh& mesh) {
  using R = cell_rule_of_t<Q>;
  mesh.validate();
  quadrature_points qp;
  const auto n = static_cast<std::size_t>(mesh.cells() * R::points_per_cell);
  qp.position.reserve(n);
  qp.weight.reserve(n);
  qp.cell.reserve(n);
  for (index_t c = 0; c < mesh.cells(); ++c) {
    const vec2& x0 = mesh.node[mesh.cell[c][0]];
    const vec2& x1 = mesh.node[mesh.cell[c][1]];
    const vec2& x2 = mesh.node[mesh.cell[c][2]];
    const vec2& x3 = mesh.node[mesh.cell[c][3]];
    if constexpr (ShapedCellRule<R>) {
      for (const cell_point& p : R::cell_points({x0, x1, x2, x3})) {
        if (!(p.area > 0.0))
          fail("background cell {} is inverted or degenerate: rule {} gives it a part of area {:.3g} at ({:.6g}, {:.6g})",
               c, R::name, p.area, p.position[0], p.position[1]);
        qp.position.push_back(p.position);
        qp.weight.push_back(p.area * G::weight_factor(p.position));
        qp.cell.push_back(c);
      }
    } else {
      for (const auto& [xi, eta, w] : R::rule) {
        const double n0 = 0.25 * (1 - xi) * (1 - eta), n1 = 0.25 * (1 + xi) * (1 - eta);
        const double n2 = 0.25 * (1 + xi) * (1 + eta), n3 = 0.25 * (1 - xi) * (1 + eta);
        const vec2 X = n0 * x0 + n1 * x1 + n2 * x2 + n3 * x3;
        const vec2 dxi = 0.25 * (-(1 - eta) * x0 + (1 - eta) * x1 + (1 + eta) * x2 - (1 + eta) * x3);
        const vec2 deta = 0.25 * (-(1 - xi) * x0 - (1 + xi) * x1 + (1 + xi) * x2 + (1 - xi) * x3);
        const double detJ = dxi[0] * deta[1] - dxi[1] * deta[0];
        if (!(detJ > 0.0))
          fail("background cell {} is inverted or degenerate at ({}, {}): det J = {:.3g}", c, xi, eta, detJ);
        qp.position.push_back(X);
        qp.weight.push_back(w * detJ * G::weight_factor(X));
        qp.cell.push_back(c);
      }
    }
  }
  return qp;
}

}  // namespace rkpm
