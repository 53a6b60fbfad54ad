#pragma once
// The cracks and failed points of a VTK snapshot (docs/method.md section 9.4). A cell that a
// crack cuts (solver/crack_growth.hpp) is not drawn as one quad, which would bridge the opened
// crack, but as its two sides, each a VTK_POLYGON of the corners on that side and the two points
// where the crack crosses the cell's sides, placed where that side's material has taken them: so
// ParaView shows the crack open as wide as the approximation has it. Each failed material point
// is a vertex of its own at its current position, for a viewer to pick out.
//   crack_face_points(m, cuts, d)   the crossing points of every cut on each side, at their
//                                   current positions: each fitted from the particles on its side
//   snapshot_extras_of(s)           those and the failed points, with the particle whose values
//                                   each carries and its kind, and the cells
//   snapshot_of(s)                  a snapshot's points, cells and point arrays, with the extras
//                                   when there are any: what write_vtu's piecewise form takes
// A crossing on the side of corner a is placed by the affine map x = b + A (X - X_c) fitted by
// weighted least squares to the current positions of the particles around its cell that see it
// (no crack between, (112)); it reproduces every field linear on that side exactly, as the
// approximation there does, and whatever the other side does. A side seen by fewer than three
// particles not on a line moves with corner a. Extra points carry the point arrays of a
// particle (a crossing its corner a, a failed point the particle of largest N_J(X_q) in its
// row); the array "point_kind" tells them apart: 0 particle, 1 crack face, 2 failed point.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <Eigen/LU>

#include <rkpm/concepts/material.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/io/point_data.hpp>
#include <rkpm/io/solver_output.hpp>
#include <rkpm/io/vtu_cells.hpp>
#include <rkpm/solver/crack_growth.hpp>
#include <rkpm/solver/discrete_model.hpp>
#include <rkpm/solver/fields.hpp>

namespace rkpm::io {

inline constexpr std::uint8_t point_kind_particle = 0, point_kind_crack_face = 1, point_kind_failed_point = 2;

struct crack_faces {
  // Per cut (in cut order) four crossings: side[0] and side[1] seen from the corners after
  // side[0] (the "first" polygon), then side[1] and side[0] seen from the others.
  std::vector<vec2> position;  // current positions
  std::vector<index_t> corner;  // each crossing's corner a: the particle whose values it carries
};

namespace detail {

// Where the material point X_c on the side of particle a is now: the affine fit over the
// particles `near` that see it, weighted (1 - (r / R)^2)^2 with R 1.5 times the farthest.
inline vec2 fitted_position(const discrete_model& m, const std::vector<vec2>& x, const std::vector<index_t>& near,
                            const vec2& X_c, index_t a) {
  const vec2 from = X_c + 1e-6 * (m.particles.position[a] - X_c);  // just off the crack, on a's side
  std::vector<index_t> seen;
  double reach = 0.0;
  for (const index_t I : near)
    if (!m.mesh.cracks.blocks(from, m.particles.position[I])) {
      seen.push_back(I);
      reach = std::max(reach, (m.particles.position[I] - X_c).norm());
    }
  const vec2 moved_with_a = x[a] + (X_c - m.particles.position[a]);
  if (seen.size() < 3) return moved_with_a;
  const double R = 1.5 * reach;
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  Eigen::Matrix<double, 3, 2> rhs = Eigen::Matrix<double, 3, 2>::Zero();
  for (const index_t I : seen) {
    const vec2 dX = (m.particles.position[I] - X_c) / R;
    const double w = std::pow(1.0 - dX.squaredNorm(), 2);
    const Eigen::Vector3d p(1.0, dX[0], dX[1]);
    M += w * p * p.transpose();
    rhs += w * p * x[I].transpose();
  }
  // The seen on a line leave M singular: its determinant against the cube of its mean diagonal.
  if (!(M.determinant() > 1e-12 * std::pow(M.trace() / 3.0, 3))) return moved_with_a;
  return (M.inverse() * rhs).row(0).transpose();  // b: the fit at X_c
}

}  // namespace detail

// The crossings of every cut of m's cells at their current positions (d: the coefficients).
inline crack_faces crack_face_points(const discrete_model& m, const std::vector<cell_crack>& cuts,
                                     const std::vector<vec2>& d) {
  crack_faces out;
  if (cuts.empty()) return out;
  const std::vector<vec2> x = positions_at_particles(m, d);
  const auto cells_at = cells_at_nodes(m.mesh);
  for (const cell_crack& cut : cuts) {
    const auto& corner = m.mesh.cell[cut.cell];
    std::vector<index_t> near;  // the corners of the cells that share a corner with this one
    for (const stored_index n : corner)
      for (const index_t c : cells_at[n])
        for (const stored_index k : m.mesh.cell[c]) near.push_back(k);
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    const auto crossing = [&](int e) {
      const index_t k = cut.side[e];
      return ((1.0 - cut.at[e]) * m.particles.position[corner[k]] +
              cut.at[e] * m.particles.position[corner[(k + 1) % 4]]).eval();
    };
    // Side k runs from corner k to k + 1: the first polygon holds corners side[0] + 1 .. side[1].
    const std::array<std::pair<int, index_t>, 4> seen_from{{{0, corner[(cut.side[0] + 1) % 4]},
                                                            {1, corner[cut.side[1]]},
                                                            {1, corner[(cut.side[1] + 1) % 4]},
                                                            {0, corner[cut.side[0]]}}};
    for (const auto& [e, a] : seen_from) {
      out.position.push_back(detail::fitted_position(m, x, near, crossing(e), a));
      out.corner.push_back(a);
    }
  }
  return out;
}

// A snapshot's points beyond the particles, and its cells.
struct snapshot_extras {
  std::vector<vec2> position;       // current positions
  std::vector<index_t> source;      // the particle whose point arrays each carries
  std::vector<std::uint8_t> kind;   // point_kind_crack_face or point_kind_failed_point
  vtu_cells cells;                  // on the particles (first) and the extras (after them)
  bool empty() const { return position.empty(); }
};

// The crack faces and failed points of s, when its cracks can grow or it has cuts (a notch cut
// before the run) and its particles are the cells' nodes; empty otherwise (the plain snapshot).
template <class Solver>
snapshot_extras snapshot_extras_of(const Solver& s) {
  snapshot_extras out;
  if constexpr (requires { s.cracks_can_grow(); }) {
    const discrete_model& m = s.model();
    const bool nodes = m.bodies.found() ? m.bodies.nodes_are_particles()
                                        : rkpm::nodes_are_particles(m.particles.position, m.mesh);
    if ((!s.cracks_can_grow() && s.cracks().empty()) || !nodes) return out;
    const auto n = static_cast<std::int64_t>(m.particle_count());
    const std::vector<cell_crack>& cuts = s.cracks();
    const crack_faces faces = crack_face_points(m, cuts, s.coefficients());
    out.position = faces.position;
    out.source = faces.corner;
    out.kind.assign(faces.position.size(), point_kind_crack_face);
    using state_type = typename Solver::state_type;
    if constexpr (FailingState<state_type>)
      for (index_t q = 0; q < m.point_count(); ++q) {
        if (!s.point_states()[q].failed()) continue;
        out.position.push_back(m.points.position[q] + m.at_points.interpolate(q, s.coefficients()));
        index_t largest = m.at_points.offset[q];
        for (index_t e = largest; e < m.at_points.offset[q + 1]; ++e)
          if (m.at_points.N[e] > m.at_points.N[largest]) largest = e;
        out.source.push_back(m.at_points.neighbor[largest]);
        out.kind.push_back(point_kind_failed_point);
      }
    if (out.empty()) return out;
    // The cells: uncut cells as quads, a cut one as its two sides, each extra a vertex.
    vtu_cells& c = out.cells;
    const auto close_cell = [&c](std::uint8_t type) {
      c.offsets.push_back(static_cast<std::int64_t>(c.connectivity.size()));
      c.types.push_back(type);
    };
    std::size_t next_cut = 0;
    std::vector<bool> used(static_cast<std::size_t>(n), false);
    for (index_t cell = 0; cell < m.mesh.cells(); ++cell) {
      const auto& corner = m.mesh.cell[cell];
      for (const stored_index k : corner) used[k] = true;
      if (next_cut < cuts.size() && cuts[next_cut].cell == cell) {
        const cell_crack& cut = cuts[next_cut];
        const std::int64_t face = n + 4 * static_cast<std::int64_t>(next_cut);
        c.connectivity.push_back(face);  // the first side: side[0]'s crossing, its corners, side[1]'s
        for (int k = cut.side[0] + 1; k <= cut.side[1]; ++k) c.connectivity.push_back(corner[k]);
        c.connectivity.push_back(face + 1);
        close_cell(vtk_polygon);
        c.connectivity.push_back(face + 2);  // the second: side[1]'s crossing, the others, side[0]'s
        for (int k = cut.side[1] + 1; k <= cut.side[0] + 4; ++k) c.connectivity.push_back(corner[k % 4]);
        c.connectivity.push_back(face + 3);
        close_cell(vtk_polygon);
        ++next_cut;
        continue;
      }
      for (const stored_index k : corner) c.connectivity.push_back(k);
      close_cell(vtk_quad);
    }
    for (std::int64_t I = 0; I < n; ++I)
      if (!used[static_cast<std::size_t>(I)]) {
        c.connectivity.push_back(I);
        close_cell(vtk_vertex);
      }
    for (std::size_t k = 4 * cuts.size(); k < out.position.size(); ++k) {
      c.connectivity.push_back(n + static_cast<std::int64_t>(k));
      close_cell(vtk_vertex);
    }
  }
  return out;
}

// A snapshot's points (their coordinates made piecewise), cells and point arrays, as write_vtu's
// piecewise form takes them: the plain ones of io/solver_output.hpp, with the extras and the
// array "point_kind" when there are any.
struct snapshot_parts {
  std::size_t points = 0;
  std::function<point_data::filler()> xyz;
  cell_layout cells;
  point_data fields;
};

template <class Solver>
snapshot_parts snapshot_of(const Solver& s, field_arrays when = field_arrays::deferred) {
  const auto n = static_cast<std::size_t>(s.model().particle_count());
  snapshot_extras extras = snapshot_extras_of(s);
  if (extras.empty()) return {n, snapshot_points(s), snapshot_cell_layout(s), snapshot_fields(s, when)};
  point_data fields = with_extra_points(snapshot_fields(s, when), n, extras.source);
  std::vector<double> kind(n, static_cast<double>(point_kind_particle));
  for (const std::uint8_t k : extras.kind) kind.push_back(static_cast<double>(k));
  fields.add("point_kind", std::move(kind));
  auto at = std::make_shared<const std::vector<vec2>>(std::move(extras.position));
  auto xyz = [particles = snapshot_points(s), at, n] {
    return point_data::filler([fill = particles(), at, n](std::size_t first, std::size_t count, double* out) {
      const std::size_t own = first < 3 * n ? std::min(count, 3 * n - first) : 0;
      if (own > 0) fill(first, own, out);
      for (std::size_t k = own; k < count; ++k) {
        const std::size_t entry = first + k - 3 * n;
        out[k] = entry % 3 < 2 ? (*at)[entry / 3][static_cast<index_t>(entry % 3)] : 0.0;
      }
    });
  };
  return {n + at->size(), std::move(xyz), cell_layout::given(std::move(extras.cells)), std::move(fields)};
}

}  // namespace rkpm::io
