#pragma once
// Contact between deformable bodies: the paper's slave and master bodies (docs/method.md section
// 6.9), and a body against itself (self-contact, section 6.11). A body_pair names a slave body and
// a master body of the problem's mesh (the connected parts of its cells, found by the model:
// discretization/model_bodies.hpp), the same body for self-contact; all_body_pairs asks for every
// pair (body_pair_surfaces.hpp). The master surface is
// the master body's boundary chains (model_bodies::surface; not the axis of a section), its
// vertices the master particles at their physical positions x = X + sum_I N_I(X) d_I on the
// predicted configuration. Each step, for every slave particle J of the slave body:
//   (i)   the segment a-b of the master surface it penetrates: projection lambda in [0, 1],
//         gap g = -(x_J - x_a) . n in (0, depth] with n the master's outward normal (the
//         nearest such segment; surface_search.hpp), among the candidates of a grid over the
//         master's segments (segment_grid.hpp, rebuilt for each pair on its configuration);
//   (ii)  the normal and friction forces of (P4)-(P6) as for a rigid tool (contact_kernel.hpp),
//         with the velocity of the contact point x_c = (1 - lambda) x_a + lambda x_b as the
//         tool velocity; the effective mass counts both sides, 1 / m_eff = sum_I N_I(X_J)^2 / m_I + sum_I c_I^2 / m_I,
//         c_I = (1 - lambda) N_I(X_a) + lambda N_I(X_b), so that an isolated gap closes in one
//         step, and is shared among contacts that move the same coefficients as (61a) shares it
//         among slaves on a tool (effective_mass enforcement); the paper's form uses the reduced
//         mass of the slave and the contact point;
//   (iii) the force f_J on the slave goes to the slave body's coefficients through N_I(X_J)
//         (P7), and its reaction -f_J at the contact point to the master body's through c_I (the
//         transpose of (P7) on the master side). Both rows sum to one, so the bodies' linear
//         momentum is unchanged to round-off.
// The effective-mass sweeps repeat (ii)-(iii) on the updated configuration (contact_sweeps.hpp,
// the skeleton of every contact pass). The particles of master surfaces must be the mesh nodes
// (grids and meshed bodies are). A self pair is the same pass with both rows in one body: each
// slave skips the segments within its kernel's reach (108), and the rows still sum to one.
// In all-pairs mode the faces of cracks cut through the cells are masters and slaves too
// (crack_face_points.hpp, (114)): virtual points numbered after the particles, each with its row
// seen from its side of the crack, so that the pieces a crack makes touch again through it.

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <utility>
#include <vector>

#include <rkpm/concepts/contact.hpp>
#include <rkpm/core/error.hpp>
#include <rkpm/contact/body_pair_surfaces.hpp>
#include <rkpm/contact/contact_pair.hpp>
#include <rkpm/contact/contact_sweeps.hpp>
#include <rkpm/contact/crack_face_points.hpp>
#include <rkpm/contact/segment_grid.hpp>
#include <rkpm/contact/surface_scratch.hpp>
#include <rkpm/contact/surface_search.hpp>
#include <rkpm/discretization/model_bodies.hpp>

namespace rkpm::contact {

// One slave particle (or crack face point) against one master segment in the last step.
struct body_contact_pair {
  index_t pair = 0;     // index into the body pairs
  index_t slave = 0;    // particle, or face point p of a crack as n + p (n particles; crack_face_points.hpp)
  index_t a = 0, b = 0; // the segment's master particles (or face points, numbered so)
  double lambda = 0.0;  // contact point (1 - lambda) x_a + lambda x_b
  double gap = 0.0;     // penetration before correction
  vec2 normal = vec2::Zero();  // the master's outward normal
  double normal_force = 0.0;
  vec2 tangential_force = vec2::Zero();
  vec2 force() const { return normal_force * normal + tangential_force; }  // on the slave
};

class body_contact {
 public:
  body_contact() = default;
  explicit body_contact(std::vector<body_pair> pairs) : pairs_(std::move(pairs)) {}
  explicit body_contact(all_body_pairs_t) : all_pairs_(true) {}

  bool empty() const { return pairs_.empty() && !all_pairs_; }
  bool all_pairs() const { return all_pairs_; }
  // The declared pairs; in all-pairs mode those setup() made (none before).
  const std::vector<body_pair>& pairs() const { return pairs_; }
  std::span<const body_contact_pair> active_pairs() const {
    return {active_.data(), static_cast<std::size_t>(active_count_)};
  }

  // `slaves`: the problem's slave particles; each declared pair's slaves are those of its slave
  // body. In all-pairs mode the pairs are made here, on the model's bodies (body_pair_surfaces.hpp).
  void setup(const contact_body& body, std::span<const index_t> slaves) {
    if (empty()) return;
    if (!body.bodies || !body.at_particles)
      fail("contact between bodies and self-contact need the model's bodies and the shape functions at the "
           "particles; the solver passes them in contact_body");
    if (all_pairs_) pairs_ = every_body_pair(body.bodies->count());
    faces_.setup(body, all_pairs_);
    surfaces_ = pair_surfaces(pairs_, *body.bodies, body.reference_position, slaves, all_pairs_,
                              faces_.empty() ? nullptr : &faces_.faces(), body.particle_id);
    std::size_t capacity = 0;
    for (const auto& s : surfaces_.slave) capacity += s.size();
    active_.assign(capacity, body_contact_pair{});
    scratch_.resize(faces_.points());
    shared_mass_.assign(capacity, 0.0);
    grid_.assign(pairs_.size(), segment_grid{});
    for (std::size_t k = 0; k < pairs_.size(); ++k)
      grid_[k].reserve(static_cast<index_t>(surfaces_.segment[k].size()));
  }

  template <class Enforcement, class Friction>
  void enforce(const contact_body& body, double dt, const Enforcement& enforcement, const Friction& friction,
               std::vector<vec2>& d, std::vector<vec2>& v, contact_result& result) {
    if (pairs_.empty()) return;
    pass p{*this, faces_.rows(body), faces_.reference(body), body.mass, dt, d, v};
    p.refresh();
    // The pairs one after the other (Gauss-Seidel): a second pass, the same two bodies with
    // the roles swapped, sees the gaps the first one closed instead of closing them again. A
    // pair without contacts moved nothing, so the next one reads the same state (the many
    // pairs of all-pairs mode cost one refresh each only where something touches).
    active_count_ = 0;
    for (std::size_t k = 0; k < pairs_.size(); ++k) {
      const index_t first = active_count_;
      detect(k, p.rows, result);
      contact_sweeps(p, first, active_count_, dt, enforcement, friction);  // (ii)-(iii)
      if (active_count_ > first && k + 1 < pairs_.size()) p.refresh();
    }
  }

 private:
  // (i) for pair k on the current configuration: the segment each slave penetrates, among the
  // candidates of a grid over the master's segments. Its reach, twice the depth, holds every
  // point a segment catches with room for round-off, so the contacts are those of a search over
  // all the segments, in the same order. A self pair leaves out the segments within each
  // slave's kernel reach (108); a crack's face catches a little past its ends (114).
  void detect(std::size_t k, const shape_table<2>& rows, contact_result& result) {
    const std::span<const std::array<index_t, 2>> segments = surfaces_.segment[k];
    const std::span<const vec2> x = scratch_.x;
    const double depth = surfaces_.depth[k];
    const bool self = pairs_[k].slave == pairs_[k].master;
    grid_[k].rebuild(
        static_cast<index_t>(segments.size()),
        [&](index_t s) { return std::pair<vec2, vec2>(x[segments[s][0]], x[segments[s][1]]); }, 2.0 * depth);
    const auto overhang = [&](index_t a, index_t) { return faces_.overhang(a); };
    for (index_t J : surfaces_.slave[k]) {
      const auto candidates = grid_[k].candidates(x[J]);
      const surface_hit hit = penetrated_segment(
          segments, candidates, x, x[J], depth,
          [&](index_t a, index_t b) { return self && faces_.within_reach(rows, J, a, b); }, overhang);
      if (hit.segment < 0) continue;
      const auto [a, b] = segments[hit.segment];
      active_[active_count_++] =
          body_contact_pair{static_cast<index_t>(k), J, a, b, hit.lambda, hit.gap, hit.normal, 0.0, vec2::Zero()};
      result.max_penetration = std::max(result.max_penetration, hit.gap);
      ++result.active;
    }
  }

  // One pair's contacts for contact_sweeps (contact_sweeps.hpp).
  struct pass {
    body_contact& self;
    const shape_table<2>& rows;
    std::span<const vec2> X;
    std::span<const double> m;
    double dt;
    std::vector<vec2>& d;
    std::vector<vec2>& v;

    void refresh() {
      for (index_t I : self.surfaces_.surface) self.scratch_.physical_state(rows, X, I, d, v);
    }
    // The shared effective mass of each contact of the pass (docs/method.md (61a) with the
    // master's row): a unit force on contact p closes the gap of contact q by
    // dt^2 sum_I r_qI r_pI / m_I, so
    //   m_sh,q = 1 / sum_I |r_qI| S_I / m_I,   S_I = sum over the pass's contacts p of |r_pI|,
    // bounds every pattern of corrections (Gershgorin) and is 1 / sum_I r_qI^2 / m_I, the mass
    // that closes an isolated gap in one step, when q shares no coefficient with another
    // contact. The row r_q is +N_I(X_J) on the slave's coefficients and -c_I on the master's.
    void shared_masses(index_t first, index_t end) {
      self.scratch_.shared_masses(
          first, end, m,
          [&](index_t q, auto&& visit) {
            const body_contact_pair& p = self.active_[q];
            for (index_t e = rows.offset[p.slave]; e < rows.offset[p.slave + 1]; ++e)
              visit(rows.neighbor[e], rows.N[e]);
            self.scratch_.visit_point(rows, p.a, p.b, p.lambda, [&](index_t I, double c) { visit(I, -c); });
          },
          [&](index_t q, double mass) { self.shared_mass_[q] = mass; });
    }
    body_contact_pair& contact(index_t q) { return self.active_[q]; }
    contact_state state(index_t q, int sweep) const {
      const body_contact_pair& p = self.active_[q];
      const auto& x = self.scratch_.x;
      const auto& w = self.scratch_.w;
      const vec2 xc = (1.0 - p.lambda) * x[p.a] + p.lambda * x[p.b];
      const vec2 vc = (1.0 - p.lambda) * w[p.a] + p.lambda * w[p.b];
      const double g = sweep == 0 ? p.gap : -(x[p.slave] - xc).dot(p.normal);
      // The paper's form (P4) closes the gap with the slave's mass against a rigid master; a
      // master with mass m_c (its contact point's share) moves too, so the pair's reduced mass.
      const crack_face_points& f = self.faces_;
      const double m_c = (1.0 - p.lambda) * f.mass(m, p.a) + p.lambda * f.mass(m, p.b);
      const double m_s = f.mass(m, p.slave) * m_c / (f.mass(m, p.slave) + m_c);
      return {g, vec2(w[p.slave] - vc), p.normal, m_s, self.shared_mass_[q]};
    }
    void spread(index_t q, const vec2& df) {
      const body_contact_pair& p = self.active_[q];
      self.scratch_.spread(rows, p.slave, 1.0, df);
      self.scratch_.spread(rows, p.a, -(1.0 - p.lambda), df);
      self.scratch_.spread(rows, p.b, -p.lambda, df);
    }
    void apply() { self.scratch_.apply(m, dt, d, v); }
  };

  std::vector<body_pair> pairs_;  // declared, or made by setup() in all-pairs mode
  bool all_pairs_ = false;
  body_pair_surfaces surfaces_;
  crack_face_points faces_;  // in all-pairs mode, the crack faces' points after the particles
  std::vector<segment_grid> grid_;  // per pair: over its master segments

  // Scratch, sized in setup().
  std::vector<body_contact_pair> active_;
  index_t active_count_ = 0;
  surface_scratch scratch_;
  std::vector<double> shared_mass_;  // #capacity of active_
};

}  // namespace rkpm::contact
