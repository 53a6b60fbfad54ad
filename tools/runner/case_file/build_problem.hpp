#pragma once
// build_problem<Contact>(case, resolution): the rkpm::problem a case file describes, for any
// contact policy. Resolution K refines as the typed cases do (cases/parameters.hpp): a
// rectangle of n particles per direction gets (n - 1) K + 1, a polygon's spacing is divided by
// K (gmsh_bodies.hpp). A rectangle builds exactly the particles and cells of make_grid_particles and
// make_grid_mesh, in the same order, so a paper case file reproduces its typed case bit for
// bit.

#include <map>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include <rkpm/contact/enforcement.hpp>
#include <rkpm/discretization/background_mesh.hpp>
#include <rkpm/discretization/particle_set.hpp>
#include <rkpm/solver/problem.hpp>

#include "body_edges.hpp"
#include "case_description.hpp"
#include "case_material.hpp"
#include "cases/contact_setup.hpp"
#include "cases/parameters.hpp"
#include "diagnostics.hpp"
#include "gmsh_bodies.hpp"
#include "make_tools.hpp"

namespace rkpm::runner::case_file {

// One line "FILE: POINTER: message", as load_case_file reports.
[[noreturn]] inline void fail_at(const case_description& c, const std::string& at, const std::string& message) {
  diagnostics d(c.file.string());
  d.error(at, message);
  d.throw_if_any();
  throw rkpm::error(message);  // not reached
}

inline material_type make_material(const material_description& m) {
  const material::elastic_constants constants{m.youngs_modulus, m.poisson_ratio, m.density};
  if (m.law != material::j2_name) return material_type(constants, hardening_law::no_yield());
  if (m.hardening == material::hardening::power_law::name)
    return material_type(constants, hardening_law::of(material::hardening::power_law{
                                        m.flow_coefficient, m.flow_offset, m.flow_exponent}));
  return material_type(constants, hardening_law::of(material::hardening::linear{m.yield_stress, m.hardening_modulus}));
}

namespace detail {

inline std::pair<particle_set<2>, background_mesh> discretize(const case_description& c, const body_description& b,
                                                              int resolution) {
  if (const auto* r = std::get_if<rectangle_shape>(&b.shape)) {
    const Eigen::Vector2i n(cases::refined_count(r->particles[0], resolution),
                            cases::refined_count(r->particles[1], resolution));
    return {make_grid_particles<2>(r->lower_left, r->upper_right, n, c.support_factor),
            make_grid_mesh(r->lower_left, r->upper_right, n)};
  }
  return gmsh_discretize(c, b, resolution, [&](const std::string& at, const std::string& message) {
    fail_at(c, at, message);
  });
}

// Velocity constraints of the body's edges; a particle shared by two edges (a corner) is
// constrained once per direction, and refused if the edges prescribe different values there.
inline std::vector<velocity_constraint> make_constraints(const case_description& c, const body_description& b,
                                                         const std::vector<vec2>& X) {
  std::vector<velocity_constraint> out;
  std::map<std::pair<index_t, int>, std::pair<double, std::string>> given;
  for (const auto& k : b.constraints)
    for (index_t I : particles_on_edge(b, X, k.edge))
      for (int dir = 0; dir < 2; ++dir) {
        if (!k.velocity[dir]) continue;
        const double v = *k.velocity[dir];
        const auto [it, fresh] = given.try_emplace({I, dir}, v, k.edge);
        if (!fresh) {
          if (it->second.first != v)
            fail_at(c, child_pointer(k.at, "velocity_m_s"),
                    fmt::format("edges '{}' and '{}' prescribe different {} velocities ({:g} and {:g} m/s) at their "
                                "shared particle ({:g}, {:g}); make them agree", it->second.second, k.edge,
                                dir == 0 ? "x" : "y", it->second.first, v, X[I].x(), X[I].y()));
          continue;
        }
        velocity_constraint vc{I, dir, {}};
        if (v != 0.0) vc.velocity = [v](double) { return v; };  // an empty function holds it at rest
        out.push_back(std::move(vc));
      }
  return out;
}

}  // namespace detail

template <class Contact>
problem<material_type, Contact> build_problem(const case_description& c, int resolution) {
  if (resolution < 1) fail("resolution {} must be a whole number >= 1", resolution);
  if (c.bodies.size() != 1)
    fail_at(c, "/bodies", fmt::format("{} bodies; the solver has exactly one deformable body", c.bodies.size()));
  const body_description& b = c.bodies.front();
  if constexpr (requires { typename Contact::enforcement_type; })
    if (std::is_same_v<typename Contact::enforcement_type, contact::enforcement::penalty> && !c.penalty_stiffness)
      fail_at(c, "/contact", "the penalty enforcement needs a stiffness; add \"penalty_stiffness_N_m\": 1e11 to "
                             "\"contact\"");
  auto [particles, mesh] = detail::discretize(c, b, resolution);
  std::vector<velocity_constraint> constraints = detail::make_constraints(c, b, particles.position);
  problem<material_type, Contact> pr{
      .particles = std::move(particles),
      .mesh = std::move(mesh),
      .material = make_material(b.material),
      .contact = cases::make_contact<Contact>(make_tools(c), c.friction, c.penalty_stiffness.value_or(0.0)),
      .initial_velocity = {},
      .constraints = std::move(constraints),
      .body_force = b.body_force,
      .slave_particles = {},
  };
  if (b.initial_velocity != vec2::Zero()) pr.initial_velocity = [v = b.initial_velocity](const vec2&) { return v; };
  if (b.all_slaves)
    for (index_t I = 0; I < pr.particles.size(); ++I) pr.slave_particles.push_back(I);
  return pr;
}

}  // namespace rkpm::runner::case_file
