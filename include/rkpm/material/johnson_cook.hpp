#pragma once
// Johnson-Cook plasticity with adiabatic heating and Johnson-Cook damage (docs/method.md
// section 4.5): the finite-strain J2 model of j2_plasticity.hpp (its elastic predictor and
// radial return, j2_trial; the return mapping of radial_return.hpp) with the flow stress (24b)
// of hardening::johnson_cook, evaluated at the point's temperature and at the rate dgamma / dt
// its increment implies, and per point:
//   - the temperature: rho0 c_p dT = beta dW_p (32a), dW_p = sigma_y deps_p the plastic work
//     per unit reference volume of the step (32) at the step's rate and temperature, beta the
//     Taylor-Quinney fraction. The flow stress of a step uses the temperature at its start
//     (explicit in T: the heat of a step softens the next one);
//   - melt: at T >= T_melt the flow stress is 0, so the whole trial deviator returns (dgamma =
//     q_trial / (3 mu)) and the point carries pressure only;
//   - damage (optional): D += dgamma / eps_f (32b) with the failure strain
//       eps_f = (D1 + D2 exp(D3 sigma*)) (1 + D4 ln max(rate*, 1)) (1 + D5 T*)          (32c)
//     and sigma* = (tr tau / 3) / q, the mean stress over the von Mises stress at the end of the
//     step: POSITIVE IN TENSION (1/3 in uniaxial tension, -1/3 in uniaxial compression), as
//     Johnson & Cook (Eng. Fract. Mech. 21 (1985) 31-48) define it, so that D3 < 0 makes
//     tension the more damaging. A point with D >= 1 has failed: from then on it carries no
//     deviatoric stress and no tension, tau = K theta 1 when theta = ln J < 0 and 0 otherwise
//     (32d). eps_f <= 0 (possible with D1 < 0) fails the point at its next plastic step.
//     With johnson_cook_damage::opens_cracks, a point that fails with its largest principal
//     stress tensile records that principal direction as its crack normal (32f), and the solver
//     cuts its cell (solver/crack_growth.hpp); one that fails in compression or shear records
//     none and cuts nothing.
// The temperature is the state's (the solver passes it back as material_step::temperature);
// the state starts at the initial temperature. The heat is part of the plastic work that the
// energy ledger already counts (no new balance term); failure removes stress, which the ledger's
// internal work (the trapezoidal work of f_int, section 7) follows with no term of its own.

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string_view>
#include <utility>

#include <rkpm/concepts/material.hpp>
#include <rkpm/core/block_matrix.hpp>
#include <rkpm/core/error.hpp>
#include <rkpm/core/hot_inline.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/material/elastic_constants.hpp>
#include <rkpm/material/hardening/johnson_cook.hpp>
#include <rkpm/material/hencky.hpp>
#include <rkpm/material/j2_plasticity.hpp>
#include <rkpm/material/radial_return.hpp>

namespace rkpm::material {

// j2_state's members (b_e, F_n, eps_p, W_p) and the point's temperature and damage, then three
// speed caches and the crack normal. The caches are checkpointed with the rest (points.state
// holds the state's bytes) because none follows from eps_p and T to the bit: T*^m is carried by
// a series, the flow stress at rest is the return mapping's strain factor times 1 - T*^m, and
// ln dgamma is where the next Newton iteration starts, which moves its root within the
// tolerance. Recomputed at a restart, they would change every later plastic step of the run it
// continues.
struct johnson_cook_state {
  block_matrix elastic_left_cauchy_green;  // b_e
  block_matrix previous_deformation;       // F of the last accepted step
  double equivalent_plastic_strain = 0.0;
  double plastic_work = 0.0;                                       // J/m^3 of reference volume
  double temperature = std::numeric_limits<double>::quiet_NaN();   // K (NaN: none, a J2 point of a case file)
  double damage = 0.0;                                             // D, >= 1 failed
  // sigma_y(eps_p, T) at the reference rate, (A + B eps_p^n)(1 - T*^m): the yield check of the
  // next step, kept so that a step that stays elastic costs no pow (a Johnson-Cook point only).
  double flow_stress_at_rest = std::numeric_limits<double>::quiet_NaN();
  // ln dgamma of the last step that yielded (-inf before any): where the next return mapping starts.
  double log_last_increment = -std::numeric_limits<double>::infinity();
  // T*^m at T (hardening::johnson_cook::homologous_power), carried from step to step by a short
  // series instead of a pow (homologous_power_after).
  double homologous_power = 0.0;
  // Unit normal of the crack in the current configuration, (32f): the direction of the largest
  // principal stress at the update where the point failed, when that stress was tensile, in
  // plane, and the damage opens cracks; zero otherwise.
  packed_vec2 crack_normal;

  bool failed() const { return damage >= 1.0; }
  // The snapshot fields (io/solver_output.hpp).
  static constexpr auto output_fields() {
    return std::array{std::pair{std::string_view("temperature_K"), &johnson_cook_state::temperature},
                      std::pair{std::string_view("damage"), &johnson_cook_state::damage}};
  }
};

// Adiabatic heating (32a).
struct johnson_cook_heating {
  double specific_heat;                                              // c_p in J/(kg K)
  double taylor_quinney = 0.9;                                       // beta in [0, 1]
  double initial_temperature = std::numeric_limits<double>::quiet_NaN();  // K; NaN: the room temperature
};

// The failure strain (32c), and whether a failed point opens a crack (32f).
struct johnson_cook_damage {
  double D1, D2, D3, D4, D5;
  bool opens_cracks = false;

  // eps_f at the triaxiality sigma* (positive in tension), the rate factor's ln max(rate*, 1) and T*.
  double failure_strain(double triaxiality, double log_rate, double homologous) const {
    return (D1 + D2 * std::exp(D3 * triaxiality)) * (1.0 + D4 * log_rate) * (1.0 + D5 * homologous);
  }
};

class johnson_cook {
 public:
  static constexpr std::string_view name = "johnson_cook";
  using flow_type = hardening::johnson_cook;
  using state_type = johnson_cook_state;

  // newton_tolerance: |r| <= tolerance q_trial as in j2_plasticity (q_trial >= sigma_y at the
  // root, and exceeds it by 3 mu dgamma, a small fraction of sigma_y in an explicit step).
  johnson_cook(elastic_constants constants, flow_type flow, johnson_cook_heating heating,
               std::optional<johnson_cook_damage> damage = std::nullopt, double newton_tolerance = 1e-12,
               int max_newton_iterations = 50)
      : constants_(constants),
        flow_(flow),
        heating_(heating),
        damage_(damage),
        tolerance_(newton_tolerance),
        max_iterations_(max_newton_iterations) {
    constants_.validate();
    flow_.validate();
    if (!(std::isfinite(heating_.specific_heat) && heating_.specific_heat > 0.0))
      fail("material::johnson_cook: specific_heat = {} J/(kg K) is invalid: give a finite value > 0 (copper: 383)",
           heating_.specific_heat);
    if (!(heating_.taylor_quinney >= 0.0 && heating_.taylor_quinney <= 1.0))
      fail("material::johnson_cook: taylor_quinney = {} is invalid: give a fraction in [0, 1] (usually 0.9)",
           heating_.taylor_quinney);
    if (std::isnan(heating_.initial_temperature)) heating_.initial_temperature = flow_.room_temperature;
    if (!(std::isfinite(heating_.initial_temperature) && heating_.initial_temperature > 0.0))
      fail("material::johnson_cook: initial_temperature = {} K is invalid: give a finite value > 0 (e.g. 294)",
           heating_.initial_temperature);
    if (damage_) {
      const johnson_cook_damage& d = *damage_;
      if (!(std::isfinite(d.D1) && std::isfinite(d.D2) && std::isfinite(d.D3) && std::isfinite(d.D4) &&
            std::isfinite(d.D5)))
        fail("material::johnson_cook: the damage constants D1..D5 = {}, {}, {}, {}, {} must be finite (OFHC copper: "
             "0.54, 4.89, -3.03, 0.014, 1.12)",
             d.D1, d.D2, d.D3, d.D4, d.D5);
    }
    if (!(std::isfinite(tolerance_) && tolerance_ > 0.0 && tolerance_ < 1.0))
      fail("material::johnson_cook: newton_tolerance = {} is invalid: give a relative tolerance in (0, 1), e.g. 1e-12",
           tolerance_);
    if (max_iterations_ < 1)
      fail("material::johnson_cook: max_newton_iterations = {} is invalid: give at least 1 (e.g. 50)",
           max_iterations_);
    mu_ = constants_.shear_modulus();
    bulk_ = constants_.bulk_modulus();
    heat_per_work_ = heating_.taylor_quinney / (constants_.density * heating_.specific_heat);
    flow_constants_ = flow_.precomputed();
  }

  // A point at the initial temperature, with a plastic strain already (a prestrained part) or
  // none. Set a state's eps_p or T through here, not by hand: the state keeps the flow stress
  // they give.
  state_type initial_state(double equivalent_plastic_strain = 0.0) const {
    state_type s;
    s.temperature = heating_.initial_temperature;
    s.equivalent_plastic_strain = equivalent_plastic_strain;
    s.homologous_power = flow_.homologous_power(s.temperature);
    s.flow_stress_at_rest = flow_.flow_stress(equivalent_plastic_strain, flow_point{0.0, s.temperature});
    return s;
  }

  // Advances s from s.previous_deformation to F (dt from step; the temperature is s's) and
  // returns the Kirchhoff stress.
  RKPM_HOT_INLINE mat3 kirchhoff_stress(const mat3& F, state_type& s, const material_step& step = {}) const {
    return kirchhoff_stress(F, s, step, std::numeric_limits<double>::quiet_NaN());
  }
  // The same with log_dt = ln step.dt given (UpdatesWithStepLog, concepts/material.hpp: the force
  // loop takes it once per step); NaN: the return mapping takes it. The same bits either way.
  RKPM_HOT_INLINE mat3 kirchhoff_stress(const mat3& F, state_type& s, const material_step& step, double log_dt) const {
    check_deformation_gradient(F, "material::johnson_cook");
    j2_trial t = j2_trial::of(F, s.elastic_left_cauchy_green, s.previous_deformation, mu_);
    s.previous_deformation = block_matrix::of(F);
    if (s.failed()) {
      s.elastic_left_cauchy_green = isotropic(t.volumetric);
      return failed_stress(t.volumetric);
    }
    const double T = s.temperature;
    const double eps_p = s.equivalent_plastic_strain;
    const double yield = s.flow_stress_at_rest;  // (24b) at eps_p and T, rate* <= 1
    if (!(t.q > yield)) {
      s.elastic_left_cauchy_green = t.b;
      return hencky_stress(t.frame, t.volumetric, t.dev, bulk_, mu_);
    }
    const auto law = flow_.at_homologous_power(s.homologous_power, flow_constants_);  // at the step's temperature
    if (law.theta == 0.0) {  // molten: sigma_y = 0, the whole deviator returns
      s.equivalent_plastic_strain = eps_p + t.q / (3.0 * mu_);
      s.elastic_left_cauchy_green = isotropic(t.volumetric);
      return mat3::Identity() * (bulk_ * t.volumetric);
    }
    const radial_return_result rr = radial_return(law, t.q, 3.0 * mu_, eps_p, tolerance_, max_iterations_, yield,
                                                  material_step{step.dt, step.time, T}, s.log_last_increment, log_dt);
    const double dgamma = rr.increment;
    s.log_last_increment = rr.log_increment;
    s.elastic_left_cauchy_green = t.return_by(dgamma, 3.0 * mu_);
    // ln max(rate*, 1) at the root, from the return mapping's own ln dgamma (no log here), once
    // for the work's rate factor and the failure strain.
    const double log_rate = rr.log_rate;
    const double rate_factor = 1.0 + flow_.C * log_rate;
    // (32) at the step's rate and T: the exact integral from the yield stress at the start and
    // the strain factor S = A + B eps_p^n at the root (no pow, no division).
    const double eps = eps_p + dgamma;
    const double S = rr.strain_factor;
    const double work = law.integral_at_factor(eps_p, eps, yield, S, rate_factor);
    s.plastic_work += work;
    s.equivalent_plastic_strain = eps;
    s.temperature = T + heat_per_work_ * work;  // (32a)
    s.homologous_power = flow_.homologous_power_after(T, s.homologous_power, s.temperature);
    // The next yield check: (A + B eps_p^n)(1 - T*^m) at the new T.
    s.flow_stress_at_rest = S * (1.0 - s.homologous_power);
    if (damage_ && dgamma > 0.0) {
      const double q = rr.flow_stress;  // sqrt(3/2) 2 mu |e^e| = sigma_y at the root
      const double triaxiality = q > 0.0 ? bulk_ * t.volumetric / q : 0.0;  // (tr tau / 3) / q
      const double eps_f = damage_->failure_strain(triaxiality, log_rate, flow_.homologous_temperature(T));
      s.damage = eps_f > 0.0 ? s.damage + dgamma / eps_f : std::max(1.0, s.damage);  // (32b)
      if (s.failed()) {
        if (damage_->opens_cracks) s.crack_normal = crack_normal_at_failure(t);
        s.elastic_left_cauchy_green = isotropic(t.volumetric);
        return failed_stress(t.volumetric);
      }
    }
    return hencky_stress(t.frame, t.volumetric, t.dev, bulk_, mu_);
  }

  // The stress the last kirchhoff_stress(F, s) returned, from the state it left (as
  // j2_plasticity's, to rounding after a return; a failed point's from its volume alone).
  mat3 current_kirchhoff_stress(const mat3& /*F*/, const state_type& s) const {
    const hencky_strains e = hencky_strains::of(s.elastic_left_cauchy_green.full());
    if (s.failed()) return failed_stress(e.volumetric);
    return hencky_stress(e.frame, e.volumetric, e.dev, bulk_, mu_);
  }

  // The point at temperature T (K), from a conducted field (thermal/heat_coupling.hpp), with the
  // flow stress at rest and T*^m that the state keeps for it.
  void set_temperature(state_type& s, double T) const {
    s.temperature = T;
    s.homologous_power = flow_.homologous_power(T);
    s.flow_stress_at_rest = flow_.flow_stress(s.equivalent_plastic_strain, flow_point{0.0, T});
  }

  double density() const { return constants_.density; }
  double dilatational_wave_speed() const { return constants_.dilatational_wave_speed(); }
  const elastic_constants& constants() const { return constants_; }
  const flow_type& flow() const { return flow_; }
  const johnson_cook_heating& heating() const { return heating_; }
  const std::optional<johnson_cook_damage>& damage() const { return damage_; }
  // Whether failed points open cracks (OpensCracks, concepts/material.hpp): the solver looks
  // for failed points only then.
  bool opens_cracks() const { return damage_ && damage_->opens_cracks; }
  // K per J/m^3 of plastic work: beta / (rho0 c_p).
  double heat_per_work() const { return heat_per_work_; }

 private:
  // (32d): pressure in compression only.
  mat3 failed_stress(double volumetric) const {
    return volumetric < 0.0 ? mat3(mat3::Identity() * (bulk_ * volumetric)) : mat3(mat3::Zero());
  }
  // (32f): the in-plane direction of the largest principal stress of the returned trial t (the
  // stress the point carried as it failed, tau_i = K theta + 2 mu e_i, e_0 >= e_1 in plane),
  // when it is tensile and larger than the out-of-plane one; zero otherwise.
  vec2 crack_normal_at_failure(const j2_trial& t) const {
    const double in_plane = bulk_ * t.volumetric + 2.0 * mu_ * t.dev[0];
    const double out_of_plane = bulk_ * t.volumetric + 2.0 * mu_ * t.dev[2];
    return in_plane > 0.0 && in_plane >= out_of_plane ? principal_direction(t.frame) : vec2::Zero();
  }
  // b_e with the volume change theta and no deviator: exp(2 theta / 3) 1.
  static block_matrix isotropic(double volumetric) {
    const double b = std::exp(2.0 * volumetric / 3.0);
    return {b, 0.0, 0.0, b, b};
  }

  elastic_constants constants_;
  flow_type flow_;
  johnson_cook_heating heating_;
  std::optional<johnson_cook_damage> damage_;
  double tolerance_;
  int max_iterations_;
  double mu_ = 0.0, bulk_ = 0.0, heat_per_work_ = 0.0;
  flow_type::precomputed_t flow_constants_{};
};

}  // namespace rkpm::material
