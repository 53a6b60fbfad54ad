#pragma once
// crack_face_rows: the faces of the cracks cut through a model's cells (crack_set::faces) as
// surfaces that contact can see (docs/method.md section 6.11, (114)). Each cut cell's chord is two
// faces, one per side of the crack; a face is a segment between two virtual points, the chord's
// ends P, each with its row of shape functions seen from that face's side only: the particles
// whose support holds P and whose sight line from a point just inside the side crosses no crack
// (112), and the RK functions at P over them. The reproducing conditions hold at P on the side's
// particles alone, so x_P = P + sum_I N_I(P) d_I moves with that side (a rigid motion of the side
// carries it exactly) and the other side never moves it.
//   position  #points P, reference configuration
//   rows      #points rows N_I(P), values only (entries below 1e-30 left out, as values_only)
//   segment   #faces the two points of each face, its side's material on the left (the outward
//             normal (t_y, -t_x) / |t| points across the crack), as boundary chains run
//   body      #faces the body of the face's cell
// A face whose side sees too few particles for the correction (a sliver) is left out.

#include <array>
#include <cmath>
#include <vector>

#include <rkpm/approximation/rk_shape_functions.hpp>
#include <rkpm/discretization/crack_set.hpp>
#include <rkpm/discretization/model_bodies.hpp>
#include <rkpm/discretization/neighbor_search.hpp>
#include <rkpm/discretization/particle_set.hpp>
#include <rkpm/discretization/shape_table.hpp>

namespace rkpm {

struct crack_face_rows {
  std::vector<vec2> position;
  shape_table<2> rows;
  std::vector<std::array<index_t, 2>> segment;
  std::vector<index_t> body;

  index_t points() const { return static_cast<index_t>(position.size()); }
  index_t faces() const { return static_cast<index_t>(segment.size()); }
  bool empty() const { return segment.empty(); }
};

// The faces of `cracks` (none if it has no faces) over `particles`, each seen within its cell's
// body of `bodies`.
template <Kernel K, Correction C>
crack_face_rows build_crack_face_rows(const particle_set<2>& particles, const crack_set& cracks,
                                      const model_bodies& bodies, double max_condition) {
  crack_face_rows out;
  if (cracks.faces().empty()) return out;
  const neighbor_search<2> supports(particles);  // without the cracks: the sight lines are checked below
  const rk_shape_functions<K, C, 2> rk(max_condition);
  std::vector<index_t> found, seen;
  std::vector<double> N;
  std::vector<vec2> grad;
  std::array<std::vector<double>, 2> value;
  std::array<std::vector<index_t>, 2> column;
  for (const crack_set::face_type& face : cracks.faces()) {
    const index_t b = bodies.of_cell(face.cell);
    const vec2 t = face.chord[1] - face.chord[0];
    if (!(t.norm() > 0.0)) continue;
    const vec2 left(-t[1], t[0]);  // into the material left of the chord
    for (const double side : {1.0, -1.0}) {
      bool seen_enough = true;
      for (int e = 0; e < 2; ++e) {
        const vec2& P = face.chord[e];
        // Just off the chord on this side: the visibility of (112) from inside the material.
        const vec2 from = P + side * 1e-6 * left;
        supports.query(P, found);
        seen.clear();
        for (const index_t I : found)
          if (bodies.of_particle(I) == b && !cracks.blocks(from, particles.position[I])) seen.push_back(I);
        if (!rk.try_evaluate(P, particles, seen, N, grad)) seen_enough = false;
        value[e].clear();
        column[e].clear();
        for (std::size_t j = 0; j < N.size(); ++j)
          if (std::abs(N[j]) >= values_only.drop_below) {
            value[e].push_back(N[j]);
            column[e].push_back(seen[j]);
          }
      }
      if (!seen_enough) continue;
      // The left side's face runs along the chord, the right side's against it.
      const std::array<int, 2> order = side > 0.0 ? std::array<int, 2>{0, 1} : std::array<int, 2>{1, 0};
      std::array<index_t, 2> points{};
      for (int k = 0; k < 2; ++k) {
        const int e = order[k];
        points[k] = out.points();
        out.position.push_back(face.chord[e]);
        for (std::size_t j = 0; j < value[e].size(); ++j) {
          out.rows.neighbor.push_back(static_cast<particle_index>(column[e][j]));
          out.rows.N.push_back(value[e][j]);
        }
        out.rows.offset.push_back(static_cast<stored_index>(out.rows.neighbor.size()));
      }
      out.segment.push_back(points);
      out.body.push_back(b);
    }
  }
  return out;
}

}  // namespace rkpm
