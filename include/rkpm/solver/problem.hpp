#pragma once
// problem: the run-time description of one simulation that a case builds for any
// configuration type (docs/method.md section 9.1): particles, cells, material, contact (with its
// tools), initial velocity, constraints and body force (constant, or a field b(X, t)); and
// run_options for the stepping.
// Several bodies (docs/method.md section 3.1) are the connected parts of the cells; add_body
// appends one with its own material constants and returns its number.

#include <functional>
#include <utility>
#include <vector>

#include <rkpm/core/error.hpp>
#include <rkpm/discretization/background_mesh.hpp>
#include <rkpm/discretization/body_partition.hpp>
#include <rkpm/discretization/particle_set.hpp>
#include <rkpm/solver/constraints.hpp>
#include <rkpm/solver/mass_scaling.hpp>
#include <rkpm/solver/rereference.hpp>

namespace rkpm {

template <class Material, class Contact>
struct problem {
  particle_set<2> particles;
  background_mesh mesh;
  Material material;
  Contact contact;
  // Physical initial velocity v0(X); the coefficients start at v0(X_I), exact for linear fields.
  std::function<vec2(const vec2&)> initial_velocity;
  // Or per particle, taking precedence: v0 of particle I at X_I, for bodies that touch at t = 0
  // (particles of two bodies at one position) and move apart.
  std::function<vec2(index_t, const vec2&)> initial_particle_velocity;
  // Prescribed physical velocities; in axisymmetric geometry u_r = 0 on the axis is added.
  std::vector<velocity_constraint> constraints;
  vec2 body_force = vec2::Zero();  // acceleration (m/s^2), e.g. gravity
  // Or an acceleration that varies, b(X, t) at the particle's reference position X and time t
  // (m/s^2), in place of body_force when given: f_ext,I = m_I b(X_I, t). Called from one thread,
  // once per particle per step (so it need not be thread-safe).
  std::function<vec2(const vec2& X, double t)> body_force_field;
  // Contact slave particles; empty means the boundary nodes of the mesh when the mesh nodes are
  // the particles (make_grid_mesh + make_grid_particles), else none.
  std::vector<index_t> slave_particles;
  // Material constants per body: body_materials[b] is body b's, the bodies numbered as
  // partition_bodies numbers them, from 0 in the order of their first cells (the order append_body
  // or add_body added them; add_body returns the number). Empty: every body is `material`;
  // otherwise one per body, and `material` is not used.
  std::vector<Material> body_materials;
};

// Appends a body (its particles and its cells, which must be connected: one body) with its own
// material, and returns its number, the one contact::body_pair and body_materials use. Every
// body of the problem must come with its material: add all of them with add_body.
template <class Material, class Contact>
index_t add_body(problem<Material, Contact>& p, const particle_set<2>& particles, const background_mesh& cells,
                 Material material) {
  index_t before = 0, parts = 0;
  if (p.mesh.cells() > 0) cell_bodies(p.mesh, &before);
  cell_bodies(cells, &parts);
  if (before != static_cast<index_t>(p.body_materials.size()))
    fail("add_body: the problem already has {} bodies but {} body_materials; add every body with add_body", before,
         p.body_materials.size());
  if (parts != 1)
    fail("add_body: the cells given form {} separate bodies; add each connected part with its own add_body", parts);
  append_body(p.particles, p.mesh, particles, cells);
  p.body_materials.push_back(std::move(material));
  return before;
}

struct run_options {
  double end_time = 0.0;            // s
  double time_step_fraction = 0.7;  // dt = fraction * stable step (estimated, re-estimated)
  double fixed_time_step = 0.0;     // s; > 0 forces dt (checked against the stable limit)
  int time_step_update_interval = 10;  // steps between re-estimates of the stable step
  double max_moment_condition = 1e10;  // RK moment-matrix conditioning limit
  double axis_tolerance = 1e-9;        // relative to the body size: particles with r below lie on the axis
  index_t max_steps = 50'000'000;      // a run needing more steps is refused (a wrong constant, not a long run)
  rereference_policy rereference;      // when the kernels are rebuilt in the current configuration (never by default)
  mass_scaling_policy mass_scaling;    // masses scaled for a slow process (none by default)

  void validate() const;
};

inline void run_options::validate() const {
  if (!(end_time >= 0.0)) fail("end time {} must be non-negative", end_time);
  if (!(time_step_fraction > 0.0 && time_step_fraction <= 1.0))
    fail("time step fraction {} must lie in (0, 1]: the central-difference scheme is unstable beyond "
         "the stable step", time_step_fraction);
  if (!(fixed_time_step >= 0.0)) fail("fixed time step {} must be positive (or 0 for automatic)", fixed_time_step);
  if (time_step_update_interval < 1) fail("time step update interval must be at least 1 step");
  if (max_steps < 1) fail("max_steps {} must be at least 1", max_steps);
  rereference.validate();
  mass_scaling.validate();
}

}  // namespace rkpm
