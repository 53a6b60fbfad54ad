#pragma once
// point_materials<G, M, V>::internal_force and its batched update (solver/point_materials.hpp): the
// force loop over the traversal's tiles, the material at every point (lanes_of<V> points at a time
// where the material has a batched update, with the same bits), the tiles' sums in order.
// Included at the end of solver/point_materials.hpp.

#include <array>
#include <cmath>
#include <exception>
#include <limits>
#include <vector>

#include <rkpm/solver/point_materials.hpp>

namespace rkpm {

template <Geometry G, Material M, class V>
void point_materials<G, M, V>::internal_force(const discrete_model& m, const materials_by_body<M>& material,
                                           const std::vector<vec2>& d, std::vector<vec2>& f_int,
                                           step_context where) {
  const point_traversal& tr = m.traversal;
  tile_.assign(tr.tiles(), tile_summary{});
  // ln dt once for every point, for a law that takes it (UpdatesWithStepLog, concepts/material.hpp).
  const double log_dt = where.dt > 0.0 ? std::log(where.dt) : std::numeric_limits<double>::quiet_NaN();
  const auto point = [&](index_t t, index_t q, const point_gradient& g, mat2& S, double& hoop) {
    tile_summary& tile = tile_[t];  // its points are visited in order by one thread
    const mat3 F_rel = deformation_gradient_at(m, q, g);
    const mat3 F = reference_.active() ? reference_.total(q, block_matrix::of(F_rel)).full() : F_rel;
    const double J = block_matrix::of(F).determinant();  // F.determinant()'s value, fewer flops
    if (!(J > 0.0) || !std::isfinite(J)) {
      tile.fail(q, failure::inverted, J);
      return;
    }
    if constexpr (!state_records_F) F_[q] = block_matrix::of(F);
    mat3 tau;
    try {
      tau = material_update(material.at_point(q), F, state_[q],
                            material_step{where.dt, where.time, state_temperature(state_[q])}, log_dt);
    } catch (const std::exception& ex) {
      tile.fail(q, failure::material, J);
#pragma omp critical(rkpm_material_error)
      if (error_.empty() || q < error_point_) {
        error_ = ex.what();
        error_point_ = q;
      }
      return;
    }
    if constexpr (!stress_recomputed) tau_[q] = block_matrix::of(tau);
    if constexpr (BreakingState<state_type>) tile.broken += state_[q].failed() ? 1 : 0;
    if (reference_.active()) point_force_rereferenced(m, tile, q, F_rel, tau, S, hoop);
    else point_force(m, tile, q, F, tau, S, hoop);
  };
  if constexpr (batched) {
    assemble_point_batches<G, lanes_of<V>>(
        m, d, f_int, [&](index_t t, index_t q0, int n, const point_gradient* g, mat2* S, double* hoop) {
          if (n < lanes_of<V> || !batch_update(m, material, t, q0, g, S, hoop, where))
            for (int k = 0; k < n; ++k) point(t, q0 + k, g[k], S[k], hoop[k]);
        });
  } else {
    assemble_point_forces<G>(m, d, f_int, point);
  }
  // The tiles in order: the same sums and the same first failure whatever the thread count.
  double narrowest = std::numeric_limits<double>::infinity(), plastic = 0.0;
  index_t broken = 0;
  for (const tile_summary& tile : tile_) {
    if (tile.failed != failure::none) report_failure(m, tile, where);
    narrowest = std::min(narrowest, tile.narrowest);
    plastic += tile.plastic;
    broken += tile.broken;
  }
  min_stretch_ = narrowest;
  plastic_work_ = plastic;
  failed_points_ = broken;
}

template <Geometry G, Material M, class V>
bool point_materials<G, M, V>::batch_update(const discrete_model& m, const materials_by_body<M>& material, index_t t,
                                         index_t q0, const point_gradient* g, mat2* S, double* hoop,
                                         step_context where) {
  // F relative to the current reference, and the total F the material takes (79).
  constexpr int lanes = lanes_of<V>;
  std::array<mat3, lanes> F;
  std::array<block_matrix, lanes> total;
  const bool rereferenced = reference_.active();
  for (int k = 0; k < lanes; ++k) {
    F[k] = deformation_gradient_at(m, q0 + k, g[k]);
    total[k] = rereferenced ? reference_.total(q0 + k, block_matrix::of(F[k])) : block_matrix::of(F[k]);
    const double J = total[k].determinant();
    if (!(J > 0.0) || !std::isfinite(J) || &material.at_point(q0 + k) != &material.at_point(q0)) return false;
  }
  if (!updates_in_lanes(material.at_point(q0))) return false;
  const basic_block_lanes<V> F_lanes = gather_block<V>([&](int k) { return total[k]; });
  basic_block_lanes<V> tau;
  try {
    tau = kirchhoff_stress_batch(material.at_point(q0), F_lanes, &state_[q0],
                                           material_step{where.dt, where.time, std::numeric_limits<double>::quiet_NaN()});
  } catch (const std::exception&) {
    return false;
  }
  // point_force of the lanes (solver/point_force_terms.hpp), the tile's sums in point order.
  const V weight = gather_lanes<V>([&](int k) { return m.points.weight[q0 + k]; });
  const V radius = gather_lanes<V>([&](int k) { return m.points.position[q0 + k][0]; });
  tile_summary& tile = tile_[t];
  if constexpr (BreakingState<state_type>)
    for (int k = 0; k < lanes; ++k) tile.broken += state_[q0 + k].failed() ? 1 : 0;
  if (rereferenced) {  // (80): F_rel with tau / det F_r, as point_force_rereferenced
    const V volume_change = gather_lanes<V>([&](int k) { return reference_.volume_change(q0 + k); });
    const basic_block_lanes<V> tau_r{tau.xx / volume_change, tau.xy / volume_change, tau.yx / volume_change,
                            tau.yy / volume_change, tau.zz / volume_change};
    const basic_block_lanes<V> F_rel = gather_block<V>([&](int k) { return block_matrix::of(F[k]); });
    const V stretch =
        support_stretch(point_forces_in_lanes<G>(F_rel, tau_r, weight, radius, S, hoop), support_inverse_);
    for (int k = 0; k < lanes; ++k) {
      tile.narrowest = std::min(tile.narrowest, std::min(static_cast<double>(stretch[k]), F[k](2, 2)));
      add_plastic_work(tile, q0 + k,
                       state_[q0 + k].plastic_work * m.points.weight[q0 + k] *
                           reference_.initial_volume_per_weight(q0 + k));
    }
    return true;
  }
  const V stretch =
      support_stretch(point_forces_in_lanes<G>(F_lanes, tau, weight, radius, S, hoop), support_inverse_);
  for (int k = 0; k < lanes; ++k) {
    tile.narrowest = std::min(tile.narrowest, std::min(static_cast<double>(stretch[k]), F[k](2, 2)));
    add_plastic_work(tile, q0 + k, state_[q0 + k].plastic_work * m.points.weight[q0 + k]);
  }
  return true;
}

}  // namespace rkpm
