#pragma once
// Heat sources in coefficient space for heat_conduction::advance (docs/method.md section 5.9, the
// s_I of (89)): a heat generated per volume at the quadrature points (beta times the plastic
// power, W/m^3 of reference volume) scattered as the force loop scatters a force,
//   s_I += sum_q N_I(X_q) w_q p_q,
// and a heat generated at a particle (the frictional heat of a contact slave, W) distributed
// through the rows N_I(x_J), as contact forces are (section 6.5). Both keep the total: sum_I s_I is
// sum_q w_q p_q, and Q_J, to round-off (the partition of unity).
//   power  #points heat per reference volume, W/m^3
//   s      #particles heat rates, W (added to)

#include <vector>

#include <rkpm/solver/discrete_model.hpp>

namespace rkpm::thermal {

inline void add_point_heat(const discrete_model& m, const std::vector<double>& power, std::vector<double>& s) {
  const shape_table<2>& t = m.at_points;
  for (index_t q = 0; q < m.point_count(); ++q) {
    const double wp = m.points.weight[q] * power[q];
    for (index_t e = t.offset[q]; e < t.offset[q + 1]; ++e) s[t.neighbor[e]] += t.N[e] * wp;
  }
}

inline void add_particle_heat(const discrete_model& m, index_t J, double heat, std::vector<double>& s) {
  const shape_table<2>& t = m.at_particles;
  for (index_t e = t.offset[J]; e < t.offset[J + 1]; ++e) s[t.neighbor[e]] += t.N[e] * heat;
}

}  // namespace rkpm::thermal
