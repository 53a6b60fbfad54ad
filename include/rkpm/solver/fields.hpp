#pragma once
// Physical fields from RK coefficients (docs/method.md section 2): RK coefficients are not
// nodal values, so a particle's displacement is u(X_I) = sum_J N_J(X_I) d_J, and a
// quadrature-point quantity reaches the particles by the lumped L2 projection
//   value_I = sum_q N_I(X_q) w_q value_q / sum_q N_I(X_q) w_q.

#include <vector>

#include <rkpm/solver/discrete_model.hpp>

namespace rkpm {

// u(X_I) = sum_J N_J(X_I) c_J at every particle.
inline std::vector<vec2> values_at_particles(const discrete_model& m, const std::vector<vec2>& c) {
  std::vector<vec2> out(m.particle_count());
  for (index_t I = 0; I < m.particle_count(); ++I) out[I] = m.at_particles.interpolate(I, c);
  return out;
}

// at_point(q) carried to the particles by the lumped L2 projection.
template <class Value, class PointValue>
std::vector<Value> project_to_particles(const discrete_model& m, PointValue&& at_point) {
  const auto& tt = m.particles_of_points;
  std::vector<Value> out(m.particle_count());
  for (index_t I = 0; I < m.particle_count(); ++I) {
    Value sum = at_point(index_t{0}) * 0.0;
    for (index_t s = tt.offset[I]; s < tt.offset[I + 1]; ++s)
      sum += m.at_points.N[tt.entry[s]] * m.points.weight[tt.point[s]] * at_point(tt.point[s]);
    out[I] = sum / m.lumped_volume[I];
  }
  return out;
}

}  // namespace rkpm
