#pragma once
// The J2 update of j2_plasticity::kirchhoff_stress (j2_plasticity.hpp, docs/method.md section
// 4.4) for several points at once, one point per lane of a vector of doubles V (core/simd.hpp;
// the force loop's simd_double, or simd_of<N> in the tests): the force loop's batched path
// (solver/point_materials.hpp). The elastic predictor, the principal frame, the Hencky stress
// and the exponential map of the return are the point update's own formulas (basic_j2_trial,
// hencky.hpp), instantiated for V instead of double: what differs from lane to lane stays
// scalar inside them (the logs, the exps) or here (the yield check and the radial return,
// j2_plasticity::plastic_flow_of: a Newton iteration of its own length per lane). So each lane
// gets the bits the scalar update gives its point, at any width (tests/unit/material/j2_batch.cpp
// checks 2, 4 and 8 lanes and the native width).

#include <array>

#include <rkpm/concepts/material.hpp>
#include <rkpm/core/block_matrix.hpp>
#include <rkpm/core/simd.hpp>
#include <rkpm/material/j2_plasticity.hpp>

namespace rkpm::material {

// Advances the lanes_of<V> states s[0], s[1], ... from their previous_deformation to the lanes
// of F and returns their Kirchhoff stresses, as j2_plasticity::kirchhoff_stress does point by
// point; the step's temperature is each state's (state_temperature). A lane's F must be a valid
// deformation gradient (finite, det F > 0): the caller checks, and takes the scalar update for a
// batch with a lane that is not. A radial return that fails throws before any state is written.
template <Hardening H, class State, class V>
basic_block_lanes<V> kirchhoff_stress_batch(const j2_plasticity<H>& m, const basic_block_lanes<V>& F, State* s,
                                            const material_step& step) {
  constexpr int lanes = lanes_of<V>;
  const double mu = m.shear_modulus();
  basic_j2_trial<V> t = basic_j2_trial<V>::of(
      F, gather_block<V>([&](int k) -> const block_matrix& { return s[k].elastic_left_cauchy_green; }),
      gather_block<V>([&](int k) -> const block_matrix& { return s[k].previous_deformation; }), mu);

  // The yield check and the return, lane by lane (j2_plasticity::plastic_flow_of).
  std::array<double, lanes> dgamma{}, work{};
  typename V::mask_type yields(false);
  for (int k = 0; k < lanes; ++k) {
    const material_step at{step.dt, step.time, state_temperature(s[k])};
    const auto flow = m.plastic_flow_of(t.q[k], s[k].equivalent_plastic_strain, at);
    yields[k] = flow.yields;
    dgamma[k] = flow.increment;
    work[k] = flow.work;
  }

  // The exponential map where a lane yields, the trial b_e elsewhere.
  const basic_block_lanes<V> b_e =
      stdx::any_of(yields) ? t.return_by(V(dgamma.data(), stdx::element_aligned), 3.0 * mu, yields) : t.b;
  for (int k = 0; k < lanes; ++k) {
    s[k].elastic_left_cauchy_green = lane_of(b_e, k);
    if (yields[k]) {
      s[k].plastic_work += work[k];
      s[k].equivalent_plastic_strain += dgamma[k];
    }
    s[k].previous_deformation = lane_of(F, k);
  }
  return hencky_stress_block(t.frame, t.volumetric, t.dev, m.bulk_modulus(), mu);
}

// J2 always updates its points in lanes (a material that wraps several laws says per body).
template <Hardening H>
constexpr bool updates_in_lanes(const j2_plasticity<H>&) {
  return true;
}

}  // namespace rkpm::material
