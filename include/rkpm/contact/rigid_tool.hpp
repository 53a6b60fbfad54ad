#pragma once
// rigid_tool: a master surface of docs/method.md section 6, an open polyline of segments
// P_k - P_{k+1} that translates rigidly with a prescribed motion. body_side says on which side
// of the polyline direction the body lies; the unit normals n_k point out of the tool toward
// the body. Because the tool only translates, its geometry is kept in its own frame
// (the vertices at t = 0) and a world point x is looked at as y = x - u(t).
//
// Which segment "catches" a point y (the master-segment test of the contact subroutine, step i):
//   gap g = -(y - P_k) . n_k must satisfy 0 < g <= max_depth, so a particle far behind a face
//   (for example beneath the other side of a thin tool) is not pulled through it;
//   the projection lambda = (y - P_k) . t_k / L_k must lie in [0, 1], except inside the wedge
//   behind a concave vertex of the tool (tool-side angle above 180 degrees) where neither face's
//   band reaches: there a point behind both adjacent faces (within the depth of each) and past
//   the shared vertex of both is caught by both, and the caller chooses (segment_search.hpp).

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <rkpm/contact/tool_motion.hpp>
#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>

namespace rkpm::contact {

// Side of the polyline direction P_0 -> P_1 -> ... on which the body lies.
enum class side { left, right };

class rigid_tool {
 public:
  // max_depth: deepest penetration a segment still acts on; 0 picks half the shortest segment.
  rigid_tool(std::string name, std::vector<vec2> vertices_at_t0, side body_side,
             tool_motion motion = {}, double max_depth = 0.0)
      : name_(std::move(name)), vertex_(std::move(vertices_at_t0)), side_(body_side),
        motion_(std::move(motion)) {
    const index_t nv = static_cast<index_t>(vertex_.size());
    if (nv < 2) fail("rigid tool '{}': {} vertices; give at least 2 (one segment)", name_, nv);
    for (index_t i = 0; i < nv; ++i)
      if (!vertex_[i].allFinite()) fail("rigid tool '{}': vertex {} is not finite", name_, i);
    const double sigma = body_side == side::left ? 1.0 : -1.0;
    double shortest = INFINITY;
    for (index_t k = 0; k + 1 < nv; ++k) {
      const vec2 e = vertex_[k + 1] - vertex_[k];
      const double L = e.norm();
      if (!(L > 0.0))
        fail("rigid tool '{}': segment {} from vertex {} to {} has zero length; remove the repeated vertex "
             "({}, {})",
             name_, k, k, k + 1, vertex_[k].x(), vertex_[k].y());
      length_.push_back(L);
      tangent_.push_back(e / L);
      normal_.push_back(sigma * vec2(-e.y(), e.x()) / L);
      shortest = std::min(shortest, L);
    }
    if (max_depth < 0.0 || !std::isfinite(max_depth))
      fail("rigid tool '{}': max_depth {} must be finite and >= 0 (0 picks half the shortest segment)", name_,
           max_depth);
    depth_ = max_depth > 0.0 ? max_depth : 0.5 * shortest;
    // A vertex is concave for the tool when the polyline turns toward the body there.
    concave_.assign(nv, false);
    reach_ = depth_;
    for (index_t v = 1; v + 1 < nv; ++v) {
      const vec2& a = tangent_[v - 1];
      const vec2& b = tangent_[v];
      const double turn = sigma * (a.x() * b.y() - a.y() * b.x());
      if (turn > 1e-12) {
        concave_[v] = true;
        // The wedge behind both faces, within depth of each, reaches depth / cos(phi / 2) from
        // the vertex (phi the angle between the normals); cap it for near-hairpin turns.
        const double c = std::sqrt(std::max(0.0, 0.5 * (1.0 + normal_[v - 1].dot(normal_[v]))));
        reach_ = std::max(reach_, depth_ / std::max(c, 0.1));
      }
    }
  }

  const std::string& name() const { return name_; }
  side body_side() const { return side_; }
  const tool_motion& motion() const { return motion_; }
  const std::vector<vec2>& reference_vertices() const { return vertex_; }
  index_t segments() const { return static_cast<index_t>(length_.size()); }
  const vec2& tangent(index_t k) const { return tangent_[k]; }
  const vec2& normal(index_t k) const { return normal_[k]; }
  double length(index_t k) const { return length_[k]; }
  bool concave_vertex(index_t v) const { return concave_[v]; }
  double max_depth() const { return depth_; }
  // Largest distance from a segment at which a point can still be caught by it.
  double reach() const { return reach_; }

  vec2 displacement(double t) const { return motion_.displacement(t); }
  vec2 velocity(double t) const { return motion_.velocity(t); }
  // Vertices in world coordinates at time t (for output; allocates).
  std::vector<vec2> vertices(double t) const {
    const vec2 u = displacement(t);
    std::vector<vec2> out(vertex_);
    for (vec2& p : out) p += u;
    return out;
  }

  // Signed distance from segment k's line (positive on the body side) and the projection
  // parameter lambda along the segment, for a point y in the tool frame.
  struct projection {
    double distance;
    double lambda;
  };
  projection project(index_t k, const vec2& y) const {
    const vec2 r = y - vertex_[k];
    return {r.dot(normal_[k]), r.dot(tangent_[k]) / length_[k]};
  }

  // True if segment k catches y (tool frame); then `gap` is the penetration g > 0.
  bool catches(index_t k, const vec2& y, double& gap) const {
    const projection p = project(k, y);
    const double g = -p.distance;
    if (!(g > 0.0 && g <= depth_)) return false;
    if (p.lambda < 0.0 && !(concave_[k] && in_wedge(project(k - 1, y), false))) return false;
    if (p.lambda > 1.0 && !(concave_[k + 1] && in_wedge(project(k + 1, y), true))) return false;
    gap = g;
    return true;
  }

 private:
  // Is a point, seen from the neighbouring segment (projection q), in the wedge behind a concave
  // vertex: behind that segment too, within the depth, and past its end at the shared vertex?
  bool in_wedge(const projection& q, bool vertex_is_start) const {
    const double g = -q.distance;
    return g > 0.0 && g <= depth_ && (vertex_is_start ? q.lambda < 0.0 : q.lambda > 1.0);
  }

  std::string name_;
  std::vector<vec2> vertex_;
  side side_;
  tool_motion motion_;
  std::vector<double> length_;
  std::vector<vec2> tangent_;
  std::vector<vec2> normal_;
  std::vector<bool> concave_;
  double depth_ = 0.0;
  double reach_ = 0.0;
};

}  // namespace rkpm::contact
