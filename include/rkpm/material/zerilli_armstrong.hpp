#pragma once
// Zerilli-Armstrong plasticity with adiabatic heating (docs/method.md section 4.6): the
// finite-strain J2 model of j2_plasticity.hpp (its predictor and radial return, j2_trial) with the
// flow stress (24c) of hardening::zerilli_armstrong, fcc or bcc, at the point's temperature and
// at the rate dgamma / dt its increment implies (the return mapping (28a) of radial_return.hpp),
// and per point, as material::johnson_cook has them:
//   - the temperature: rho0 c_p dT = beta dW_p (32e), dW_p the exact work integral (32) at the
//     step's rate and temperature, beta the Taylor-Quinney fraction; the flow stress of a step
//     uses the temperature at its start (explicit in T);
//   - melt (optional): at T >= T_melt the flow stress is 0, the whole trial deviator returns
//     (dgamma = q_trial / (3 mu)) and the point carries pressure only.
// No damage. The heat is part of the plastic work the energy ledger already counts.

#include <array>
#include <cmath>
#include <limits>
#include <string_view>
#include <utility>

#include <rkpm/concepts/material.hpp>
#include <rkpm/core/block_matrix.hpp>
#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/material/elastic_constants.hpp>
#include <rkpm/material/hardening/zerilli_armstrong.hpp>
#include <rkpm/material/hencky.hpp>
#include <rkpm/material/j2_plasticity.hpp>
#include <rkpm/material/radial_return.hpp>

namespace rkpm::material {

// j2_state's members and the point's temperature (104 B).
struct zerilli_armstrong_state {
  block_matrix elastic_left_cauchy_green;  // b_e
  block_matrix previous_deformation;       // F of the last accepted step
  double equivalent_plastic_strain = 0.0;
  double plastic_work = 0.0;                                      // J/m^3 of reference volume
  double temperature = std::numeric_limits<double>::quiet_NaN();  // K
  // The snapshot fields (io/solver_output.hpp).
  static constexpr auto output_fields() {
    return std::array{std::pair{std::string_view("temperature_K"), &zerilli_armstrong_state::temperature}};
  }
};

// Adiabatic heating (32e).
struct zerilli_armstrong_heating {
  double specific_heat;        // c_p in J/(kg K), > 0
  double taylor_quinney = 0.9; // beta in [0, 1]
  double initial_temperature;  // K, > 0 (the law has no room temperature to fall back on)
};

class zerilli_armstrong {
 public:
  static constexpr std::string_view name = "zerilli_armstrong";
  using flow_type = hardening::zerilli_armstrong;
  using state_type = zerilli_armstrong_state;

  zerilli_armstrong(elastic_constants constants, flow_type flow, zerilli_armstrong_heating heating,
                    double newton_tolerance = 1e-12, int max_newton_iterations = 50)
      : constants_(constants),
        flow_(flow),
        heating_(heating),
        tolerance_(newton_tolerance),
        max_iterations_(max_newton_iterations) {
    constants_.validate();
    flow_.validate();
    if (!(std::isfinite(heating_.specific_heat) && heating_.specific_heat > 0.0))
      fail("material::zerilli_armstrong: specific_heat = {} J/(kg K) is invalid: give a finite value > 0 (copper: 383)",
           heating_.specific_heat);
    if (!(heating_.taylor_quinney >= 0.0 && heating_.taylor_quinney <= 1.0))
      fail("material::zerilli_armstrong: taylor_quinney = {} is invalid: give a fraction in [0, 1] (usually 0.9)",
           heating_.taylor_quinney);
    if (!(std::isfinite(heating_.initial_temperature) && heating_.initial_temperature > 0.0))
      fail("material::zerilli_armstrong: initial_temperature = {} K is invalid: give a finite value > 0 (e.g. 294)",
           heating_.initial_temperature);
    if (!(std::isfinite(tolerance_) && tolerance_ > 0.0 && tolerance_ < 1.0))
      fail("material::zerilli_armstrong: newton_tolerance = {} is invalid: give a relative tolerance in (0, 1), e.g. "
           "1e-12",
           tolerance_);
    if (max_iterations_ < 1)
      fail("material::zerilli_armstrong: max_newton_iterations = {} is invalid: give at least 1 (e.g. 50)",
           max_iterations_);
    mu_ = constants_.shear_modulus();
    bulk_ = constants_.bulk_modulus();
    heat_per_work_ = heating_.taylor_quinney / (constants_.density * heating_.specific_heat);
  }

  state_type initial_state() const {
    state_type s;
    s.temperature = heating_.initial_temperature;
    return s;
  }

  // Advances s from s.previous_deformation to F (dt from step; the temperature is s's) and
  // returns the Kirchhoff stress. Any state with zerilli_armstrong_state's members will do (the
  // case files' material keeps more, tools/runner/case_file/case_material.hpp).
  template <class State>
  mat3 kirchhoff_stress(const mat3& F, State& s, const material_step& step = {}) const {
    check_deformation_gradient(F, "material::zerilli_armstrong");
    j2_trial t = j2_trial::of(F, s.elastic_left_cauchy_green, s.previous_deformation, mu_);
    s.previous_deformation = block_matrix::of(F);
    const double T = s.temperature;
    const double eps_p = s.equivalent_plastic_strain;
    if (flow_.molten(T)) {  // sigma_y = 0: the whole deviator returns
      s.equivalent_plastic_strain = eps_p + t.q / (3.0 * mu_);
      const double b = std::exp(2.0 * t.volumetric / 3.0);
      s.elastic_left_cauchy_green = {b, 0.0, 0.0, b, b};
      return mat3::Identity() * (bulk_ * t.volumetric);
    }
    const double yield = flow_.flow_stress(eps_p, flow_point{0.0, T});  // rate* = 1
    if (!(t.q > yield)) {
      s.elastic_left_cauchy_green = t.b;
      return hencky_stress(t.frame, t.volumetric, t.dev, bulk_, mu_);
    }
    const radial_return_result rr = radial_return(flow_, t.q, 3.0 * mu_, eps_p, tolerance_, max_iterations_, yield,
                                                  material_step{step.dt, step.time, T});
    const double dgamma = rr.increment;
    s.elastic_left_cauchy_green = t.return_by(dgamma, 3.0 * mu_);
    const double rate = step.dt > 0.0 ? dgamma / step.dt : 0.0;
    const double work = flow_.integral(eps_p, eps_p + dgamma, flow_point{rate, T});  // (32)
    s.plastic_work += work;
    s.equivalent_plastic_strain = eps_p + dgamma;
    s.temperature = T + heat_per_work_ * work;  // (32e)
    return hencky_stress(t.frame, t.volumetric, t.dev, bulk_, mu_);
  }

  // The stress the last kirchhoff_stress(F, s) returned, from the state it left (as
  // j2_plasticity's).
  template <class State>
  mat3 current_kirchhoff_stress(const mat3& /*F*/, const State& s) const {
    const hencky_strains e = hencky_strains::of(s.elastic_left_cauchy_green.full());
    return hencky_stress(e.frame, e.volumetric, e.dev, bulk_, mu_);
  }

  double density() const { return constants_.density; }
  double dilatational_wave_speed() const { return constants_.dilatational_wave_speed(); }
  const elastic_constants& constants() const { return constants_; }
  const flow_type& flow() const { return flow_; }
  const zerilli_armstrong_heating& heating() const { return heating_; }
  // The point at temperature T (K), from a conducted field (thermal/heat_coupling.hpp).
  template <class State>
  void set_temperature(State& s, double T) const {
    s.temperature = T;
  }
  // K per J/m^3 of plastic work: beta / (rho0 c_p).
  double heat_per_work() const { return heat_per_work_; }

 private:

  elastic_constants constants_;
  flow_type flow_;
  zerilli_armstrong_heating heating_;
  double tolerance_;
  int max_iterations_;
  double mu_ = 0.0, bulk_ = 0.0, heat_per_work_ = 0.0;
};

}  // namespace rkpm::material
