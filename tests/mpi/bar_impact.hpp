#pragma once
// The bar of mpi/bar_problem.hpp thrown at 150 m/s onto a rigid anvil with Coulomb friction
// (axisymmetric, J2, Q2): a problem whose step has all of its parts (the axis constraints, the
// contact, the force loop, the stable step re-estimated), for the tests of the whole step on
// several processes (mpi/distributed_step.cpp, distributed_restart.cpp, distributed_bodies.cpp),
// and what they compare with one process.

#include <cstring>
#include <vector>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/parallel/communicator.hpp>
#include <rkpm/parallel/distributed_solver.hpp>
#include <rkpm/parallel/gather.hpp>
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

// The totals every rank has: time, step size, the energies, the largest penetration, the
// smallest support stretch and each tool's impulse.
inline std::vector<double> totals(const solver_type& s) {
  const energy_balance& e = s.energy();
  std::vector<double> t{s.time(),    s.time_step(),  e.kinetic, e.internal,         e.external,
                        e.contact,   e.constraint,   e.plastic, s.max_penetration(), s.min_stretch()};
  for (const vec2& impulse : s.tool_impulses()) t.insert(t.end(), {impulse[0], impulse[1]});
  return t;
}

// Whether two runs' totals are the same bits.
inline bool same_totals(const solver_type& a, const solver_type& b) {
  const std::vector<double> x = totals(a), y = totals(b);
  return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size() * sizeof(double)) == 0;
}

// How many particles' owned coefficients and velocities on the ranks differ in any bit from one
// process's, counted on rank 0 (zero elsewhere). Collective.
struct differing_particles {
  index_t coefficients = 0, velocities = 0;
};
inline differing_particles differing(parallel::communicator& world, const parallel::distributed_solver<solver_type>& part,
                                     const solver_type& one) {
  const std::vector<vec2> d = parallel::gather_owned(world, part.plan(), part.solver().coefficients()),
                          v = parallel::gather_owned(world, part.plan(), part.solver().coefficient_velocities());
  differing_particles n;
  for (std::size_t I = 0; I < d.size(); ++I) {
    n.coefficients += std::memcmp(d[I].data(), one.coefficients()[I].data(), sizeof(vec2)) != 0;
    n.velocities += std::memcmp(v[I].data(), one.coefficient_velocities()[I].data(), sizeof(vec2)) != 0;
  }
  return n;
}

}  // namespace rkpm::test::bar
