#pragma once
// The J2 update of j2_plasticity::kirchhoff_stress (j2_plasticity.hpp, docs/method.md section
// 4.4) for several points at once, one point per lane of a vector of doubles V (core/simd.hpp;
// the force loop's simd_double, or simd_of<N> in the tests): the force loop's batched path
// (solver/point_materials.hpp). The elastic predictor, the principal
// frame, the Hencky stress and the exponential map of the return are vector arithmetic over the
// lanes; what differs from lane to lane stays scalar: the logs (the C library's, lane by lane),
// the exps (Eigen's array exp of each yielding lane, as the scalar update takes them) and the
// yield check and radial return (j2_plasticity::plastic_flow_of: a Newton iteration of its own
// length per lane). Every formula is the scalar one in the same order, so each lane gets the bits
// the scalar update gives its point, at any width (tests/unit/material/j2_batch.cpp checks 2, 4
// and 8 lanes and the native width); only a build
// whose vector and scalar code round multiply-adds differently (FMA units under -march=native)
// can differ, by rounding.

#include <array>
#include <cmath>

#include <rkpm/concepts/material.hpp>
#include <rkpm/core/block_matrix.hpp>
#include <rkpm/core/simd.hpp>
#include <rkpm/material/j2_plasticity.hpp>

namespace rkpm::material {

namespace detail {

// principal_frame (hencky.hpp) over the lanes: the in-plane eigenvalues and the frame's double
// angle, and sum v_i n_i n_i^T back from it.
template <class V>
struct frame_lanes {
  V larger, smaller, out_of_plane, cos2 = 1.0, sin2 = 0.0;

  static frame_lanes of(const basic_block_lanes<V>& a) {
    const V a12 = 0.5 * (a.xy + a.yx);
    const V mean = 0.5 * (a.xx + a.yy);
    const V half_diff = 0.5 * (a.xx - a.yy);
    const V radius = stdx::sqrt(half_diff * half_diff + a12 * a12);
    frame_lanes frame;
    frame.larger = mean + radius;
    frame.smaller = (a.xx * a.yy - a12 * a12) / frame.larger;
    frame.out_of_plane = a.zz;
    const typename V::mask_type turned = radius > 0.0;
    stdx::where(turned, frame.cos2) = half_diff / radius;
    stdx::where(turned, frame.sin2) = a12 / radius;
    return frame;
  }

  basic_block_lanes<V> assemble(const std::array<V, 3>& v) const {
    const V mean = 0.5 * (v[0] + v[1]);
    const V half_diff = 0.5 * (v[0] - v[1]);
    return {mean + half_diff * cos2, half_diff * sin2, half_diff * sin2, mean - half_diff * cos2, v[2]};
  }
};

}  // namespace detail

// Advances the lanes_of<V> states s[0], s[1], ... from their previous_deformation to the lanes
// of F and returns their Kirchhoff stresses, as j2_plasticity::kirchhoff_stress does point by
// point; the step's temperature is each state's (state_temperature). A lane's F must be a valid
// deformation gradient (finite, det F > 0): the caller checks, and takes the scalar update for a
// batch with a lane that is not. A radial return that fails throws before any state is written.
template <Hardening H, class State, class V>
basic_block_lanes<V> kirchhoff_stress_batch(const j2_plasticity<H>& m, const basic_block_lanes<V>& F, State* s,
                                            const material_step& step) {
  constexpr int lanes = lanes_of<V>;
  const double mu = m.shear_modulus(), three_mu = 3.0 * mu;
  // The elastic predictor (j2_trial::of).
  const basic_block_lanes<V> F_n = gather_block<V>([&](int k) -> const block_matrix& { return s[k].previous_deformation; });
  const basic_block_lanes<V> b_n = gather_block<V>([&](int k) -> const block_matrix& { return s[k].elastic_left_cauchy_green; });
  const basic_block_lanes<V> f = F * inverse(F_n);
  const basic_block_lanes<V> b_trial = f * b_n * f.transpose();
  const auto frame = detail::frame_lanes<V>::of(b_trial);
  const auto log_strain = [](const V& v) { return lanewise(v, [](double x) { return 0.5 * std::log(x); }); };
  const std::array<V, 3> eps{log_strain(frame.larger), log_strain(frame.smaller), log_strain(frame.out_of_plane)};
  const V volumetric = eps[0] + eps[1] + eps[2];
  const V third = volumetric / 3.0;
  std::array<V, 3> dev{eps[0] - third, eps[1] - third, eps[2] - third};
  const V q = std::sqrt(1.5) * 2.0 * mu * stdx::sqrt(dev[0] * dev[0] + dev[1] * dev[1] + dev[2] * dev[2]);

  // The yield check and the return, lane by lane (j2_plasticity::plastic_flow_of).
  std::array<double, lanes> dgamma{}, work{};
  typename V::mask_type yields(false);
  for (int k = 0; k < lanes; ++k) {
    const material_step at{step.dt, step.time, state_temperature(s[k])};
    const auto flow = m.plastic_flow_of(q[k], s[k].equivalent_plastic_strain, at);
    yields[k] = flow.yields;
    dgamma[k] = flow.increment;
    work[k] = flow.work;
  }

  // The exponential map (j2_trial::return_by) where a lane yields, the trial b_e elsewhere.
  basic_block_lanes<V> b_e = b_trial;
  if (stdx::any_of(yields)) {
    const V scale = 1.0 - three_mu * V(dgamma.data(), stdx::element_aligned) / q;
    for (V& d : dev) stdx::where(yields, d) = d * scale;
    // exp(2 eps_e) as j2_trial::return_by takes it, by Eigen's array exp of the lane's three
    // strains (a packet exp of its own, whose bits std::exp need not share).
    std::array<V, 3> stretch{V(1.0), V(1.0), V(1.0)};
    for (int k = 0; k < lanes; ++k) {
      if (!yields[k]) continue;
      const vec3 eps_e = vec3(dev[0][k], dev[1][k], dev[2][k]) + vec3::Constant(third[k]);
      const vec3 squared = (2.0 * eps_e).array().exp().matrix();
      for (int i = 0; i < 3; ++i) stretch[i][k] = squared(i);
    }
    const basic_block_lanes<V> returned = frame.assemble(stretch);
    stdx::where(yields, b_e.xx) = returned.xx;
    stdx::where(yields, b_e.xy) = returned.xy;
    stdx::where(yields, b_e.yx) = returned.yx;
    stdx::where(yields, b_e.yy) = returned.yy;
    stdx::where(yields, b_e.zz) = returned.zz;
  }
  for (int k = 0; k < lanes; ++k) {
    s[k].elastic_left_cauchy_green = lane_of(b_e, k);
    if (yields[k]) {
      s[k].plastic_work += work[k];
      s[k].equivalent_plastic_strain += dgamma[k];
    }
    s[k].previous_deformation = lane_of(F, k);
  }
  // tau = K tr(eps_e) 1 + 2 mu dev(eps_e) in the principal frame of b_e (hencky_stress).
  const V mean_stress = m.bulk_modulus() * volumetric;
  const double two_mu = 2.0 * mu;
  return frame.assemble({mean_stress + two_mu * dev[0], mean_stress + two_mu * dev[1], mean_stress + two_mu * dev[2]});
}

// J2 always updates its points in lanes (a material that wraps several laws says per body).
template <Hardening H>
constexpr bool updates_in_lanes(const j2_plasticity<H>&) {
  return true;
}

}  // namespace rkpm::material
