#pragma once
// body_pair_surfaces: what the contact between bodies (body_contact.hpp; docs/method.md sections
// 6.9 and 6.11) reads of each pair, set up once on the model: the master's segments, the slave
// particles, the depth of (75) and the particles whose physical state the detection reads.
//   - Declared pairs (a list of body_pair): a pair's slaves are the problem's slave particles that
//     belong to its slave body. A pair of a body with itself is self-contact.
//   - All pairs (all_body_pairs, (109)): every (slave, master) of the model's bodies, itself
//     included, master by master (every body's slaves against body 0's surface, then body 1's,
//     ...); the slaves every vertex of the slave body's surface chains, in increasing order (on
//     a rank's part, of the whole model's indices), the order of the default slaves (the mesh's
//     boundary nodes), so that two bodies give what the pairs (1, 0) and (0, 1) with the default
//     slaves give, bit for bit, and a part what the whole model gives. With the faces of cracks
//     (crack_face_points.hpp, (114)), a master's faces follow its surface segments and a slave
//     body's face points its surface vertices, numbered after the particles.

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <vector>

#include <rkpm/core/error.hpp>
#include <rkpm/contact/contact_pair.hpp>
#include <rkpm/discretization/crack_face_rows.hpp>
#include <rkpm/discretization/model_bodies.hpp>

namespace rkpm::contact {

struct body_pair_surfaces {
  std::vector<std::vector<std::array<index_t, 2>>> segment;  // per pair: master segments (particles)
  std::vector<std::vector<index_t>> slave;                   // per pair: slave particles
  std::vector<double> depth;                                 // per pair: half the shortest master segment
  std::vector<index_t> surface;  // the particles of every segment and slave, in increasing order
};

// (109): every (slave, master) of `bodies` bodies, master by master. For two bodies (1, 0) comes
// before (0, 1), the order the project's cases and tests declare (the later body the slave
// first): Gauss-Seidel passes are not symmetric, and a projectile on a plate (plate_impact)
// inverts a cell of the plate at 4.5 us with the other order.
inline std::vector<body_pair> every_body_pair(index_t bodies) {
  std::vector<body_pair> pairs;
  pairs.reserve(static_cast<std::size_t>(bodies * bodies));
  for (index_t m = 0; m < bodies; ++m)
    for (index_t s = 0; s < bodies; ++s) pairs.push_back({s, m});
  return pairs;
}

// The pairs' surfaces on the model's bodies, reference positions X. `slaves`: the problem's slave
// particles (declared pairs), or every surface vertex a slave when `surface_slaves`, ordered by
// `particle_id` (a rank's part: each particle's index in the whole model; empty: their own).
// `faces`: the crack faces, face point p numbered n + p (none if null).
inline body_pair_surfaces pair_surfaces(std::span<const body_pair> pairs, const model_bodies& bodies,
                                        std::span<const vec2> X, std::span<const index_t> slaves,
                                        bool surface_slaves, const crack_face_rows* faces = nullptr,
                                        std::span<const stored_index> particle_id = {}) {
  const auto n = static_cast<index_t>(X.size());
  const index_t face_points = faces ? faces->points() : 0;
  for (std::size_t k = 0; k < pairs.size(); ++k)
    for (index_t b : {pairs[k].slave, pairs[k].master})
      if (b < 0 || b >= bodies.count())
        fail("contact pair {}: body {} does not exist; the cells form {} bodies, numbered 0 to {} in the order "
             "of their first cells",
             k, b, bodies.count(), bodies.count() - 1);
  const auto& chains = bodies.surface("contact between bodies");
  std::vector<index_t> vertices;  // on a surface chain, in the whole model's order
  if (surface_slaves) {
    std::vector<char> vertex(n, 0);
    for (const auto& c : chains)
      for (index_t I : c.node)
        if (!vertex[I]) {
          vertex[I] = 1;
          vertices.push_back(I);
        }
    std::ranges::sort(vertices, {}, [&](index_t I) { return particle_id.empty() ? I : index_t{particle_id[I]}; });
  }

  body_pair_surfaces out;
  out.segment.assign(pairs.size(), {});
  out.slave.assign(pairs.size(), {});
  out.depth.assign(pairs.size(), 0.0);
  std::vector<char> read(n + face_points, 0);
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    double shortest = INFINITY;
    for (const auto& c : chains)
      if (c.body == pairs[k].master)
        for (index_t s = 0; s < c.segments(); ++s) {
          const auto seg = c.segment(s);
          out.segment[k].push_back(seg);
          shortest = std::min(shortest, (X[seg[1]] - X[seg[0]]).norm());
          read[seg[0]] = read[seg[1]] = 1;
        }
    for (index_t f = 0; faces && f < faces->faces(); ++f)
      if (faces->body[f] == pairs[k].master) {
        const auto [a, b] = faces->segment[f];
        out.segment[k].push_back({n + a, n + b});
        shortest = std::min(shortest, (faces->position[b] - faces->position[a]).norm());
        read[n + a] = read[n + b] = 1;
      }
    out.depth[k] = 0.5 * shortest;
    auto& slave = out.slave[k];
    if (surface_slaves) {
      for (index_t I : vertices)
        if (bodies.of_particle(I) == pairs[k].slave) slave.push_back(I);
    } else {
      for (index_t J : slaves)
        if (bodies.of_particle(J) == pairs[k].slave) slave.push_back(J);
    }
    for (index_t f = 0; faces && f < faces->faces(); ++f)
      if (faces->body[f] == pairs[k].slave)
        for (const index_t p : faces->segment[f]) slave.push_back(n + p);
    for (index_t J : slave) read[J] = 1;
    if (slave.empty())
      fail("contact pair {}: slave body {} has no slave particles; give slaves on its boundary", k, pairs[k].slave);
  }
  for (index_t I = 0; I < n + face_points; ++I)
    if (read[I]) out.surface.push_back(I);
  return out;
}

}  // namespace rkpm::contact
