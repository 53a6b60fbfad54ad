#pragma once
// contact_stage<Contact>: the contact part of the explicit step (docs/method.md section 6): the
// policy, its slave particles and what the run reports of it. After the prediction it corrects
// d(n+1) and v(n+1/2) on the predicted configuration, books the work of those velocity jumps
// (docs/method.md section 7, energy.hpp's impulse_work_at) and each tool's impulse, the sum of
// its reaction times the step (what a tool's mean force over an interval is computed from).
// The impulse is summed with compensation (Kahan): a mean force is the difference of two
// readings, and a plain sum over n steps can lose n x 1e-16 of the total.

#include <algorithm>
#include <ranges>
#include <typeinfo>
#include <span>
#include <utility>
#include <vector>

#include <rkpm/concepts/contact.hpp>
#include <rkpm/core/block_sums.hpp>
#include <rkpm/io/checkpoint.hpp>
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
  std::vector<vec2> impulse;        // per tool: sum over the steps of reactions() dt since t = 0 (N s)
  std::vector<vec2> impulse_carry;  // per tool: what the rounding of impulse left out

  // Rigid tools, or pairs of deformable bodies (contact/body_contact.hpp), to enforce contact with.
  bool active() const { return has_contact(policy); }

  // Picks the slaves (the given particles, or the boundary nodes: select_slaves) and sets the
  // policy up on the body.
  void setup(const discrete_model& m, const contact_body& body, std::vector<index_t> given) {
    const contact_slaves s = select_slaves(m, std::move(given), active());
    slaves = s.particle;
    policy.setup(body, s);
    impulse.assign(std::ranges::size(policy.tools()), vec2::Zero());
    impulse_carry = impulse;
  }

  // The same slaves on a model rebuilt in the current configuration (explicit_solver::rereference):
  // their rows taken again, the impulses and the policy's state kept.
  void rebind(const discrete_model& m, const contact_body& body) {
    if (!active()) return;
    if constexpr (RebindsSlaves<Ct>) {
      policy.rebind(body, select_slaves(m, slaves, true));
    } else {
      fail("re-referencing: the contact policy {} cannot take a rebuilt model (it has no rebind()); run without "
           "\"rereference\" or give it one",
           typeid(Ct).name());
    }
  }

  // Checkpoint sections (io/checkpoint.hpp).
  void save(io::checkpoint_writer& w) const { sections(w, *this); }
  void load(io::checkpoint_reader& r) { sections(r, *this); }

  // Corrects d and v at time t, the end of a step dt, and returns the work of the corrections:
  // v_before holds the velocities before them, v_half_prev v(n-1/2); sums over the particles.
  double enforce(const contact_body& body, double t, double dt, std::vector<vec2>& d, std::vector<vec2>& v,
                 const std::vector<vec2>& v_before, const std::vector<vec2>& v_half_prev, const block_sums<2>& sums) {
    last = policy.enforce(body, t, dt, d, v);
    max_penetration = std::max(max_penetration, last.max_penetration);
    const std::span<const vec2> reaction = policy.reactions();
    for (std::size_t k = 0; k < impulse.size(); ++k) {
      const vec2 add = reaction[k] * dt - impulse_carry[k];
      const vec2 sum = impulse[k] + add;
      impulse_carry[k] = (sum - impulse[k]) - add;
      impulse[k] = sum;
    }
    return sums([&](index_t I, block_sums<2>::sums& s) {
      s[0] += impulse_work_at(body.mass[I], v[I], v_before[I], v_half_prev[I]);
    })[0];
  }
 private:
  template <class Archive, class Self>
  static void sections(Archive& a, Self& s) {
    a.value("solver.last_contact", s.last);
    a.value("solver.max_penetration", s.max_penetration);
    a.array("solver.tool_impulse", s.impulse);
    a.array("solver.tool_impulse_carry", s.impulse_carry);
    a.part(s.policy);
  }
};

}  // namespace rkpm
