#pragma once
// Contact test fixtures shared by the unit tests of the contact policies.

#include <vector>

#include <rkpm/contact/body_view.hpp>

namespace rkpm::test {

// Particles that carry their own mass: N_I(X_J) = delta_IJ, every particle a slave.
struct identity_body {
  std::vector<vec2> X;
  std::vector<double> m;
  contact::body_view view() const {
    contact::body_view b{&X, &m, {}, {}};
    for (index_t J = 0; J < static_cast<index_t>(X.size()); ++J) {
      b.slave.push_back(J);
      b.slave_table.neighbor.push_back(J);
      b.slave_table.N.push_back(1.0);
      b.slave_table.grad.push_back(vec2::Zero());
      b.slave_table.offset.push_back(J + 1);
    }
    return b;
  }
};

}  // namespace rkpm::test
