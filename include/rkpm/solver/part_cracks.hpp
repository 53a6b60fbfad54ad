#pragma once
// Cracks on a rank's part of a run on several processes (docs/method.md sections 5.12 and 9.8).
// The part holds no mesh and cuts no cell: it decides, alike on every rank, whether the whole
// model's failed points cut one now (explicit_solver::grow_cracks), and leaves the rebuild
// pending; parallel::distributed_solver then cuts and rebuilds the whole model as one process
// does and builds every part again from it (parallel/distributed_rereference.hpp).
//   cells_around_points  each point's cell as the part sees it (its corners and neighbours)
//   part_cuts_a_cell     whether the whole model's grow_cracks would cut a cell now (collective)

#include <algorithm>
#include <array>
#include <optional>
#include <vector>

#include <rkpm/core/process_group.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/discretization/background_mesh.hpp>
#include <rkpm/solver/crack_growth.hpp>
#include <rkpm/solver/discrete_model.hpp>
#include <rkpm/solver/fields.hpp>

namespace rkpm {

// A rank's part `part` (parallel/local_model.hpp) of the model whose cells are `whole`: each of
// its points' cell, its corners by local ids (the nodes are the particles) and its neighbours;
// empty when the nodes are not the particles or the points have no cells.
inline std::vector<cell_around> cells_around_points(const background_mesh& whole, const discrete_model& part) {
  std::vector<cell_around> out;
  if (part.points.cell.size() != static_cast<std::size_t>(part.point_count())) return out;
  std::vector<stored_index> local(whole.node.size(), -1);
  for (index_t i = 0; i < part.particle_count(); ++i) {
    if (part.particle_id[i] >= static_cast<stored_index>(local.size())) return out;
    local[part.particle_id[i]] = static_cast<stored_index>(i);
  }
  const std::vector<std::array<index_t, 4>> neighbours = cell_neighbours(whole);
  out.resize(part.points.cell.size());
  for (index_t q = 0; q < part.point_count(); ++q) {
    const index_t c = part.points.cell[q];
    for (int k = 0; k < 4; ++k) out[q].corner[k] = local[whole.cell[c][k]];
    out[q].neighbour = neighbours[c];
  }
  return out;
}

// On a rank's part (section 9.8), collectively: whether explicit_solver::grow_cracks of the whole
// model would cut a cell now, the same answer on every rank. It cuts one if and only if some
// failed point, in a cell not cut yet, has a cut that the cuts so far leave (beside_a_cut; the
// first such point in point order is cut with the cuts so far, and a point refused by them is
// refused by more). Each rank asks that of the points it owns, on the current positions of
// their cells' corners (its owned particles', forwarded to its ghosts), and the answers are
// or-ed (a max over the ranks). A failed point whose cell the part cannot see (a corner not held,
// or no cells_around) answers yes: the rebuild then decides on the whole model, which a wrong
// yes costs time, not bits. `d`: the coefficients, ghosts' current.
// `look`: whether this rank reads its states (false: none of its points can cut, as its last look
// found, point_materials::failures_to_scan); `left_uncut`: whether it found a failed point in a
// cell not cut.
template <class State>
bool part_cuts_a_cell(const discrete_model& part, const std::vector<State>& states, const std::vector<cell_crack>& cuts,
                      const std::vector<vec2>& d, bool look, bool& left_uncut) {
  process_group& group = *part.own.group;
  std::vector<index_t> failed;  // allocates only when some point has failed
  if (look)
    for_each_owned_point(part, [&](index_t q) {
      const State& s = states[q];
      if (s.failed() && vec2(s.crack_normal).squaredNorm() > 0.0 && !is_cut(cuts, part.points.cell[q]))
        failed.push_back(q);
    });
  left_uncut = !failed.empty();
  if (!(group.max(failed.empty() ? 0.0 : 1.0) > 0.0)) return false;
  std::vector<vec2> x(part.particle_count(), vec2::Zero());
  for (index_t I = part.own.particles.begin; I < part.own.particles.end; ++I) x[I] = position_at_particle(part, d, I);
  group.forward(x);
  bool cut = false;
  for (const index_t q : failed) {
    if (part.cells_around.empty() || std::ranges::find(part.cells_around[q].corner, -1) != part.cells_around[q].corner.end()) {
      cut = true;
      break;
    }
    const cell_around& around = part.cells_around[q];
    const std::array<vec2, 4> corner{x[around.corner[0]], x[around.corner[1]], x[around.corner[2]], x[around.corner[3]]};
    const std::optional<cell_crack> k = cut_cell(corner, part.points.cell[q], vec2(states[q].crack_normal).normalized());
    if (k && !beside_a_cut(around.neighbour, cuts, *k)) {
      cut = true;
      break;
    }
  }
  return group.max(cut ? 1.0 : 0.0) > 0.0;
}

}  // namespace rkpm
