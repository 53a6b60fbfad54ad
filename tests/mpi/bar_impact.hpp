#pragma once
// The bar of mpi/bar_problem.hpp thrown at 150 m/s onto a rigid anvil with Coulomb friction
// (axisymmetric, J2, Q2): a problem whose step has all of its parts (the axis constraints, the
// contact, the force loop, the stable step re-estimated), for the tests of the whole step on
// several processes (mpi/distributed_step.cpp, mpi/distributed_restart.cpp).

#include <vector>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/solver/explicit_solver.hpp>

#include "mpi/bar_problem.hpp"

namespace rkpm::test::bar {

using contact_type = contact::particle_to_segment<contact::enforcement::paper, contact::friction::coulomb>;
using solver_type = explicit_solver<geometry_type, material_type, contact_type>;

inline problem<material_type, contact_type> impact() {
  // The anvil 20 um below the bar's face: the first steps fly, then the face is crushed.
  const contact::rigid_tool anvil("anvil", {vec2(-1e-3, -2e-5), vec2(2 * radius, -2e-5)}, contact::side::left,
                                  contact::tool_motion::fixed());
  return {.particles = {},
          .mesh = {},
          .material = copper(),
          .contact = contact_type({anvil}, contact::friction::coulomb{0.2}),
          .initial_velocity = [](const vec2&) { return vec2(0.0, -150.0); }};
}

inline run_options options() {
  run_options o;
  o.end_time = 1.0;  // stepped by hand
  o.time_step_update_interval = 3;
  return o;
}

// The totals every rank has: time, step size, the energies, the tool's impulse, the largest
// penetration and the smallest support stretch.
inline std::vector<double> totals(const solver_type& s) {
  const energy_balance& e = s.energy();
  return {s.time(), s.time_step(), e.kinetic, e.internal, e.external, e.contact, e.constraint, e.plastic,
          s.tool_impulses()[0][0], s.tool_impulses()[0][1], s.max_penetration(), s.min_stretch()};
}

}  // namespace rkpm::test::bar
