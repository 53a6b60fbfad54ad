#pragma once
// Material and Hardening: what the explicit solver calls at every quadrature point
// (docs/method.md section 4).
//
// Material: `kirchhoff_stress(F, s, step)` takes the current total deformation gradient F (3x3,
// with the 2D block structure [[F11, F12, 0], [F21, F22, 0], [0, 0, F33]], F33 = 1 in plane
// strain and the hoop stretch in axisymmetric geometry) and what it may need of the step
// (material_step: dt, time, the point's temperature), advances the internal state s from the
// last accepted F to this one and returns the Kirchhoff stress tau = J sigma with the same block
// structure. A law that needs nothing of the step may take `kirchhoff_stress(F, s)` instead
// (call either through material_update). The state exposes the equivalent plastic strain and
// the cumulative plastic work per unit REFERENCE volume (J/m^3) for output and the energy
// balance; a state with a `temperature` member (K) is the point's temperature, which the solver
// passes back in material_step::temperature.
// Optional: `current_kirchhoff_stress(F, s)` (const, s const), the stress the last
// kirchhoff_stress(F, s) returned, recomputed from its F and the state it left; with it the
// solver stores no stress per point (solver/point_materials.hpp).
//
// Hardening: the flow stress sigma_y in Pa and its slope d sigma_y / d eps_p, for J2 return
// mappings, either of eps_p alone (`flow_stress(e)`, `slope(e)`: linear, power, Voce) or of eps_p
// and the flow_point (plastic strain rate, temperature: `flow_stress(e, at)`, `slope(e, at)`,
// and optionally `rate_slope(e, at)` = d sigma_y / d rate). Call either through flow_stress_at,
// slope_at and rate_slope_at (docs/method.md section 4.3).

#include <concepts>
#include <limits>
#include <string_view>

#include <rkpm/core/hot_inline.hpp>
#include <rkpm/core/types.hpp>

namespace rkpm {

// What a material update knows of its step besides F.
struct material_step {
  double dt = 0.0;    // s, the step (0: an evaluation at the start, no time has passed)
  double time = 0.0;  // s, at the end of the step
  // K; NaN when the problem has no temperature (the state carries none).
  double temperature = std::numeric_limits<double>::quiet_NaN();
  // ln dt when the caller takes it once for every point of the step (the solver); NaN: a law
  // that needs it takes it itself. The same value either way.
  double log_dt = std::numeric_limits<double>::quiet_NaN();
};

// Where on its curve a hardening law is asked for its flow stress, besides eps_p.
struct flow_point {
  double plastic_strain_rate = 0.0;  // 1/s, d eps_p / dt over the step (0 when dt = 0)
  double temperature = std::numeric_limits<double>::quiet_NaN();  // K, as material_step
};

template <class M>
concept updates_with_step = requires(const M& m, typename M::state_type& s, const mat3& F, const material_step& t) {
  { m.kirchhoff_stress(F, s, t) } -> std::same_as<mat3>;
};
template <class M>
concept updates_without_step = requires(const M& m, typename M::state_type& s, const mat3& F) {
  { m.kirchhoff_stress(F, s) } -> std::same_as<mat3>;
};

template <class M>
concept Material = requires(const M& m, typename M::state_type& s, const mat3& F) {
  { M::name } -> std::convertible_to<std::string_view>;
  { m.initial_state() } -> std::same_as<typename M::state_type>;
  requires updates_with_step<M> || updates_without_step<M>;
  { m.density() } -> std::same_as<double>;
  { m.dilatational_wave_speed() } -> std::same_as<double>;
  // The small-strain elastic constants (material/elastic_constants.hpp) the stable step is
  // estimated with; required by shape so that this header does not depend on a material.
  { m.constants().lame_lambda() } -> std::convertible_to<double>;
  { m.constants().shear_modulus() } -> std::convertible_to<double>;
  m.constants().validate();
  { s.equivalent_plastic_strain } -> std::convertible_to<double>;
  { s.plastic_work } -> std::convertible_to<double>;
};

// The material update with its step, whichever form the law takes.
// Inlined (as the laws' own updates are) so that the force loop's call passes F and the stress
// in registers, not through memory.
template <class M>
RKPM_HOT_INLINE mat3 material_update(const M& m, const mat3& F, typename M::state_type& s, const material_step& step) {
  if constexpr (updates_with_step<M>) return m.kirchhoff_stress(F, s, step);
  else return m.kirchhoff_stress(F, s);
}

// The point's temperature as its state records it, NaN when it records none.
template <class State>
double state_temperature(const State& s) {
  if constexpr (requires { { s.temperature } -> std::convertible_to<double>; }) return s.temperature;
  else return std::numeric_limits<double>::quiet_NaN();
}

template <class H>
concept hardens_with_state = requires(const H& h, double e, const flow_point& at) {
  { h.flow_stress(e, at) } -> std::same_as<double>;
  { h.slope(e, at) } -> std::same_as<double>;
};
template <class H>
concept hardens_with_strain = requires(const H& h, double e) {
  { h.flow_stress(e) } -> std::same_as<double>;
  { h.slope(e) } -> std::same_as<double>;
};

template <class H>
concept Hardening = requires {
  { H::name } -> std::convertible_to<std::string_view>;
  requires hardens_with_state<H> || hardens_with_strain<H>;
};

template <Hardening H>
double flow_stress_at(const H& h, double eps_p, const flow_point& at) {
  if constexpr (hardens_with_state<H>) return h.flow_stress(eps_p, at);
  else return h.flow_stress(eps_p);
}
template <Hardening H>
double slope_at(const H& h, double eps_p, const flow_point& at) {
  if constexpr (hardens_with_state<H>) return h.slope(eps_p, at);
  else return h.slope(eps_p);
}
// d sigma_y / d (plastic strain rate); 0 for a rate-independent law.
template <Hardening H>
double rate_slope_at(const H& h, double eps_p, const flow_point& at) {
  if constexpr (requires { { h.rate_slope(eps_p, at) } -> std::convertible_to<double>; }) return h.rate_slope(eps_p, at);
  else return 0.0;
}

}  // namespace rkpm
