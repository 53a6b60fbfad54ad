#pragma once
// Physical fields from RK coefficients (docs/method.md section 2): RK coefficients are not
// nodal values, so a particle's displacement is u(X_I) = sum_J N_J(X_I) d_J, and a
// quadrature-point quantity reaches the particles by the lumped L2 projection
//   value_I = sum_q N_I(X_q) w_q value_q / sum_q N_I(X_q) w_q.

#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include <rkpm/core/process_group.hpp>
#include <rkpm/solver/discrete_model.hpp>

namespace rkpm {

// u(X_I) = sum_J N_J(X_I) c_J at every particle.
inline std::vector<vec2> values_at_particles(const discrete_model& m, const std::vector<vec2>& c) {
  std::vector<vec2> out(m.particle_count());
  for (index_t I = 0; I < m.particle_count(); ++I) out[I] = m.at_particles.interpolate(I, c);
  return out;
}

// Current position x_I = X_I + sum_J N_J(X_I) d_J of particle I, and of every particle.
inline vec2 position_at_particle(const discrete_model& m, const std::vector<vec2>& d, index_t I) {
  return m.at_particles.interpolate(I, d) + m.particles.position[I];
}
inline std::vector<vec2> positions_at_particles(const discrete_model& m, const std::vector<vec2>& d) {
  std::vector<vec2> x(m.particle_count());
  for (index_t I = 0; I < m.particle_count(); ++I) x[I] = position_at_particle(m, d, I);
  return x;
}

// f(q) for each point this process owns: every point of a whole model; of a part of a run on
// several processes, the points it owns among those it computes (parallel/global_blocks.hpp), so
// that a sum over every process's calls counts each point once.
template <class F>
void for_each_owned_point(const discrete_model& m, F&& f) {
  if (!m.own.group) {
    for (index_t q = 0; q < m.point_count(); ++q) f(q);
    return;
  }
  for (const stored_index q : m.own.group->owned_points()) f(static_cast<index_t>(q));
}

namespace detail {

// The projection into particle I's value at(I), zero on entry (a reference or an Eigen::Map).
template <class Value, class PointValue, class At>
void project_into(const discrete_model& m, PointValue&& at_point, At&& at) {
  const auto& t = m.at_points;
  for (index_t q = 0; q < m.point_count(); ++q) {
    const Value value = at_point(q);
    for (index_t e = t.offset[q]; e < t.offset[q + 1]; ++e) at(t.neighbor[e]) += t.N[e] * m.points.weight[q] * value;
  }
  for (index_t I = 0; I < m.particle_count(); ++I) at(I) = at(I) / m.lumped_volume[I];
}

}  // namespace detail

// at_point(q) carried to the particles by the lumped L2 projection.
// One serial pass over the points: each particle's sum runs over its points in ascending order.
template <class Value, class PointValue>
std::vector<Value> project_to_particles(const discrete_model& m, PointValue&& at_point) {
  std::vector<Value> out(m.particle_count(), at_point(index_t{0}) * 0.0);
  detail::project_into<Value>(m, at_point, [&](index_t I) -> Value& { return out[I]; });
  return out;
}

// The same into point-major rows of Components doubles, with no array of Eigen values beside
// them: at_point(q) returns an Eigen vector of Components values (a tensor's components in the
// order a file wants them).
template <int Components, class PointValue>
std::vector<double> project_to_particles_flat(const discrete_model& m, PointValue&& at_point) {
  using row = Eigen::Matrix<double, Components, 1>;
  std::vector<double> out(static_cast<std::size_t>(Components) * m.particle_count(), 0.0);
  detail::project_into<row>(m, at_point, [&](index_t I) {
    return Eigen::Map<row>(out.data() + static_cast<std::size_t>(Components) * I);
  });
  return out;
}

}  // namespace rkpm
