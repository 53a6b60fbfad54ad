#pragma once
// contact_stage<Contact>: the contact part of the explicit step (docs/method.md section 6): the
// policy, its slave particles and what the run reports of it. After the prediction it corrects
// d(n+1) and v(n+1/2) on the predicted configuration and books the work of those velocity
// jumps (docs/method.md section 7, energy.hpp's impulse_work_at).

#include <algorithm>
#include <utility>
#include <vector>

#include <rkpm/concepts/contact.hpp>
#include <rkpm/core/block_sums.hpp>
#include <rkpm/solver/body_setup.hpp>
#include <rkpm/solver/discrete_model.hpp>
#include <rkpm/solver/energy.hpp>

namespace rkpm {

template <Contact Ct>
struct contact_stage {
  Ct policy;
  std::vector<index_t> slaves;  // the particles checked against the tools
  contact_result last;          // of the last step
  double max_penetration = 0.0;  // over the run

  // Rigid tools, or pairs of deformable bodies (contact/body_contact.hpp), to enforce contact with.
  bool active() const { return has_contact(policy); }

  // Picks the slaves (the given particles, or the boundary nodes: select_slaves) and sets the
  // policy up on the body.
  void setup(const discrete_model& m, const contact_body& body, std::vector<index_t> given) {
    const contact_slaves s = select_slaves(m, std::move(given), active());
    slaves = s.particle;
    policy.setup(body, s);
  }

  // Corrects d and v at time t, the end of a step dt, and returns the work of the corrections:
  // v_before holds the velocities before them, v_half_prev v(n-1/2); sums over the particles.
  double enforce(const contact_body& body, double t, double dt, std::vector<vec2>& d, std::vector<vec2>& v,
                 const std::vector<vec2>& v_before, const std::vector<vec2>& v_half_prev, const block_sums<2>& sums) {
    last = policy.enforce(body, t, dt, d, v);
    max_penetration = std::max(max_penetration, last.max_penetration);
    return sums([&](index_t I, block_sums<2>::sums& s) {
      s[0] += impulse_work_at(body.mass[I], v[I], v_before[I], v_half_prev[I]);
    })[0];
  }
};

}  // namespace rkpm
