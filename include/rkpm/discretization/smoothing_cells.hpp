#pragma once
// Smoothing cells and smoothed gradients of stabilized conforming nodal integration (SCNI;
// Chen, Wu, Yoon, You 2001; modified SCNI, Puso, Chen, Zywicz, Elmer 2008; docs/method.md
// section 3.6, (19d)-(19h)).
//
// The smoothing cell of mesh node k is its median dual cell: for every background cell around
// k, the part (sub-cell) X_k, midpoint of the edge k-next, cell centre (mean of the corners),
// midpoint of the edge prev-k, counter-clockwise. The parts of all cells tile the body exactly
// (conforming), whatever the particles; in the shipped cases the particles are the nodes, so
// this is nodal integration. On each part s, with W_s = A_s omega(c_s) (c_s its centroid,
// omega = 2 pi R: Pappus, exact),
//   T_s,J = integral over the boundary of s of N_J n omega ds         (Gauss points per segment)
//   g_s,J = T_s,J / W_s - e_r N_J(c_s) / R(c_s)                         (hoop term in axisymmetry)
// which reproduces linear fields exactly (the point at the centroid makes the hoop correction
// consistent) and makes sum_s W_s [g_s,J + e_r N_J(c_s) / R] = sum_s T_s,J telescope to the body
// boundary integral b_J: the integration constraint (19a) holds to round-off.
//   make_smoothing_cells        parts, grouped by node
//   make_nodal_points           one point per node (Beta = 0) or per part (Beta > 0)
//   make_split_boundary_points  the body's boundary split at the edge midpoints, Gauss points
//                               placed exactly as on the parts (for measuring (19a))
//   smooth_point_gradients      replaces at_points' gradients with the smoothed ones and widens
//                               its rows to every particle that touches the smoothing cell

#include <algorithm>
#include <array>
#include <vector>

#include <rkpm/approximation/rk_shape_functions.hpp>
#include <rkpm/concepts/correction.hpp>
#include <rkpm/concepts/geometry.hpp>
#include <rkpm/concepts/kernel.hpp>
#include <rkpm/core/error.hpp>
#include <rkpm/discretization/background_mesh.hpp>
#include <rkpm/discretization/integration_constraint.hpp>
#include <rkpm/discretization/neighbor_search.hpp>
#include <rkpm/discretization/particle_set.hpp>
#include <rkpm/discretization/quadrature_points.hpp>
#include <rkpm/discretization/shape_table.hpp>
#include <rkpm/quadrature/shaped_rules.hpp>

namespace rkpm {

// The parts of the smoothing cells, sorted by node.
//   corner  #parts 4 corners, counter-clockwise
//   cell    #parts background cell of the part
//   offset  #nodes+1: the parts of node k are offset[k] .. offset[k+1]-1 (none for a node no
//           cell uses)
struct smoothing_cells {
  std::vector<std::array<vec2, 4>> corner;
  std::vector<index_t> cell;
  std::vector<index_t> offset{0};
  index_t parts() const { return static_cast<index_t>(corner.size()); }
  index_t nodes() const { return static_cast<index_t>(offset.size()) - 1; }
};

inline smoothing_cells make_smoothing_cells(const background_mesh& mesh) {
  mesh.validate();
  const auto nodes = static_cast<index_t>(mesh.node.size());
  smoothing_cells s;
  s.offset.assign(nodes + 1, 0);
  for (const auto& c : mesh.cell)
    for (index_t k : c) ++s.offset[k + 1];
  for (index_t k = 0; k < nodes; ++k) s.offset[k + 1] += s.offset[k];
  s.corner.resize(s.offset[nodes]);
  s.cell.resize(s.offset[nodes]);
  std::vector<index_t> fill(s.offset.begin(), s.offset.end() - 1);
  for (index_t c = 0; c < mesh.cells(); ++c) {
    const auto& n = mesh.cell[c];
    std::array<vec2, 4> x{mesh.node[n[0]], mesh.node[n[1]], mesh.node[n[2]], mesh.node[n[3]]};
    const vec2 centre = 0.25 * (x[0] + x[1] + x[2] + x[3]);
    for (int a = 0; a < 4; ++a) {
      const int next = (a + 1) % 4, prev = (a + 3) % 4;
      const index_t slot = fill[n[a]]++;
      // Midpoints as 0.5 (first + second) in the cell's own order: the same bits on both
      // cells sharing the edge (addition commutes), so the Gauss points coincide.
      s.corner[slot] = {x[a], 0.5 * (x[a] + x[next]), centre, 0.5 * (x[prev] + x[a])};
      s.cell[slot] = c;
    }
  }
  return s;
}

// Points of a nodal rule and the parts each stands for.
//   points        positions (centroids), weights A omega(centroid), cells
//   parts_of      #points: [first, end) of its parts in smoothing_cells order
//   group_of      #points: [first, end) of the points of the same smoothing cell
struct nodal_points {
  quadrature_points points;
  std::vector<std::array<index_t, 2>> parts_of;
  std::vector<std::array<index_t, 2>> group_of;
};

template <Geometry G>
nodal_points make_nodal_points(const smoothing_cells& s, bool per_part) {
  nodal_points np;
  auto& qp = np.points;
  for (index_t k = 0; k < s.nodes(); ++k) {
    const index_t first = s.offset[k], end = s.offset[k + 1];
    if (first == end) continue;
    const auto group_first = qp.size();
    double area = 0.0;
    vec2 moment = vec2::Zero();
    for (index_t p = first; p < end; ++p) {
      const cell_point c = quadrature::detail::polygon_centroid<4>(s.corner[p]);
      if (!(c.area > 0.0))
        fail("smoothing cell of node {}: its part in background cell {} has area {:.3g}; the cell is not "
             "convex enough for nodal integration (scni)", k, s.cell[p], c.area);
      area += c.area;
      moment += c.area * c.position;
      if (per_part) {
        qp.position.push_back(c.position);
        qp.weight.push_back(c.area * G::weight_factor(c.position));
        qp.cell.push_back(s.cell[p]);
        np.parts_of.push_back({p, p + 1});
      }
    }
    if (!per_part) {
      const vec2 centroid = moment / area;
      qp.position.push_back(centroid);
      qp.weight.push_back(area * G::weight_factor(centroid));
      qp.cell.push_back(s.cell[first]);
      np.parts_of.push_back({first, end});
    }
    for (index_t q = group_first; q < qp.size(); ++q) np.group_of.push_back({group_first, qp.size()});
  }
  return np;
}


// The body's boundary with each edge split at its midpoint, `points` Gauss points per half:
// the points the smoothing cells use on the boundary, so that b_I from them is the sum of the
// parts' boundary integrals to round-off.
template <Geometry G>
boundary_points make_split_boundary_points(const background_mesh& mesh, int points) {
  boundary_points b;
  for (const auto& [i, j] : mesh.boundary_edges()) {
    const vec2 &A = mesh.node[i], &B = mesh.node[j];
    const vec2 m = 0.5 * (A + B);
    detail::add_segment_points<G>(A, m, points, b, /*keep_axis_points=*/true);
    detail::add_segment_points<G>(m, B, points, b, /*keep_axis_points=*/true);
  }
  return b;
}

// Smoothed gradients (docs/method.md (19e)-(19g)) on the points of `np`: at_points (built at
// np.points by build_shape_table) gets, at every point, one entry for every particle that
// touches its smoothing cell (N kept, zero for the particles added), with the gradient
//   Beta = 0: g_J = sum_s T_s,J / W - e_r N_J(c) / R(c)          (one point per smoothing cell)
//   Beta > 0: g_J = g_cell,J + Beta (g_s,J - g_cell,J),  g_cell,J = sum_s W_s g_s,J / sum_s W_s
template <Kernel K, Correction C, Geometry G>
void smooth_point_gradients(const particle_set<2>& particles, const smoothing_cells& s, const nodal_points& np,
                            double beta, int edge_points, shape_table<2>& at_points,
                            double max_condition = default_max_moment_condition) {
  // Gauss points of the four segments of every part: part p owns 4 * edge_points points.
  boundary_points seg;
  for (index_t p = 0; p < s.parts(); ++p)
    for (int k = 0; k < 4; ++k)
      detail::add_segment_points<G>(s.corner[p][k], s.corner[p][(k + 1) % 4], edge_points, seg,
                                    /*keep_axis_points=*/true);
  const neighbor_search<2> search(particles);
  const shape_table<2> at_seg =
      build_shape_table<K, C, 2>(search, seg.position, rk_shape_functions<K, C, 2>(max_condition));
  const index_t per_part = 4 * edge_points, n = particles.size(), nq = np.points.size();
  const auto& qp = np.points;

  // Per point, the smoothed gradient of every particle of its group; assembled per group.
  std::vector<std::vector<index_t>> nbr(nq);
  std::vector<std::vector<double>> val(nq);
  std::vector<std::vector<vec2>> grd(nq);
  std::vector<index_t> slot(n, -1);
  std::vector<index_t> touched;
  std::vector<vec2> own, mean;  // per touched particle: the point's own g_s, the group's weighted sum
  for (index_t g0 = 0; g0 < nq; g0 = np.group_of[g0][1]) {
    const index_t g1 = np.group_of[g0][1];
    touched.clear();
    auto add = [&](index_t J) {
      if (slot[J] < 0) {
        slot[J] = static_cast<index_t>(touched.size());
        touched.push_back(J);
      }
    };
    for (index_t q = g0; q < g1; ++q) {
      for (index_t e = at_points.offset[q]; e < at_points.offset[q + 1]; ++e) add(at_points.neighbor[e]);
      for (index_t p = np.parts_of[q][0]; p < np.parts_of[q][1]; ++p)
        for (index_t b = p * per_part; b < (p + 1) * per_part; ++b)
          for (index_t e = at_seg.offset[b]; e < at_seg.offset[b + 1]; ++e) add(at_seg.neighbor[e]);
    }
    const auto m = touched.size();
    std::vector<std::vector<vec2>> point_g(static_cast<std::size_t>(g1 - g0), std::vector<vec2>(m, vec2::Zero()));
    mean.assign(m, vec2::Zero());
    double group_weight = 0.0;
    for (index_t q = g0; q < g1; ++q) {
      auto& gq = point_g[q - g0];
      for (index_t p = np.parts_of[q][0]; p < np.parts_of[q][1]; ++p)
        for (index_t b = p * per_part; b < (p + 1) * per_part; ++b)
          for (index_t e = at_seg.offset[b]; e < at_seg.offset[b + 1]; ++e)
            gq[slot[at_seg.neighbor[e]]] += at_seg.N[e] * seg.weight[b] * seg.normal[b];
      const double W = qp.weight[q];
      for (auto& x : gq) x /= W;
      if constexpr (G::is_axisymmetric)
        for (index_t e = at_points.offset[q]; e < at_points.offset[q + 1]; ++e)
          gq[slot[at_points.neighbor[e]]][0] -= at_points.N[e] / qp.position[q][0];
      for (std::size_t j = 0; j < m; ++j) mean[j] += W * gq[j];
      group_weight += W;
    }
    for (auto& x : mean) x /= group_weight;
    for (index_t q = g0; q < g1; ++q) {
      nbr[q] = touched;
      val[q].assign(m, 0.0);
      for (index_t e = at_points.offset[q]; e < at_points.offset[q + 1]; ++e) val[q][slot[at_points.neighbor[e]]] = at_points.N[e];
      grd[q].resize(m);
      const auto& gq = point_g[q - g0];
      for (std::size_t j = 0; j < m; ++j) grd[q][j] = (g1 - g0 == 1) ? gq[j] : vec2(mean[j] + beta * (gq[j] - mean[j]));
    }
    for (index_t J : touched) slot[J] = -1;
  }
  shape_table<2> t;
  t.offset.assign(nq + 1, 0);
  for (index_t q = 0; q < nq; ++q) t.offset[q + 1] = t.offset[q] + static_cast<index_t>(nbr[q].size());
  for (index_t q = 0; q < nq; ++q) {
    t.neighbor.insert(t.neighbor.end(), nbr[q].begin(), nbr[q].end());
    t.N.insert(t.N.end(), val[q].begin(), val[q].end());
    t.grad.insert(t.grad.end(), grd[q].begin(), grd[q].end());
  }
  at_points = std::move(t);
}

}  // namespace rkpm
