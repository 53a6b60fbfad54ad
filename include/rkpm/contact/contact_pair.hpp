#pragma once
// contact_pair: one slave particle in contact with one tool during the last step, as
// particle_to_segment reports it (docs/method.md section 6); body_pair: two deformable bodies
// that may touch (body_contact.hpp, section 6.9).

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
struct body_pair {
  index_t slave = 0;
  index_t master = 1;
};

}  // namespace rkpm::contact
