#pragma once
// choose_segment: which master segment of a tool a penetrating slave particle is pushed out of
// (step 1 of the contact subroutine, docs/method.md section 6.8). Among the segments that catch
// the particle (rigid_tool::catches), prefer, in this order:
//   1. the face its path from the previous call crossed (the first one crossed along the path),
//      which is the physically right one at concave corners where a particle is behind two faces;
//   2. the segment that held it at the previous call (a particle kept slightly inside by a partial
//      correction has not crossed anything this step);
//   3. the face with the smallest penetration (the nearest face).
// A particle sliding past a vertex leaves the band of its old segment and is taken over by the
// next one through rule 1 or 3.

#include <span>

#include <rkpm/contact/rigid_tool.hpp>

namespace rkpm::contact {

struct segment_hit {
  index_t segment = -1;  // -1: no penetration
  double gap = 0.0;      // penetration g > 0 along the segment normal
};

// y, y_prev: the particle now and at the previous call, both in the tool frame.
inline segment_hit choose_segment(const rigid_tool& tool, std::span<const index_t> candidates, const vec2& y,
                                  const vec2& y_prev, index_t previous_segment) {
  segment_hit crossed, held, nearest;
  double first_crossing = 2.0;
  for (const index_t k : candidates) {
    double g;
    if (!tool.catches(k, y, g)) continue;
    if (nearest.segment < 0 || g < nearest.gap) nearest = {k, g};
    if (k == previous_segment) held = {k, g};
    const double before = tool.project(k, y_prev).distance;
    if (before >= 0.0) {
      const double tau = before / (before + g);  // where the path meets the face's line
      const double lambda = tool.project(k, vec2(y_prev + tau * (y - y_prev))).lambda;
      if (lambda >= -1e-12 && lambda <= 1.0 + 1e-12 && tau < first_crossing) {
        first_crossing = tau;
        crossed = {k, g};
      }
    }
  }
  if (crossed.segment >= 0) return crossed;
  if (held.segment >= 0) return held;
  return nearest;
}

}  // namespace rkpm::contact
