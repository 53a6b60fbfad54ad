#pragma once
// What the force loop's tiles record of their points (solver/point_materials.hpp): the narrowest
// support stretch and the plastic work summed in point order, and the first point that failed
// (det F <= 0 or a failed material update), reported once the loop is over with the step it
// belongs to, the same whatever the thread count.

#include <limits>
#include <string>

#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/solver/discrete_model.hpp>

namespace rkpm {

// The step a force evaluation belongs to: where an error happened, for its message, and what
// the material update is told of the step (material_step, concepts/material.hpp).
struct step_context {
  index_t step = 0;
  double time = 0.0;  // s, at the end of the step
  double dt = 0.0;    // s, 0 for the evaluation at the start
};

enum class point_failure : char { none, inverted, material };

// What a tile's points left in the last evaluation.
struct point_tile_summary {
  double narrowest = std::numeric_limits<double>::infinity();
  double plastic = 0.0;
  index_t broken = 0;  // points whose state has failed (BreakingState: a damage at 1)
  point_failure failed = point_failure::none;
  index_t point = -1;  // the first failed point of the tile
  double det = 0.0;    // its det F
  void fail(index_t q, point_failure why, double J) {
    if (failed != point_failure::none) return;
    failed = why;
    point = q;
    det = J;
  }
};

// The error of a tile's failed point; `message`: the material's, for a failed update.
[[noreturn]] inline void report_point_failure(const discrete_model& m, const point_tile_summary& tile,
                                              step_context where, const std::string& message) {
  const index_t q = tile.point;
  const vec2& X = m.points.position[q];
  if (tile.failed == point_failure::material)
    fail("step {}, t = {:.6g} s: the material update failed at quadrature point {} (X = {:.6g}, {:.6g}): {}",
         where.step, where.time, m.global_point(q), X[0], X[1], message);
  fail("step {}, t = {:.6g} s: det F = {:.6g} at quadrature point {} (X = {:.6g}, {:.6g}): the body "
       "has inverted or the solution has blown up; reduce the time step fraction, refine the "
       "particles or check the boundary conditions. Output written so far is kept",
       where.step, where.time, tile.det, m.global_point(q), X[0], X[1]);
}

}  // namespace rkpm
