#pragma once
// penetrated_segment: which segment of a deformable surface a point is behind (docs/method.md
// section 6.9), for the body pairs' slaves (body_contact.hpp) and the tools' vertices
// (tool_vertex_contact.hpp). Segment a-b of the surface, at the particles' physical positions
// x, catches the point P if
//   lambda = (P - x_a) . t / |t|^2 in [0, 1],   g = -(P - x_a) . n in (0, depth],
// with t = x_b - x_a and n = (t_y, -t_x) / |t| the surface's outward normal (the chains run with
// the body on their left). Of the candidates that catch P, the one with the smallest g, the
// first of them in the candidates' order if several tie. A slave against its own body's surface
// (self-contact, docs/method.md (108)) leaves out the segments within its kernel's reach
// (within_kernel_reach), which the surface beside it, curving or wrinkled, would otherwise give.

#include <algorithm>
#include <array>
#include <span>

#include <rkpm/core/types.hpp>
#include <rkpm/discretization/shape_table.hpp>

namespace rkpm::contact {

struct surface_hit {
  index_t segment = -1;  // index into the segments; -1: none catches the point
  double lambda = 0.0;   // the point's projection (1 - lambda) x_a + lambda x_b
  double gap = 0.0;      // g
  vec2 normal = vec2::Zero();
};

// (108): whether slave J is a or b or its row of the shape functions at the particles holds a
// or b (N_a(X_J) or N_b(X_J) nonzero: the rows leave out only zeros).
inline bool within_kernel_reach(const shape_table<2>& rows, index_t J, index_t a, index_t b) {
  if (J == a || J == b) return true;
  for (index_t e = rows.offset[J]; e < rows.offset[J + 1]; ++e)
    if (rows.neighbor[e] == a || rows.neighbor[e] == b) return true;
  return false;
}

// candidates: indices into segments (e.g. segment_grid::candidates, or all of them). excluded(a, b):
// segments never to take (asked only of those that catch P, so a search that excludes nothing
// costs nothing more). overhang(a, b): how far past its ends, in lambda, segment a-b catches P,
// which then meets it at the end (lambda clamped to [0, 1]); 0 for a surface's segments, more for
// the faces of cracks (docs/method.md (114)).
template <class Candidates, class Excluded, class Overhang>
surface_hit penetrated_segment(std::span<const std::array<index_t, 2>> segments, const Candidates& candidates,
                               std::span<const vec2> x, const vec2& P, double depth, Excluded&& excluded,
                               Overhang&& overhang) {
  surface_hit best;
  for (const index_t s : candidates) {
    const auto [a, b] = segments[s];
    const vec2 t = x[b] - x[a];
    const double L = t.norm();
    const vec2 r = P - x[a];
    if (r.squaredNorm() > (L + depth) * (L + depth)) continue;
    const double lambda = r.dot(t) / (L * L), past = overhang(a, b);
    if (lambda < -past || lambda > 1.0 + past) continue;
    const vec2 normal(t[1] / L, -t[0] / L);
    const double g = -r.dot(normal);
    if (g <= 0.0 || g > depth) continue;
    if (excluded(a, b)) continue;
    if (best.segment < 0 || g < best.gap) best = surface_hit{s, std::clamp(lambda, 0.0, 1.0), g, normal};
  }
  return best;
}

template <class Candidates, class Excluded>
surface_hit penetrated_segment(std::span<const std::array<index_t, 2>> segments, const Candidates& candidates,
                               std::span<const vec2> x, const vec2& P, double depth, Excluded&& excluded) {
  return penetrated_segment(segments, candidates, x, P, depth, excluded, [](index_t, index_t) { return 0.0; });
}

template <class Candidates>
surface_hit penetrated_segment(std::span<const std::array<index_t, 2>> segments, const Candidates& candidates,
                               std::span<const vec2> x, const vec2& P, double depth) {
  return penetrated_segment(segments, candidates, x, P, depth, [](index_t, index_t) { return false; });
}

}  // namespace rkpm::contact
