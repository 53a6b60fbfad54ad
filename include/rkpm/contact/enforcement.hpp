#pragma once
// Enforcement policies: how large the normal contact force (P4) and the mass in the sticking
// force (P6) are for a slave particle J with penetration g (docs/method.md (56)-(57), (61)-(61a),
// section 6.6). Each gets the slave's own mass m_s = m_J and its effective mass among the slaves
// in contact in the same step, m_sh (61a, shared_effective_mass.hpp); for an isolated slave m_sh
// is m_eff = 1 / sum_I (N_I(X_J)^2 / m_I) (61).
//   paper          f_n = m_s g / dt^2 and m_s in (P6) (the paper's form). With RK redistribution
//                  (P7) it moves an isolated x_J back by only g m_s sum_I N_I(X_J)^2 / m_I, part
//                  of the gap; in a row of slaves m_J is close to m_sh away from the row's ends.
//   effective_mass f_n = m_sh g / dt^2 and m_sh in (P6): an isolated particle lands on the segment
//                  and stops relative to the tool in one step, a uniform row too. `sweeps` > 1
//                  repeats the correction on the updated configuration (projected Jacobi, later
//                  sweeps scaled by `relaxation`) for the patterns of gaps and slips that one
//                  sweep leaves (m_sh never overshoots, so no relaxation is needed: default 1).
//                  m_sh counts every neighbour in contact as pushing along the same direction,
//                  so where slaves press on faces of different normals (a convex tool corner) it
//                  undercorrects: the default 5 sweeps keep a slave at a V punch's apex within 1%
//                  of the spacing (tests/numeric/contact_moving_tool.cpp; 1.4% with 3 sweeps).
//                  With (61)'s m_eff instead, a row of slaves was pushed off the tool and its slip
//                  reversed (about twice the correction it needed), and a surface that should
//                  stick crept by about one spacing (tests/numeric/contact_stick.cpp).
//   penalty        f_n = k g with a stiffness k in N/m (per unit of whatever the masses carry:
//                  in axisymmetric runs, per radian times 2 pi, like the masses), m_sh in (P6).

#include <cmath>
#include <string_view>

#include <rkpm/core/error.hpp>

namespace rkpm::contact::enforcement {

struct paper {
  static constexpr std::string_view name = "paper";
  static constexpr int sweeps = 1;
  static constexpr double relaxation = 1.0;
  void validate() const {}
  double normal_force(double gap, double dt, double m_s, double /*m_sh*/) const { return m_s * gap / (dt * dt); }
  double stick_mass(double m_s, double /*m_sh*/) const { return m_s; }
};

struct effective_mass {
  static constexpr std::string_view name = "effective_mass";
  int sweeps = 5;
  double relaxation = 1.0;  // applied to sweeps after the first

  void validate() const {
    if (sweeps < 1) fail("effective_mass enforcement: sweeps = {} must be >= 1", sweeps);
    if (!(relaxation > 0.0 && relaxation <= 1.0))
      fail("effective_mass enforcement: relaxation {} must lie in (0, 1]", relaxation);
  }
  double normal_force(double gap, double dt, double /*m_s*/, double m_sh) const { return m_sh * gap / (dt * dt); }
  double stick_mass(double /*m_s*/, double m_sh) const { return m_sh; }
};

struct penalty {
  static constexpr std::string_view name = "penalty";
  static constexpr int sweeps = 1;
  static constexpr double relaxation = 1.0;
  double stiffness = 0.0;  // k, N/m

  void validate() const {
    if (!(stiffness > 0.0) || !std::isfinite(stiffness))
      fail("penalty enforcement: stiffness {} must be positive and finite; give k in N/m, e.g. "
           "penalty{{.stiffness = 1e9}}",
           stiffness);
  }
  double normal_force(double gap, double /*dt*/, double /*m_s*/, double /*m_sh*/) const { return stiffness * gap; }
  double stick_mass(double /*m_s*/, double m_sh) const { return m_sh; }
};

}  // namespace rkpm::contact::enforcement
