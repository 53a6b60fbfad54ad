#pragma once
// contact_pair: one slave particle in contact with one tool during the last step, as
// particle_to_segment reports it (docs/method.md section 6); body_pair: two deformable bodies
// that may touch, or a body and itself (body_contact.hpp, sections 6.9 and 6.11); all_body_pairs:
// every body against every body.

#include <rkpm/core/types.hpp>

namespace rkpm::contact {

// One slave particle in contact with one tool during the last step.
struct contact_pair {
  index_t slave = 0;      // row j of the body's slave list (particle body.slave[j])
  index_t tool = 0;       // index into tools()
  index_t segment = 0;    // master segment of that tool
  double gap = 0.0;       // penetration before correction
  vec2 normal = vec2::Zero();
  double normal_force = 0.0;        // f_n >= 0 along normal
  // The 8 bytes before tangential_force's 16-byte alignment, named so that they hold zero:
  // checkpoints write pairs as bytes, the same bytes on any number of processes.
  double unused = 0.0;
  vec2 tangential_force = vec2::Zero();
  vec2 force() const { return normal_force * normal + tangential_force; }  // f_J on the particle
};

static_assert(sizeof(contact_pair) == 3 * sizeof(index_t) + 3 * sizeof(double) + 2 * sizeof(vec2),
              "contact_pair has padding bytes, which checkpoints would write undefined: name them");

// Slave body and master body, as numbered by partition_bodies (the order of their first cells).
// slave == master is self-contact: a body's surface against itself (section 6.11).
struct body_pair {
  index_t slave = 0;
  index_t master = 1;
};

// In place of a list of pairs: every body against every body, itself included, with every
// particle of the bodies' surfaces a slave (section 6.11). The pairs are made when the solver
// sets the contact up on the model, whose cells say how many bodies there are (a case need not
// count them, and a model rebuilt with other pieces gets its own pairs).
struct all_body_pairs_t {
  explicit all_body_pairs_t() = default;
};
inline constexpr all_body_pairs_t all_body_pairs{};

}  // namespace rkpm::contact
