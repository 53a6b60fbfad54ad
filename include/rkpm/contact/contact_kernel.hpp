#pragma once
// contact_increment: the force one contact adds in one sweep (docs/method.md (56)-(58), sections
// 6.5-6.6), the same for every contact pass (rigid tools' slaves, deformable body pairs, tools'
// vertices; contact_sweeps.hpp). Given the contact's state on the current configuration,
//   f_n  = max(0, f_n + omega f(g))               (P4), f(g) from the enforcement policy;
//   f_st = f_t - omega m_stick v_T / dt           (P6), v_T = v - (v . n) n;
//   f_t  = the friction law's limit of f_st       (P5), e.g. capped at mu f_n;
// it updates f_n, f_t of the contact and returns the change of the force on the slave side,
// (f_n - f_n,old) n + (f_t - f_t,old). omega is 1 in the first sweep and the enforcement's
// relaxation after.

#include <algorithm>

#include <rkpm/concepts/contact.hpp>
#include <rkpm/core/types.hpp>

namespace rkpm::contact {

// One contact on the current configuration.
struct contact_state {
  double gap = 0.0;                    // g > 0: penetration along normal
  vec2 relative_velocity = vec2::Zero();  // slave side minus master side
  vec2 normal = vec2::Zero();          // unit, the direction the slave side is pushed
  double own_mass = 0.0;               // m_s of the enforcement policy (enforcement.hpp)
  double shared_mass = 0.0;            // m_sh (61a)
};

template <ContactEnforcement Enforcement, FrictionLaw Friction>
vec2 contact_increment(const contact_state& c, double dt, int sweep, const Enforcement& enforcement,
                       const Friction& friction, double& normal_force, vec2& tangential_force) {
  const double omega = sweep == 0 ? 1.0 : enforcement.relaxation;
  const vec2& rel = c.relative_velocity;
  const vec2 v_t = rel - rel.dot(c.normal) * c.normal;
  const double fn =
      std::max(0.0, normal_force + omega * enforcement.normal_force(c.gap, dt, c.own_mass, c.shared_mass));
  const vec2 trial = tangential_force - omega * enforcement.stick_mass(c.own_mass, c.shared_mass) * v_t / dt;
  const vec2 ft = friction.limit(trial, fn);
  const vec2 df = (fn - normal_force) * c.normal + (ft - tangential_force);
  normal_force = fn;
  tangential_force = ft;
  return df;
}

}  // namespace rkpm::contact
