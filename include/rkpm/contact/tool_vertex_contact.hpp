#pragma once
// Rigid tools' vertices as slaves against the bodies' surfaces (the second pass of tool contact,
// docs/method.md section 6.9). Particle-to-segment contact checks the body's particles against
// the tool's segments, so a sharp tool corner can slip between two surface particles into the
// body. This pass checks each tool vertex P (at its position at t_n+1) against the boundary chains
// of every body (discretization/model_bodies.hpp): a vertex behind segment a-b of a body
// (surface_search.hpp, the nearest of all the segments),
//   lambda = (P - x_a) . t / |t|^2 in [0, 1],   g = -(P - x_a) . n in (0, depth],
// pushes the body's contact point x_c = (1 - lambda) x_a + lambda x_b out of the tool, along -n,
// by the forces of (56)-(58) (contact_kernel.hpp, in the sweeps of contact_sweeps.hpp) with the
// contact point as the slave (its velocity against the tool's, its mass the master side's: m_c
// of (78) for the paper's form, the shared effective mass of the rows
// c_I = (1 - lambda) N_I(X_a) + lambda N_I(X_b) otherwise). The force goes to the body's
// coefficients through c_I and its reaction onto the tool. The tool is rigid: only the body moves.

#include <algorithm>
#include <array>
#include <cmath>
#include <ranges>
#include <span>
#include <vector>

#include <rkpm/concepts/contact.hpp>
#include <rkpm/contact/contact_sweeps.hpp>
#include <rkpm/contact/rigid_tool.hpp>
#include <rkpm/contact/surface_scratch.hpp>
#include <rkpm/contact/surface_search.hpp>
#include <rkpm/core/error.hpp>
#include <rkpm/discretization/model_bodies.hpp>

namespace rkpm::contact {

class tool_vertex_contact {
 public:
  bool enabled() const { return enabled_; }

  // The bodies' surfaces, from the cells; their vertices must be particles.
  void setup(const contact_body& body, std::size_t tool_vertices) {
    enabled_ = true;
    if (!body.bodies || !body.at_particles)
      fail("tool vertices as slaves need the model's bodies and the shape functions at the particles; the "
           "solver passes them in contact_body");
    const std::span<const vec2> X = body.reference_position;
    const auto n = static_cast<index_t>(X.size());
    const auto& chains = body.bodies->surface("tool vertices as slaves");
    segment_.clear();
    std::vector<char> surface(n, 0);
    double shortest = INFINITY;
    for (const auto& c : chains)
      for (index_t s = 0; s < c.segments(); ++s) {
        const auto seg = c.segment(s);
        segment_.push_back(seg);
        surface[seg[0]] = surface[seg[1]] = 1;
        shortest = std::min(shortest, (X[seg[1]] - X[seg[0]]).norm());
      }
    depth_ = 0.5 * shortest;
    surface_.clear();
    for (index_t I = 0; I < n; ++I)
      if (surface[I]) surface_.push_back(I);
    contact_.assign(tool_vertices, {});
    scratch_.resize(n);
  }

  // After the particles' pass: u_now and v_tool are each tool's displacement at t_n+1 and its
  // mean velocity over the step; reactions[k] collects the force on tool k.
  template <class Enforcement, class Friction>
  void enforce(const contact_body& body, const std::vector<rigid_tool>& tools, std::span<const vec2> u_now,
               std::span<const vec2> v_tool, double dt, const Enforcement& enforcement, const Friction& friction,
               std::vector<vec2>& d, std::vector<vec2>& v, contact_result& result, std::span<vec2> reactions) {
    if (!enabled_) return;
    pass p{*this, *body.at_particles, body.reference_position, body.mass, v_tool, dt, d, v};
    p.refresh();
    count_ = 0;
    for (std::size_t k = 0; k < tools.size(); ++k)
      for (const vec2& P0 : tools[k].reference_vertices()) detect(static_cast<index_t>(k), P0 + u_now[k], result);
    contact_sweeps(p, 0, count_, dt, enforcement, friction);
    for (index_t q = 0; q < count_; ++q)
      reactions[contact_[q].tool] -= contact_[q].normal_force * -contact_[q].normal + contact_[q].tangential_force;
  }

 private:
  struct vertex_contact {
    index_t tool = 0;
    vec2 vertex = vec2::Zero();  // the tool vertex at t_n+1
    index_t a = 0, b = 0;
    double lambda = 0.0, gap = 0.0;
    vec2 normal = vec2::Zero();  // the body's outward normal
    double shared_mass = 0.0, normal_force = 0.0;
    vec2 tangential_force = vec2::Zero();
  };

  // Every surface segment is a candidate: the tools have few vertices.
  void detect(index_t tool, const vec2& P, contact_result& result) {
    const auto all = std::views::iota(index_t{0}, static_cast<index_t>(segment_.size()));
    const surface_hit hit = penetrated_segment(segment_, all, scratch_.x, P, depth_);
    if (hit.segment < 0 || count_ >= static_cast<index_t>(contact_.size())) return;
    const auto [a, b] = segment_[hit.segment];
    contact_[count_++] = vertex_contact{tool, P, a, b, hit.lambda, hit.gap, hit.normal, 0.0, 0.0, vec2::Zero()};
    result.max_penetration = std::max(result.max_penetration, hit.gap);
    ++result.active;
  }

  // The vertices' contacts for contact_sweeps (contact_sweeps.hpp): the slave side is the
  // body's contact point, pushed along -n, out of the tool (as a tool's normal, section 6.2).
  struct pass {
    tool_vertex_contact& self;
    const shape_table<2>& rows;
    std::span<const vec2> X;
    std::span<const double> m;
    std::span<const vec2> v_tool;
    double dt;
    std::vector<vec2>& d;
    std::vector<vec2>& v;

    void refresh() {
      for (index_t I : self.surface_) self.scratch_.physical_state(rows, X, I, d, v);
    }
    void shared_masses(index_t first, index_t end) {
      self.scratch_.shared_masses(
          first, end, m,
          [&](index_t q, auto&& visit) {
            const vertex_contact& p = self.contact_[q];
            self.scratch_.visit_point(rows, p.a, p.b, p.lambda, visit);
          },
          [&](index_t q, double mass) { self.contact_[q].shared_mass = mass; });
    }
    vertex_contact& contact(index_t q) { return self.contact_[q]; }
    contact_state state(index_t q, int sweep) const {
      const vertex_contact& p = self.contact_[q];
      const auto& x = self.scratch_.x;
      const auto& w = self.scratch_.w;
      const vec2 xc = (1.0 - p.lambda) * x[p.a] + p.lambda * x[p.b];
      const vec2 vc = (1.0 - p.lambda) * w[p.a] + p.lambda * w[p.b];
      const vec2 push = -p.normal;
      const double g = sweep == 0 ? p.gap : (p.vertex - xc).dot(push);
      const double m_c = (1.0 - p.lambda) * m[p.a] + p.lambda * m[p.b];
      return {g, vec2(vc - v_tool[p.tool]), push, m_c, p.shared_mass};
    }
    void spread(index_t q, const vec2& df) {
      const vertex_contact& p = self.contact_[q];
      self.scratch_.spread(rows, p.a, 1.0 - p.lambda, df);
      self.scratch_.spread(rows, p.b, p.lambda, df);
    }
    void apply() { self.scratch_.apply(m, dt, d, v); }
  };

  bool enabled_ = false;
  std::vector<std::array<index_t, 2>> segment_;  // every body's surface segments (particles)
  double depth_ = 0.0;
  std::vector<index_t> surface_;

  // Scratch, sized in setup().
  std::vector<vertex_contact> contact_;  // capacity: the tools' vertices
  index_t count_ = 0;
  surface_scratch scratch_;
};

}  // namespace rkpm::contact
