#pragma once
// materials_by_body<M>: the material constants of each body of a problem (docs/method.md
// section 3.1), as the solver reads them: the material at a quadrature point (stress update),
// the density at a particle (lumped mass m_I = rho0_b V_I) and the Lame moduli at a point (the
// stable step, where the fastest body governs). Bodies are numbered as partition_bodies numbers
// them: in the order of their first cells, which is the order append_body / add_body added them.
// With problem::body_materials empty every body is problem::material, and one body gives
// exactly the arithmetic of a problem without bodies (no lookup tables are built).

#include <string>
#include <utility>
#include <vector>

#include <rkpm/concepts/material.hpp>
#include <rkpm/core/error.hpp>
#include <rkpm/discretization/body_partition.hpp>
#include <rkpm/solver/discrete_model.hpp>
#include <rkpm/solver/stable_time_step.hpp>

namespace rkpm {

template <Material M>
class materials_by_body {
 public:
  materials_by_body() = default;

  // `shared`: problem::material; `per_body`: problem::body_materials (empty, or one per body).
  materials_by_body(const discrete_model& m, M shared, std::vector<M> per_body) {
    if (per_body.empty()) {
      material_.push_back(std::move(shared));
      check(0, false);
    } else {
      material_ = std::move(per_body);
      const body_partition part = partition_bodies(m.particles.position, m.mesh);
      if (static_cast<index_t>(material_.size()) != part.bodies)
        fail("problem: {} body_materials for {} bodies (the connected parts of the cells, numbered from 0 in the "
             "order of their first cells, i.e. the order append_body / add_body added them): give one material "
             "per body, or none to give every body problem::material",
             material_.size(), part.bodies);
      for (index_t b = 0; b < part.bodies; ++b) check(b, true);
      if (part.bodies > 1) {
        particle_body_ = part.particle_body;
        // Kernels never reach across bodies (solver/body_models.hpp): a point's body is that of
        // any particle in its row.
        moduli_.point_body.resize(m.point_count());
        for (index_t q = 0; q < m.point_count(); ++q)
          moduli_.point_body[q] = particle_body_[m.at_points.neighbor[m.at_points.offset[q]]];
      }
    }
    for (const M& mat : material_)
      moduli_.body.push_back({mat.constants().lame_lambda(), mat.constants().shear_modulus()});
  }

  index_t bodies() const { return static_cast<index_t>(material_.size()); }
  const M& of_body(index_t b) const { return material_[b]; }
  const M& at_point(index_t q) const {
    return moduli_.point_body.empty() ? material_[0] : material_[moduli_.point_body[q]];
  }
  index_t body_of_particle(index_t I) const { return particle_body_.empty() ? 0 : particle_body_[I]; }
  // The moduli the stable step is estimated with (solver/time_step_controller.hpp).
  const point_moduli& moduli() const { return moduli_; }

  // Lumped masses m_I = rho0 V_I with the density of particle I's body (docs/method.md (38)).
  std::vector<double> lumped_masses(const discrete_model& m) const {
    if (particle_body_.empty()) return rkpm::lumped_masses(m, material_[0].density());
    std::vector<double> mass(m.lumped_volume.size());
    for (std::size_t I = 0; I < mass.size(); ++I) mass[I] = material_[particle_body_[I]].density() * m.lumped_volume[I];
    return mass;
  }

 private:
  // The material constructors validate their constants, but a Material of the user's own need
  // not: checked again here, and with several bodies the message names the body.
  void check(index_t b, bool name_body) const {
    try {
      material_[b].constants().validate();
    } catch (const error& e) {
      if (!name_body) throw;
      fail("body {} (problem::body_materials[{}]): {}", b, b, e.what());
    }
  }

  std::vector<M> material_;
  std::vector<index_t> particle_body_;  // empty: one material everywhere
  point_moduli moduli_;                 // also each point's body (point_body; empty: one body)
};

}  // namespace rkpm
