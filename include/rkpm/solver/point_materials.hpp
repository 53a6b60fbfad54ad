#pragma once
// point_materials<G, M, V>: the material at every quadrature point and the internal force it
// gives (docs/method.md sections 4 and 5). At the coefficients d:
//   F_q = I + H_q (in-plane block),  F33 from the geometry,  tau_q from the material update,
//   S_q = tau_q F_q^-T w_q (in-plane),  h_q = tau33_q / F33_q w_q / R_q (axisymmetric),
// scattered by the force loop (solver/point_forces.hpp) into f_int. It also records what the
// time-step controller and the energy ledger read: the narrowest support stretch and the
// plastic work, summed per tile of the traversal (discretization/point_traversal.hpp) inside
// the parallel loop and then tile by tile, so the sums do not depend on the thread count.
// Per point it keeps the material state and only what the state cannot give again: F (as its
// block entries, core/block_matrix.hpp) unless the state records it (J2's F_n, the F of the
// last accepted update, which is this evaluation's F), tau unless the material recomputes it
// (current_kirchhoff_stress, concepts/material.hpp). det F and tau are computed from them when
// asked for (output). A point with det F <= 0 or a failed material update stops the run with
// an error naming the first such point, its position and the step.
// After a re-reference (rereference()) the gradients are those of the current reference: the
// material gets F = F_rel F_r and the force terms F_rel with tau / det F_r (docs/method.md
// (79)-(80), solver/point_reference.hpp), in the batched path as in the one-point one.
// V: the vector of doubles of the batched update (core/simd.hpp), the native one but in the
// tests, which run every width on any machine (tests/unit/solver/lane_widths.cpp).

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include <rkpm/concepts/geometry.hpp>
#include <rkpm/concepts/material.hpp>
#include <rkpm/core/block_matrix.hpp>
#include <rkpm/core/error.hpp>
#include <rkpm/core/hot_inline.hpp>
#include <rkpm/io/checkpoint.hpp>
#include <rkpm/material/j2_batch.hpp>
#include <rkpm/solver/body_materials.hpp>
#include <rkpm/solver/discrete_model.hpp>
#include <rkpm/solver/point_force_terms.hpp>
#include <rkpm/solver/point_failures.hpp>
#include <rkpm/solver/point_forces.hpp>
#include <rkpm/solver/point_reference.hpp>

namespace rkpm {

template <Geometry G, Material M, class V = simd_double>
class point_materials {
 public:
  using state_type = typename M::state_type;
  // The optional protocols of concepts/material.hpp: no F stored per point when the state keeps
  // it, no stress when the material recomputes it, lanes_of<V> points at a time where it can.
  static constexpr bool state_records_F = RecordsDeformation<state_type>;
  static constexpr bool stress_recomputed = RecomputesStress<M>;
  static constexpr bool batched = UpdatesInLanes<M, basic_block_lanes<V>> && state_records_F && stress_recomputed;

  point_materials() = default;
  point_materials(const discrete_model& m, const materials_by_body<M>& material)
      : state_(m.point_count(), material.of_body(0).initial_state()),
        tau_(stress_recomputed ? 0 : m.point_count(), block_matrix::of(mat3::Zero())),
        F_(state_records_F ? 0 : m.point_count()),
        tile_(m.traversal.tiles()),
        work_terms_(m.own.group ? m.point_count() : 0, 0.0),
        whole_points_(m.whole_point_count()) {
    if (material.count() > 1)
      for (index_t q = 0; q < m.point_count(); ++q) state_[q] = material.at_point(q).initial_state();
    support_inverse_ = m.mean_support().cwiseInverse();
  }

  // f_int at coefficients d; advances the material states to the new F. A material with a
  // batched update (material/j2_batch.hpp) takes lanes_of<V> points at a time, with the same bits.
  void internal_force(const discrete_model& m, const materials_by_body<M>& material, const std::vector<vec2>& d,
                      std::vector<vec2>& f_int, step_context where);

  // On one rank of several (discrete_model::is_part): the plastic work and the smallest stretch
  // over every rank's points. internal_force() leaves this rank's; this combines them, the
  // work summed per point owner in one process's order (process_group::sum_points).
  // Collective: every rank calls it after internal_force(). Nothing to do on one process.
  void combine(const discrete_model& m) {
    process_group* group = m.own.group;
    if (!group) return;
    const std::vector<stored_index>& owned = group->owned_points();
    if (static_cast<index_t>(work_terms_.size()) != m.point_count())
      fail("point materials: made for a model of one process, combined on a rank's part; make them on the part");
    point_terms_.resize(owned.size());
    // Each term as one process's tile sums it, recorded by the force loop (add_plastic_work).
    for (std::size_t k = 0; k < owned.size(); ++k) point_terms_[k] = work_terms_[owned[k]];
    plastic_work_ = group->sum_points(point_terms_);
    min_stretch_ = group->min(min_stretch_);
  }

  // Smallest support stretch over the points at the last evaluation (1 at F = I).
  double min_stretch() const { return min_stretch_; }
  // Plastic work of the body, sum_q w_q (plastic work per reference volume)_q.
  double plastic_work() const { return plastic_work_; }
  double initial_volume_per_weight(index_t q) const {  // V_0 / w_q (solver/point_reference.hpp)
    return reference_.active() ? reference_.initial_volume_per_weight(q) : 1.0;
  }
  const std::vector<state_type>& states() const { return state_; }
  // Whether explicit_solver::grow_cracks must read the states again (a pass over every point's,
  // a tenth of a step): a point has failed since its last look (the force loop counts them), or
  // that look left a failed point's cell uncut; scanned() records a look.
  bool failures_to_scan() const { return failed_points_ != scanned_failed_points_ || scan_left_uncut_; }
  void scanned(bool left_uncut) {
    scanned_failed_points_ = failed_points_;
    scan_left_uncut_ = left_uncut;
  }
  // f(q, state) on every point's state, between steps (explicit_solver::set_point_temperatures).
  template <class F>
  void update_states(F&& f) {
    for (index_t q = 0; q < static_cast<index_t>(state_.size()); ++q) f(q, state_[q]);
  }
  // F, det F and tau at point q at the last evaluation (tau from the material, given `material`,
  // when it can recompute it).
  mat3 deformation_gradient(index_t q) const { return deformation_block(q).full(); }
  double det_F(index_t q) const { return deformation_block(q).determinant(); }
  mat3 kirchhoff_stress(const materials_by_body<M>& material, index_t q) const {
    if constexpr (stress_recomputed) return material.at_point(q).current_kirchhoff_stress(deformation_gradient(q), state_[q]);
    else return tau_[q].full();
  }
  // F relative to the current reference at every point, as the time-step controller reads it
  // (q -> mat3): the total F until the first re-reference.
  auto deformation_gradients() const {
    return [this](index_t q) { return relative_deformation_gradient(q); };
  }
  mat3 relative_deformation_gradient(index_t q) const {
    return reference_.active() ? reference_.relative(q, deformation_block(q)).full() : deformation_gradient(q);
  }
  // The largest principal stretch of F_rel, or of its inverse, over the points (the distortion of
  // the kernels since the last reference, docs/method.md (81)), in point order.
  double max_distortion(const discrete_model& m) const {
    double largest = 1.0;
    for (index_t q = 0; q < m.point_count(); ++q)
      largest = std::max(largest, distortion(relative_deformation_gradient(q).template topLeftCorner<2, 2>()));
    return largest;
  }
  const point_reference& reference() const { return reference_; }

  // The current configuration becomes the points' reference: `next` is the model built on it, whose
  // point q is the same material point as `m`'s (the same cell and rule point). The states stay;
  // F_r takes each point's total F, the weights their ratio (solver/point_reference.hpp).
  void rereference(const discrete_model& m, const discrete_model& next) {
    if (next.point_count() != m.point_count())
      fail("re-referencing: the rebuilt model has {} quadrature points where the old one had {}; the cells "
           "and the rule must stay the same",
           next.point_count(), m.point_count());
    // The total F read from the states (or F_), not from reference_, which advance() rewrites.
    reference_.advance(m.point_count(), [&](index_t q) { return deformation_block(q); }, m.points.weight,
                       next.points.weight);
    bind(next);
  }
  // What the points read of their model besides the states: its tiles and mean support.
  void bind(const discrete_model& m) {
    tile_.assign(m.traversal.tiles(), tile_summary{});
    support_inverse_ = m.mean_support().cwiseInverse();
    whole_points_ = m.whole_point_count();
    work_terms_.assign(m.own.group ? m.point_count() : 0, 0.0);
  }

  // Checkpoint (io/checkpoint.hpp): the states and what the last force evaluation left.
  void save(io::checkpoint_writer& w) const { sections(w, *this); }
  void load(io::checkpoint_reader& r) { sections(r, *this); }

 private:
  using failure = point_failure;
  using tile_summary = point_tile_summary;

  // F_q = I + H_q in-plane, F33 from the geometry.
  static mat3 deformation_gradient_at(const discrete_model& m, index_t q, const point_gradient& g) {
    mat3 F = mat3::Identity();
    F.topLeftCorner<2, 2>() += g.H;
    F(2, 2) = G::out_of_plane_stretch(g.u, m.points.position[q]);
    return F;
  }

  // After a re-reference: S_q and h_q from F_rel and the stress per unit current reference volume,
  // tau / det F_r (80); the plastic work per unit initial volume with the point's initial volume.
  void point_force_rereferenced(const discrete_model& m, tile_summary& tile, index_t q, const mat3& F_rel,
                                const mat3& tau, mat2& S, double& hoop) {
    const mat2 Fi = point_forces_of<G>(F_rel, tau / reference_.volume_change(q), m.points.weight[q],
                                       m.points.position[q][0], S, hoop);
    tile.narrowest = std::min(tile.narrowest, std::min(support_stretch(Fi, support_inverse_), F_rel(2, 2)));
    add_plastic_work(tile, q, state_[q].plastic_work * m.points.weight[q] * reference_.initial_volume_per_weight(q));
  }

  // S_q and h_q from F_q and tau_q (solver/point_force_terms.hpp), and what the point adds to its
  // tile's summary.
  RKPM_HOT_INLINE void point_force(const discrete_model& m, tile_summary& tile, index_t q, const mat3& F,
                                   const mat3& tau, mat2& S, double& hoop) {
    const mat2 Fi = point_forces_of<G>(F, tau, m.points.weight[q], m.points.position[q][0], S, hoop);
    tile.narrowest = std::min(tile.narrowest, std::min(support_stretch(Fi, support_inverse_), F(2, 2)));
    add_plastic_work(tile, q, state_[q].plastic_work * m.points.weight[q]);
  }
  // Point q's plastic work into its tile's sum and, on a rank's part, its own term for combine()
  // (a pass over the states there cost about 3% of a step).
  RKPM_HOT_INLINE void add_plastic_work(tile_summary& tile, index_t q, double term) {
    tile.plastic += term;
    if (!work_terms_.empty()) work_terms_[q] = term;
  }

  // The batched update of points q0 .. q0 + lanes_of<V> - 1 (material/j2_batch.hpp). False, with
  // nothing changed, where the point-by-point update must decide: a lane with det F <= 0 or
  // not finite, lanes of bodies with different materials, a material that updates its points one
  // by one (updates_in_lanes), or a return that failed; the caller
  // then updates the points one by one, which reports the first failure as always.
  bool batch_update(const discrete_model& m, const materials_by_body<M>& material, index_t t, index_t q0,
                    const point_gradient* g, mat2* S, double* hoop, step_context where);

  const block_matrix& deformation_block(index_t q) const {
    if constexpr (state_records_F) return state_[q].previous_deformation;
    else return F_[q];
  }

  template <class Archive, class Self>
  static void sections(Archive& a, Self& s) {
    static_assert(bitwise_value<state_type>,
                  "checkpoints write material states as raw bytes: make the state an aggregate of at most 8 "
                  "doubles, integers or fixed-size Eigen matrices (core/bitwise.hpp)");
    a.array("points.state", s.state_);
    if constexpr (!stress_recomputed) a.array("points.tau", s.tau_);
    if constexpr (!state_records_F) a.array("points.F", s.F_);
    a.value("points.min_stretch", s.min_stretch_);
    a.value("points.plastic_work", s.plastic_work_);
    if constexpr (std::is_const_v<Self>) s.reference_.save(a, s.whole_points_);
    else s.reference_.load(a, static_cast<index_t>(s.state_.size()));
  }

  [[noreturn]] void report_failure(const discrete_model& m, const tile_summary& tile, step_context where) {
    std::string message;
    std::swap(message, error_);
    report_point_failure(m, tile, where, message);
  }

  std::vector<state_type> state_;
  std::vector<block_matrix> tau_, F_;  // empty when the material recomputes tau / the state records F
  std::vector<tile_summary> tile_;     // per tile of the traversal
  std::vector<double> point_terms_;    // on several ranks: the owned points' plastic work
  std::vector<double> work_terms_;     // on several ranks: each point's, from the force loop
  std::string error_;                  // the first material error's message (of point error_point_)
  index_t error_point_ = 0;
  point_reference reference_;           // empty until the first re-reference
  index_t whole_points_ = 0;            // the whole model's points (a rank's part: not its own)
  vec2 support_inverse_ = vec2::Ones();  // 1 / mean support per direction
  double min_stretch_ = 1.0, plastic_work_ = 0.0;
  index_t failed_points_ = 0, scanned_failed_points_ = -1;  // at the last evaluation, at the last look
  bool scan_left_uncut_ = false;
};

}  // namespace rkpm

// The force loop and its batched update, out of the class.
#include <rkpm/solver/point_force_loop.hpp>
