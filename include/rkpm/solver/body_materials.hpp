#pragma once
// materials_by_body<M>: the material constants of each body of a problem (docs/method.md
// section 3.1), as the solver reads them: the material at a quadrature point (stress update),
// the density at a particle (lumped mass m_I = rho0_b V_I) and the Lame moduli at a point (the
// stable step, where the fastest body governs). Bodies are the model's (discrete_model::bodies),
// numbered in the order of their first cells, which is the order append_body / add_body added them.
// With problem::body_materials empty every body is problem::material, and one body gives
// exactly the arithmetic of a problem without bodies (no lookup tables are built).

#include <string>
#include <utility>
#include <vector>

#include <rkpm/concepts/material.hpp>
#include <rkpm/core/error.hpp>
#include <rkpm/solver/discrete_model.hpp>
#include <rkpm/solver/stable_time_step.hpp>

namespace rkpm {

template <Material M>
class materials_by_body {
 public:
  materials_by_body() = default;

  // `shared`: problem::material; `per_body`: problem::body_materials (empty, or one per body
  // of the model, discrete_model::bodies).
  materials_by_body(const discrete_model& m, M shared, std::vector<M> per_body) {
    if (per_body.empty()) {
      material_.push_back(std::move(shared));
      check(0, false);
    } else {
      material_ = std::move(per_body);
      const index_t bodies = m.bodies.count();
      if (static_cast<index_t>(material_.size()) != bodies)
        fail("problem: {} body_materials for {} bodies (the connected parts of the cells, numbered from 0 in the "
             "order of their first cells, i.e. the order append_body / add_body added them): give one material "
             "per body, or none to give every body problem::material",
             material_.size(), bodies);
      for (index_t b = 0; b < bodies; ++b) check(b, true);
      if (bodies > 1) {
        particle_body_ = m.bodies.particle_body();
        moduli_.point_body = m.bodies.point_body();
      }
    }
    for (const M& mat : material_)
      moduli_.body.push_back({mat.constants().lame_lambda(), mat.constants().shear_modulus()});
  }

  // The materials given: one (every body's) or one per body.
  index_t count() const { return static_cast<index_t>(material_.size()); }
  const M& of_body(index_t b) const { return material_[b]; }
  const M& at_point(index_t q) const {
    return moduli_.point_body.empty() ? material_[0] : material_[moduli_.point_body[q]];
  }
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
  std::vector<index_t> particle_body_;  // empty: one material everywhere (copies of the model's)
  point_moduli moduli_;                 // also each point's body (point_body; empty: one body)
};

}  // namespace rkpm
