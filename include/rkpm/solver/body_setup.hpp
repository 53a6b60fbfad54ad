#pragma once
// What the solver derives from the problem once, before the first step:
//   axis_constraints   u_r = 0 on the axis of an axisymmetric body (docs/method.md section 5.7)
//   select_slaves      the contact slaves and their shape-function rows (docs/method.md section 6)
//   initial_velocities the coefficient velocities at t = 0 from the problem's functions

#include <algorithm>
#include <limits>
#include <vector>

#include <rkpm/concepts/contact.hpp>
#include <rkpm/concepts/geometry.hpp>
#include <rkpm/core/error.hpp>
#include <rkpm/solver/constraints.hpp>
#include <rkpm/solver/discrete_model.hpp>

namespace rkpm {

// Appends u_r = 0 at every particle on the axis (r <= tolerance x body size) of an
// axisymmetric body; refuses a particle at r < 0. Plane strain adds nothing.
template <Geometry G>
void add_axis_constraints(const discrete_model& m, double relative_tolerance,
                          std::vector<velocity_constraint>& constraints) {
  if constexpr (G::is_axisymmetric) {
    double size = 0.0, rmin = std::numeric_limits<double>::infinity();
    for (const vec2& X : m.particles.position) {
      size = std::max(size, X.cwiseAbs().maxCoeff());
      rmin = std::min(rmin, X[0]);
    }
    const double tol = relative_tolerance * size;
    if (rmin < -tol) fail("axisymmetric body has a particle at r = {:.6g} < 0: give the half section r >= 0", rmin);
    for (index_t I = 0; I < m.particle_count(); ++I)
      if (m.particles.position[I][0] <= tol) constraints.push_back({I, 0, {}});
  }
}

// The slaves of a body with contact (tools or body pairs): the given particles, or, when none are given, the boundary
// nodes of the mesh if the mesh nodes are the particles (make_grid_mesh + make_grid_particles).
// With the rows N_I(X_J) of each slave J.
// The slave particles alone (select_slaves' choice), which need no table.
inline std::vector<index_t> slave_particles(const discrete_model& m, std::vector<index_t> slaves, bool with_contact) {
  if (slaves.empty() && with_contact) {
    if (!m.bodies.nodes_are_particles())
      fail("contact needs slave particles: the mesh nodes are not the particles, so give "
           "problem.slave_particles (the boundary particles) explicitly");
    slaves = m.mesh.boundary_nodes();
  }
  for (const index_t J : slaves)
    if (J < 0 || J >= m.particle_count()) fail("slave particle {} does not exist", J);
  return slaves;
}

inline contact_slaves select_slaves(const discrete_model& m, std::vector<index_t> slaves, bool with_contact) {
  slaves = slave_particles(m, std::move(slaves), with_contact);
  contact_slaves out;
  auto& t = out.table;
  for (index_t J : slaves) {
    const auto& src = m.at_particles;
    for (index_t e = src.offset[J]; e < src.offset[J + 1]; ++e) {
      t.neighbor.push_back(src.neighbor[e]);
      t.N.push_back(src.N[e]);
    }
    t.offset.push_back(static_cast<index_t>(t.neighbor.size()));
  }
  out.particle = std::move(slaves);
  return out;
}

// v_I = problem.initial_particle_velocity(I, X_I) (I: the index in the whole model), else problem.initial_velocity(X_I); v is left
// as it is (at rest) when the problem gives neither.
template <class Problem>
void initial_velocities(const discrete_model& m, const Problem& p, std::vector<vec2>& v) {
  const auto& X = m.particles.position;
  if (p.initial_particle_velocity)
    for (index_t I = 0; I < m.particle_count(); ++I) v[I] = p.initial_particle_velocity(m.global_particle(I), X[I]);
  else if (p.initial_velocity)
    for (index_t I = 0; I < m.particle_count(); ++I) v[I] = p.initial_velocity(X[I]);
}

}  // namespace rkpm
