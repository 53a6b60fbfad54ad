#pragma once
// contact_sweeps: the corrections of one contact pass (docs/method.md section 6.5-6.6, 6.9), the
// same skeleton for the rigid tools' slaves (particle_to_segment.hpp), the deformable body pairs
// (body_contact.hpp) and the tools' vertices (tool_vertex_contact.hpp). After the pass has
// detected its contacts [first, end):
//   the shared effective masses (61a) of those contacts, on their rows;
//   `sweeps` times (the enforcement's; Jacobi: every contact on the same configuration):
//     each contact's force increment (contact_kernel.hpp) spread to the coefficients (P7),
//     then all of them applied as (60); before each later sweep, the state the detection read
//     is measured again on the updated configuration.
// The pass fills in its detection and rows through
//   shared_masses(first, end)  m_sh (61a) of each contact;
//   refresh()                  the physical state of what state() reads, after a sweep;
//   state(q, sweep)            contact_state of contact q (sweep 0: the detected gap);
//   contact(q)                 contact q, with its normal_force and tangential_force so far;
//   spread(q, df)              df to the slave side's coefficients, its reaction to the master's;
//   apply()                    (60) for what was spread.

#include <rkpm/concepts/contact.hpp>
#include <rkpm/contact/contact_kernel.hpp>

namespace rkpm::contact {

template <class Pass, ContactEnforcement Enforcement, FrictionLaw Friction>
void contact_sweeps(Pass&& pass, index_t first, index_t end, double dt, const Enforcement& enforcement,
                    const Friction& friction) {
  if (end <= first) return;
  pass.shared_masses(first, end);
  for (int sweep = 0; sweep < enforcement.sweeps; ++sweep) {
    if (sweep > 0) pass.refresh();
    for (index_t q = first; q < end; ++q) {
      auto& c = pass.contact(q);
      const contact_state s = pass.state(q, sweep);
      pass.spread(q, contact_increment(s, dt, sweep, enforcement, friction, c.normal_force, c.tangential_force));
    }
    pass.apply();
  }
}

}  // namespace rkpm::contact
