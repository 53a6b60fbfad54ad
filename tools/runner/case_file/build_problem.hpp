#pragma once
// build_problem<Contact, Material>(case, resolution): the rkpm::problem a case file describes,
// for any contact policy and either case-file material (case_material.hpp; j2_material only for
// a file whose bodies carry neither temperature nor damage, uses_johnson_cook_state in
// case_description.hpp): each body discretized and added with its own material (add_body), its
// constraints, initial velocity and slaves, and the pairs of bodies in contact. Resolution K refines as the typed cases do
// (cases/parameters.hpp): a rectangle of n particles per direction gets (n - 1) K + 1, a
// polygon's spacing is divided by K (gmsh_bodies.hpp). A rectangle builds exactly the
// particles and cells of make_grid_particles and make_grid_mesh, in the same order, so a paper
// case file reproduces its typed case bit for bit.

#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include <rkpm/contact/enforcement.hpp>
#include <rkpm/discretization/background_mesh.hpp>
#include <rkpm/discretization/body_partition.hpp>
#include <rkpm/discretization/boundary_chains.hpp>
#include <rkpm/discretization/particle_set.hpp>
#include <rkpm/kernel/cubic_spline.hpp>
#include <rkpm/kernel/quartic_spline.hpp>
#include <rkpm/material/rankine_fracture.hpp>
#include <rkpm/solver/problem.hpp>

#include "body_edges.hpp"
#include "body_fields.hpp"
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
  fail_in_file(c.file.string(), at, message);
}

// band_width: a Rankine body's crack band (m), its "band_width_m" or band_width_of (unused by the
// other laws).
template <class Material = material_type>
Material make_material(const material_description& m, double band_width = 0.0) {
  const material::elastic_constants constants{m.youngs_modulus, m.poisson_ratio, m.density};
  if (m.johnson_cook || m.zerilli_armstrong || m.rankine) {
    if constexpr (Material::holds_johnson_cook) {
      if (m.johnson_cook) return Material(*m.johnson_cook);
      if (m.zerilli_armstrong) return Material(*m.zerilli_armstrong);
      return Material(material::rankine_fracture(constants, m.rankine->tensile_strength, m.rankine->fracture_energy,
                                                 band_width));
    } else {
      fail("a body with a temperature or a damage ({}) was given a material without room for its state; build the "
           "problem with case_file::material_type (uses_johnson_cook_state)",
           m.law);
    }
  }
  if (m.law != material::j2_name) return Material(constants, hardening_law::no_yield());
  return Material(constants, m.flow_law);
}

namespace detail {

// A Rankine body's crack band (docs/method.md (107)): its "band_width_m", or the width of the
// file's kernel window at the body's largest support radius, so that a crack dissipates G_c per
// unit area at every resolution.
inline double band_width_of(const case_description& c, const body_description& b, const particle_set<2>& particles) {
  if (!b.material.rankine) return 0.0;
  if (b.material.rankine->band_width) return *b.material.rankine->band_width;
  double support = 0.0;
  for (const auto& a : particles.support) support = std::max({support, a[0], a[1]});
  return c.method.kernel == kernel::quartic_spline::name
             ? material::rankine_fracture::band_width_of_support<kernel::quartic_spline>(support)
             : material::rankine_fracture::band_width_of_support<kernel::cubic_spline>(support);
}

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

// The file's pairs of bodies in contact as body numbers (the file's order), with each pair's
// roles swapped too for two passes.
inline std::vector<contact::body_pair> make_body_pairs(const case_description& c) {
  const auto number = [&](const std::string& name) {
    for (std::size_t k = 0; k < c.bodies.size(); ++k)
      if (c.bodies[k].name == name) return static_cast<index_t>(k);
    fail("case file: no body '{}' (was the file checked by load_case_file?)", name);
  };
  std::vector<contact::body_pair> pairs;
  const auto add = [&](index_t slave, index_t master) {
    for (const auto& p : pairs)
      if (p.slave == slave && p.master == master) return;
    pairs.push_back({slave, master});
  };
  for (const auto& p : c.body_pairs) add(number(p.slave), number(p.master));
  if (c.two_pass)
    for (const auto& p : c.body_pairs) add(number(p.master), number(p.slave));
  return pairs;
}

// Refuses body k if it overlaps an earlier body at t = 0, with the test the model's builder makes
// on the cells (first_overlap: a node or cell centre of one strictly inside a cell of the other),
// so that the message can name both bodies and point at the file.
inline void check_apart(const case_description& c, const std::vector<std::pair<particle_set<2>, background_mesh>>& bodies,
                        std::size_t k) {
  const auto box = [](const background_mesh& m) {
    vec2 lo = m.node.front(), hi = m.node.front();
    for (const vec2& x : m.node) {
      lo = lo.cwiseMin(x);
      hi = hi.cwiseMax(x);
    }
    return std::pair{lo, hi};
  };
  const auto [lo_k, hi_k] = box(bodies[k].second);
  for (std::size_t j = 0; j < k; ++j) {
    const auto [lo_j, hi_j] = box(bodies[j].second);
    if ((lo_k.array() >= hi_j.array()).any() || (lo_j.array() >= hi_k.array()).any()) continue;
    particle_set<2> particles;
    background_mesh mesh;
    append_body(particles, mesh, bodies[j].first, bodies[j].second);
    append_body(particles, mesh, bodies[k].first, bodies[k].second);
    index_t parts = 0;
    const std::vector<index_t> cell_body = cell_bodies(mesh, &parts);
    if (first_overlap(mesh, cell_body, parts))
      fail_at(c, child_pointer(c.bodies[k].at, "shape"),
              fmt::format("body '{}' overlaps body '{}' at t = 0 (a cell of one reaches inside the other); move "
                          "them apart: bodies may touch along their boundaries, not overlap",
                          c.bodies[k].name, c.bodies[j].name));
  }
}

}  // namespace detail

// Bodies are added in the file's order (add_body), so body k of the problem is the file's
// /bodies/k; one body gives exactly the problem of a file without bodies (problem::material).
template <class Contact, class Material = material_type>
problem<Material, Contact> build_problem(const case_description& c, int resolution) {
  if (resolution < 1) fail("resolution {} must be a whole number >= 1", resolution);
  if (c.bodies.empty()) fail_at(c, "/bodies", "no body; give the deformable body");
  const body_description& first = c.bodies.front();
  if constexpr (requires { typename Contact::enforcement_type; })
    if (std::is_same_v<typename Contact::enforcement_type, contact::enforcement::penalty> && !c.penalty_stiffness)
      fail_at(c, "/contact", "the penalty enforcement needs a stiffness; add \"penalty_stiffness_N_m\": 1e11 to "
                             "\"contact\"");
  problem<Material, Contact> pr{
      .particles = {},
      .mesh = {},
      .material = Material({first.material.youngs_modulus, first.material.poisson_ratio, first.material.density},
                           hardening_law::no_yield()),  // the first body's, below
      .contact = c.self_contact ? cases::make_contact<Contact>(make_tools(c), c.friction,
                                                              c.penalty_stiffness.value_or(0.0), contact::all_body_pairs)
                                : cases::make_contact<Contact>(make_tools(c), c.friction,
                                                              c.penalty_stiffness.value_or(0.0), detail::make_body_pairs(c)),
      .initial_velocity = {},
      .constraints = {},
      .body_force = vec2::Zero(),  // set_body_force below
      .slave_particles = {},
  };
  std::vector<std::pair<particle_set<2>, background_mesh>> parts;
  std::vector<index_t> start;  // first particle of each body
  bool listed_slaves = false;
  for (std::size_t k = 0; k < c.bodies.size(); ++k) {
    const body_description& b = c.bodies[k];
    if (!(b.body_force == first.body_force))
      fail_at(c, child_pointer(b.at, "body_force_m_s2"),
              fmt::format("body '{}' has another body force than body '{}'; the solver takes one acceleration for "
                          "all bodies (gravity): give them the same", b.name, first.name));
    parts.push_back(detail::discretize(c, b, resolution));
    detail::check_apart(c, parts, k);
    const auto offset = static_cast<index_t>(pr.particles.size());
    start.push_back(offset);
    for (velocity_constraint& vc : detail::make_constraints(c, b, parts[k].first.position)) {
      vc.particle += offset;
      pr.constraints.push_back(std::move(vc));
    }
    Material material = pr.material;
    try {
      material = make_material<Material>(b.material, detail::band_width_of(c, b, parts[k].first));
    } catch (const error& e) {  // a band too wide for the law (103): the particles too coarse
      fail_at(c, child_pointer(b.at, "material"), e.what());
    }
    try {
      add_body(pr, parts[k].first, parts[k].second, std::move(material));
    } catch (const error& e) {
      fail_at(c, child_pointer(b.at, "shape"), e.what());
    }
    listed_slaves = listed_slaves || b.slave_layers != 1;
  }
  start.push_back(static_cast<index_t>(pr.particles.size()));
  pr.material = pr.body_materials.front();
  if (c.bodies.size() == 1) pr.body_materials.clear();  // problem::material, as a typed problem of one body
  set_initial_velocity(c, pr, start);
  set_body_force(c, pr);
  // Slaves: none given means every body's boundary nodes; "all" lists a body's every particle,
  // {"layers": K} those within K cell layers of its surface (the axis is not surface).
  if (listed_slaves)
    for (std::size_t k = 0; k < c.bodies.size(); ++k) {
      const int layers = c.bodies[k].slave_layers;
      const auto& [particles, mesh] = parts[k];
      std::vector<index_t> local;
      if (layers == 0)
        for (index_t I = 0; I < particles.size(); ++I) local.push_back(I);
      else if (layers == 1)
        local = mesh.boundary_nodes();
      else
        local = surface_layers(mesh, layers, [&](index_t I) {
          return c.geometry == "axisymmetric" && particles.position[I][0] <= 0.0;
        });
      for (index_t I : local) pr.slave_particles.push_back(start[k] + I);
    }
  return pr;
}

}  // namespace rkpm::runner::case_file
