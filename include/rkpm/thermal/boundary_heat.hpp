#pragma once
// The boundary sets' heat in the explicit step of heat_conduction (docs/method.md section 5.9,
// (89), (91), (92)): the heat Q_J of the flux and convection sets at their particles J,
// distributed to the coefficients through the rows N_I(x_J) of the table at the particles (as
// contact forces are, section 6.5), so that sum_I B_I = sum_J Q_J to round-off; convection's part
// of the operator for the stable step; and the rows of the fixed temperatures.
//   rows      discrete_model::at_particles (#particles rows of N_I(x_J))
//   sets      the boundary sets
//   area      #sets, each #particles of the set: A_J = L_J omega(x_J)

#include <span>
#include <utility>
#include <vector>

#include <rkpm/discretization/shape_table.hpp>
#include <rkpm/solver/constraints.hpp>
#include <rkpm/thermal/thermal_boundary.hpp>

namespace rkpm::thermal {

using boundary_areas = std::vector<std::vector<double>>;

// The areas A_J = L_J omega(x_J) of every set at positions x (#particles, current or reference):
// sets made on chains measure their lengths again, and in axisymmetry r_J is taken from x.
template <class G>
void boundary_areas_at(std::vector<thermal_boundary>& sets, std::span<const vec2> x, boundary_areas& area) {
  area.resize(sets.size());
  for (std::size_t s = 0; s < sets.size(); ++s) {
    thermal_boundary& b = sets[s];
    if (b.from_chain) b.length = tributary_lengths(b.particle, x, b.closed_chain);
    area[s].resize(b.particle.size());
    for (std::size_t k = 0; k < b.particle.size(); ++k) area[s][k] = b.length[k] * G::weight_factor(x[b.particle[k]]);
  }
}

// B_I += sum_J N_I(x_J) Q_J of the flux and convection sets at time t for the coefficients T
// (89), (91); returns the heat rates (W) of each kind, {flux, convection}.
inline std::pair<double, double> add_boundary_heat(const shape_table<2>& rows, const std::vector<thermal_boundary>& sets,
                                                   const boundary_areas& area, const std::vector<double>& T, double t,
                                                   std::vector<double>& B) {
  double flux = 0.0, convection = 0.0;
  for (std::size_t s = 0; s < sets.size(); ++s) {
    const thermal_boundary& b = sets[s];
    if (b.kind == boundary_kind::fixed_temperature) continue;
    const double v = b.value(t);
    for (std::size_t k = 0; k < b.particle.size(); ++k) {
      const index_t J = b.particle[k];
      const double Q = b.kind == boundary_kind::heat_flux
                           ? v * area[s][k]
                           : -b.film_coefficient * area[s][k] * (rows.interpolate(J, T) - v);
      (b.kind == boundary_kind::heat_flux ? flux : convection) += Q;
      for (index_t e = rows.offset[J]; e < rows.offset[J + 1]; ++e) B[rows.neighbor[e]] += rows.N[e] * Q;
    }
  }
  return {flux, convection};
}

// y += sum_J h A_J N(x_J) (N(x_J) . x): convection's part of K (the stable step, (90)).
inline void add_convection_operator(const shape_table<2>& rows, const std::vector<thermal_boundary>& sets,
                                    const boundary_areas& area, const std::vector<double>& x, std::vector<double>& y) {
  for (std::size_t s = 0; s < sets.size(); ++s) {
    const thermal_boundary& b = sets[s];
    if (b.kind != boundary_kind::convection) continue;
    for (std::size_t k = 0; k < b.particle.size(); ++k) {
      const index_t J = b.particle[k];
      const double hxJ = b.film_coefficient * area[s][k] * rows.interpolate(J, x);
      for (index_t e = rows.offset[J]; e < rows.offset[J + 1]; ++e) y[rows.neighbor[e]] += rows.N[e] * hxJ;
    }
  }
}

// The fixed temperatures T^h(x_J) = T_b(t) (92): the rows of the fixed sets, each particle once
// (the first set that names it wins), imposed by constraint_projector's projection of a field of
// one component with the capacities as weights (those at construction: any positive weights
// impose the rows exactly).
class fixed_temperatures {
 public:
  fixed_temperatures() = default;
  fixed_temperatures(const std::vector<thermal_boundary>& sets, const shape_table<2>& rows,
                     const std::vector<double>& capacity) {
    std::vector<velocity_constraint> fixed;
    std::vector<char> taken(capacity.size(), 0);
    for (std::size_t s = 0; s < sets.size(); ++s) {
      if (sets[s].kind != boundary_kind::fixed_temperature) continue;
      for (const index_t J : sets[s].particle) {
        if (taken[J]) continue;
        taken[J] = 1;
        fixed.push_back({J, 0, {}});
        set_.push_back(s);
      }
    }
    projector_ = constraint_projector(std::move(fixed), rows, capacity);
    target_.assign(set_.size(), 0.0);
    before_.assign(projector_.touched().size(), 0.0);
  }

  // Projects T at time t and returns the heat it added, sum_I C_I dT_I (J).
  double impose(std::vector<double>& T, const std::vector<thermal_boundary>& sets, const std::vector<double>& capacity,
                double t) {
    if (set_.empty()) return 0.0;
    for (std::size_t r = 0; r < set_.size(); ++r) target_[r] = sets[set_[r]].value(t);
    const std::vector<index_t>& touched = projector_.touched();
    for (std::size_t k = 0; k < touched.size(); ++k) before_[k] = T[touched[k]];
    projector_.project_values(T, target_);
    double heat = 0.0;
    for (std::size_t k = 0; k < touched.size(); ++k) heat += capacity[touched[k]] * (T[touched[k]] - before_[k]);
    return heat;
  }

 private:
  constraint_projector projector_;
  std::vector<std::size_t> set_;  // each row's set
  std::vector<double> target_, before_;
};

}  // namespace rkpm::thermal
