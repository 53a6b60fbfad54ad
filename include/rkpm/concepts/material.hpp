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
// balance. That is all a Material must offer.
// Optional protocols, each a named concept below that the solver checks: RecomputesStress (no
// stress stored per point), RecordsDeformation (no F stored per point), UpdatesWithStepLog (ln dt
// taken once per step), UpdatesInLanes (several points at once), FailingState, BreakingState,
// TemperatureState and ListsOutputFields (what a state may say of its point), OpensCracks.
//
// Hardening: the flow stress sigma_y in Pa and its slope d sigma_y / d eps_p, for J2 return
// mappings, either of eps_p alone (`flow_stress(e)`, `slope(e)`: linear, power, Voce) or of eps_p
// and the flow_point (plastic strain rate, temperature: `flow_stress(e, at)`, `slope(e, at)`,
// and optionally `rate_slope(e, at)` = d sigma_y / d rate). Call either through flow_stress_at,
// slope_at and rate_slope_at (docs/method.md section 4.3). The faster paths a law may offer the
// return mapping (material/radial_return.hpp) are named concepts too: SlopeFromFlow,
// SlopesFromFlow, HardensAlongStep.

#include <concepts>
#include <limits>
#include <string_view>
#include <utility>

#include <rkpm/core/block_matrix.hpp>
#include <rkpm/core/hot_inline.hpp>
#include <rkpm/core/types.hpp>

namespace rkpm {

// What a material update knows of its step besides F.
struct material_step {
  double dt = 0.0;    // s, the step (0: an evaluation at the start, no time has passed)
  double time = 0.0;  // s, at the end of the step
  // K; NaN when the problem has no temperature (the state carries none).
  double temperature = std::numeric_limits<double>::quiet_NaN();
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

// Optional: `current_kirchhoff_stress(F, s)` (const, s const), the stress the last update
// returned, recomputed from its F and the state it left; the solver then stores no stress per
// point (solver/point_materials.hpp). Offered by j2_plasticity, johnson_cook, zerilli_armstrong.
template <class M>
concept RecomputesStress = requires(const M& m, const mat3& F, const typename M::state_type& s) {
  { m.current_kirchhoff_stress(F, s) } -> std::same_as<mat3>;
};
// Optional: the state keeps the F of its last update as `previous_deformation`; the solver then
// stores no F per point. Offered by j2_state and johnson_cook_state.
template <class State>
concept RecordsDeformation = requires(const State& s) {
  { s.previous_deformation } -> std::convertible_to<block_matrix>;
};
// Optional: `kirchhoff_stress(F, s, step, log_dt)` with log_dt = ln step.dt (NaN when dt = 0),
// which the force loop takes once for every point of the step instead of the law once per
// yielding point; the same bits as without it. Offered by johnson_cook (its rate term).
template <class M>
concept UpdatesWithStepLog =
    requires(const M& m, typename M::state_type& s, const mat3& F, const material_step& t, double log_dt) {
      { m.kirchhoff_stress(F, s, t, log_dt) } -> std::same_as<mat3>;
    };

// Optional: a batched update of the points of one vector of lanes (Lanes =
// basic_block_lanes<V>, core/simd.hpp), `kirchhoff_stress_batch(m, F, s, step)` with s the
// lanes' states, and `updates_in_lanes(m)`, whether this material's points take it; both found
// by argument-dependent lookup. The force loop then updates lanes_of<V> points at a time, with
// the scalar update's bits. Offered by j2_plasticity (material/j2_batch.hpp), the case files' material.
template <class M, class Lanes>
concept UpdatesInLanes = requires(const M& m, const Lanes& F, typename M::state_type* s, const material_step& step) {
  { kirchhoff_stress_batch(m, F, s, step) } -> std::same_as<Lanes>;
  { updates_in_lanes(m) } -> std::same_as<bool>;
};

// The material update with its step, whichever form the law takes.
// Inlined (as the laws' own updates are) so that the force loop's call passes F and the stress
// in registers, not through memory.
template <class M>
RKPM_HOT_INLINE mat3 material_update(const M& m, const mat3& F, typename M::state_type& s, const material_step& step) {
  if constexpr (updates_with_step<M>) return m.kirchhoff_stress(F, s, step);
  else return m.kirchhoff_stress(F, s);
}
// The same with ln step.dt known (the force loop's), for a law that takes it.
template <class M>
RKPM_HOT_INLINE mat3 material_update(const M& m, const mat3& F, typename M::state_type& s, const material_step& step,
                                     double log_dt) {
  if constexpr (UpdatesWithStepLog<M>) return m.kirchhoff_stress(F, s, step, log_dt);
  else return material_update(m, F, s, step);
}

// Optional: a `failed()` state (the point carries no tension or no stress at all: johnson_cook's
// damage, rankine_fracture's crack); output counts the failed points.
template <class State>
concept FailingState = requires(const State& s) {
  { s.failed() } -> std::convertible_to<bool>;
};
// Optional: a state with a `temperature` (K), the point's: the solver passes it back in
// material_step::temperature and a heat coupling writes the conducted field into it
// (johnson_cook_state, the case files' state).
template <class State>
concept TemperatureState = requires(State& s) {
  { s.temperature } -> std::convertible_to<double>;
  s.temperature = 0.0;
};

// Optional: a FailingState whose failure is a crack, with its `crack_normal` in the current
// configuration (zero for a hoop crack); the solver then cuts the failed points' cells
// (solver/crack_growth.hpp). Offered by rankine_fracture's state and johnson_cook's.
template <class State>
concept BreakingState = FailingState<State> && requires(const State& s) {
  { s.crack_normal } -> std::convertible_to<vec2>;
};
// Optional: `opens_cracks()`, whether this material's failed points break (a law whose failure
// cuts cells only when asked, johnson_cook's damage with opens_cracks); without it every
// failed point of a BreakingState breaks. The solver looks for failed points only when one of
// its materials opens cracks (explicit_solver::cracks_can_grow).
template <class M>
concept OpensCracks = requires(const M& m) {
  { m.opens_cracks() } -> std::convertible_to<bool>;
};
// Optional: `static constexpr auto output_fields()`, pairs {name, &State::member} of extra
// per-point scalars that snapshots and summaries write (io/solver_output.hpp), e.g.
// {"temperature_K", &johnson_cook_state::temperature}.
template <class State>
concept ListsOutputFields = requires { State::output_fields(); };

// The point's temperature as its state records it, NaN when it records none.
template <class State>
double state_temperature(const State& s) {
  if constexpr (TemperatureState<State>) return s.temperature;
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
// Optional: `rate_slope(e, at)`, d sigma_y / d (plastic strain rate); the return mapping then
// iterates in ln dgamma (johnson_cook, zerilli_armstrong).
template <class H>
concept RateDependentHardening = requires(const H& h, double e, const flow_point& at) {
  { h.rate_slope(e, at) } -> std::convertible_to<double>;
};
// d sigma_y / d (plastic strain rate); 0 for a rate-independent law.
template <Hardening H>
double rate_slope_at(const H& h, double eps_p, const flow_point& at) {
  if constexpr (RateDependentHardening<H>) return h.rate_slope(eps_p, at);
  else return 0.0;
}

// Optional faster paths of a law for the return mapping (material/radial_return.hpp):
// SlopeFromFlow: `slope(e, flow)`, the slope at e from the flow stress there, known (power_law:
// no pow).
template <class H>
concept SlopeFromFlow = requires(const H& h, double e, double flow) {
  { h.slope(e, flow) } -> std::convertible_to<double>;
};
// SlopesFromFlow: `slopes_at_flow(e, at, flow)`, the strain and rate slopes from the flow stress
// (zerilli_armstrong, johnson_cook at one temperature).
template <class H>
concept SlopesFromFlow = requires(const H& h, double e, const flow_point& at, double flow) {
  { h.slopes_at_flow(e, at, flow) } -> std::convertible_to<std::pair<double, double>>;
};
// HardensAlongStep: `along_step(e_n, dt, flow_at_start, log_dt)`, the flow stress along one
// step's increments with its derivatives in ln dgamma (johnson_cook at one temperature).
template <class H>
concept HardensAlongStep = requires(const H& h, double e, double dt, double flow, double log_dt) {
  h.along_step(e, dt, flow, log_dt);
};

// The plastic work of an increment in closed form (plastic_work_increment, material/
// j2_plasticity.hpp): WorkIntegralFromFlow, `integral(e0, e1, flow0, flow1)` with the flow
// stresses at both ends known (power_law: no pow), or WorkIntegral, `integral(e0, e1)` (power_law,
// voce, linear); otherwise the trapezoidal rule.
template <class H>
concept WorkIntegralFromFlow = requires(const H& h, double e, double flow) {
  { h.integral(e, e, flow, flow) } -> std::convertible_to<double>;
};
template <class H>
concept WorkIntegral = requires(const H& h, double e) {
  { h.integral(e, e) } -> std::convertible_to<double>;
};
// BoundedBelow: `lowest_flow_stress()`, a lower bound of the law's flow stress over every state,
// by which J2 skips the return mapping of a point far inside the yield surface (power_law, voce).
template <class H>
concept BoundedBelow = requires(const H& h) {
  { h.lowest_flow_stress() } -> std::convertible_to<double>;
};

}  // namespace rkpm
