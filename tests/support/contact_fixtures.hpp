#pragma once
// Contact test fixtures shared by the unit tests of the contact policies.

#include <vector>

#include <rkpm/concepts/contact.hpp>

namespace rkpm::test {

// Particles that carry their own mass: N_I(X_J) = delta_IJ, every particle a slave.
struct identity_body {
  std::vector<vec2> X;
  std::vector<double> m;
  contact_body view() const { return {X, m}; }
  contact_slaves slaves() const {
    contact_slaves s;
    for (index_t J = 0; J < static_cast<index_t>(X.size()); ++J) {
      s.particle.push_back(J);
      s.table.neighbor.push_back(J);
      s.table.N.push_back(1.0);
      s.table.grad.push_back(vec2::Zero());
      s.table.offset.push_back(J + 1);
    }
    return s;
  }
};

}  // namespace rkpm::test
