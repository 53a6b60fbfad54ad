#pragma once
// Enforcement policies: how large the normal contact force (P4) and the mass in the sticking
// force (P6) are for a slave particle J with penetration g (docs/method.md (56)-(57), (61), section 6.6).
//   paper          f_n = m_s g / dt^2, m_s = m_J (the paper's form). With RK redistribution (P7)
//                  it moves x_J back by only g m_s sum_I N_I(X_J)^2 / m_I, part of the gap.
//   effective_mass f_n = m_eff g / dt^2 with m_eff = 1 / sum_I (N_I(X_J)^2 / m_I): an isolated
//                  particle lands on the segment in one step. `sweeps` > 1 repeats the
//                  correction on the updated configuration (projected Jacobi, later sweeps scaled
//                  by `relaxation`), so neighbouring slave particles that share coefficients
//                  close their gaps too. The default is 3: with one sweep a flat row of slaves
//                  is pushed out by about twice its gap (each slave's correction also moves its
//                  neighbours), so a block resting on a wall chatters and creeps under a
//                  tangential load below mu N (tests/numeric/contact_friction.cpp).
//   penalty        f_n = k g with a stiffness k in N/m (per unit of whatever the masses carry:
//                  in axisymmetric runs, per radian times 2 pi, like the masses).
// The sticking force uses m_s for the paper's form and m_eff otherwise, so that a sticking
// particle really stops relative to the tool.

#include <cmath>
#include <string_view>

#include <rkpm/core/error.hpp>

namespace rkpm::contact::enforcement {

struct paper {
  static constexpr std::string_view name = "paper";
  static constexpr int sweeps = 1;
  static constexpr double relaxation = 1.0;
  void validate() const {}
  double normal_force(double gap, double dt, double m_s, double /*m_eff*/) const { return m_s * gap / (dt * dt); }
  double stick_mass(double m_s, double /*m_eff*/) const { return m_s; }
};

struct effective_mass {
  static constexpr std::string_view name = "effective_mass";
  int sweeps = 3;
  double relaxation = 0.5;  // applied to sweeps after the first

  void validate() const {
    if (sweeps < 1) fail("effective_mass enforcement: sweeps = {} must be >= 1", sweeps);
    if (!(relaxation > 0.0 && relaxation <= 1.0))
      fail("effective_mass enforcement: relaxation {} must lie in (0, 1]", relaxation);
  }
  double normal_force(double gap, double dt, double /*m_s*/, double m_eff) const { return m_eff * gap / (dt * dt); }
  double stick_mass(double /*m_s*/, double m_eff) const { return m_eff; }
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
  double normal_force(double gap, double /*dt*/, double /*m_s*/, double /*m_eff*/) const { return stiffness * gap; }
  double stick_mass(double /*m_s*/, double m_eff) const { return m_eff; }
};

}  // namespace rkpm::contact::enforcement
