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
  vec2 tangential_force = vec2::Zero();
  vec2 force() const { return normal_force * normal + tangential_force; }  // f_J on the particle
};

// Slave body and master body, as numbered by partition_bodies (the order of their first cells).
struct body_pair {
  index_t slave = 0;
  index_t master = 1;
};

}  // namespace rkpm::contact
