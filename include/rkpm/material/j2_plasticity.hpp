#pragma once
// Finite-strain J2 plasticity with logarithmic elastic strains (docs/method.md section 4.4; the
// multiplicative model of Simo, CMAME 99 (1992), in its principal-stretch form):
//   F = F_e F_p,  b_e = F_e F_e^T,  tau = Hencky(b_e),  -1/2 L_v(b_e) b_e^-1 = dgamma n,
//   n = sqrt(3/2) dev(tau) / |dev(tau)|,  f = q - sigma_y(eps_p) <= 0,  q = sqrt(3/2) |dev(tau)|.
// One step from the last accepted F_n to F:
//   1. f = F F_n^-1,  b_e_trial = f b_e_n f^T (elastic predictor, exact for rigid rotations);
//   2. principal decomposition of b_e_trial (in-plane 2x2 + the principal 33 direction);
//   3. Hencky trial stress in principal log strains;
//   4. radial return in principal log strains (exponential map: plastically incompressible,
//      det b_e unchanged by the return): dev(eps_e) = (1 - 3 mu dgamma / q_trial) dev(eps_trial);
//   5. b_e = sum exp(2 eps_e_i) n_i n_i^T, tau = sum tau_i n_i n_i^T.
// Objective by construction: superposed rotations only rotate b_e and tau.
// Plastic work per unit REFERENCE volume (tau is the Kirchhoff stress, so tau : d_p = q dgamma
// is per unit reference volume): the exact integral of sigma_y over [eps_p_n, eps_p_n + dgamma]
// when the hardening law provides `integral(a, b)` (the shipped laws do), otherwise the
// trapezoidal rule, which is exact for linear hardening.

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <concepts>
#include <limits>
#include <string_view>

#include <rkpm/concepts/material.hpp>
#include <rkpm/core/block_matrix.hpp>
#include <rkpm/core/error.hpp>
#include <rkpm/core/hot_inline.hpp>
#include <rkpm/core/joined_name.hpp>
#include <rkpm/core/simd.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/material/elastic_constants.hpp>
#include <rkpm/material/hardening.hpp>
#include <rkpm/material/hencky.hpp>
#include <rkpm/material/radial_return.hpp>

namespace rkpm::material {

inline constexpr std::string_view j2_name = "j2";

// b_e and F_n as their block entries (core/block_matrix.hpp): 96 bytes per point instead of 160.
struct j2_state {
  block_matrix elastic_left_cauchy_green;  // b_e
  block_matrix previous_deformation;       // F of the last accepted step
  double equivalent_plastic_strain = 0.0;
  double plastic_work = 0.0;  // J/m^3 of reference volume
};

// Plastic work per unit reference volume of an increment dgamma from eps_p (docs/method.md
// (32)); flow_from, flow_to: sigma_y at both ends, known from the return mapping. The exact
// integral when the law has one, otherwise the trapezoidal rule. Called unqualified, so that a
// run-time choice of law (tools/runner/case_file/case_material.hpp) can hand it to its law.
template <Hardening H>
double plastic_work_increment(const H& h, double eps_p, double dgamma, double flow_from, double flow_to) {
  if constexpr (WorkIntegralFromFlow<H>)
    return h.integral(eps_p, eps_p + dgamma, flow_from, flow_to);
  else if constexpr (WorkIntegral<H>)
    return h.integral(eps_p, eps_p + dgamma);
  else
    return 0.5 * (flow_from + flow_to) * dgamma;
}

// exp(2 eps_i) of the principal elastic strains, by Eigen's array exp of a point's three strains
// (a packet exp of its own, whose bits std::exp need not share): for the lanes, lane by lane
// where `only` holds (1 elsewhere), each lane as its point.
RKPM_HOT_INLINE vec3 squared_stretches(const vec3& eps, bool /*only*/ = true) {
  return (2.0 * eps).array().exp().matrix();
}
template <class V>
  requires(!std::same_as<V, double>)
RKPM_HOT_INLINE std::array<V, 3> squared_stretches(const std::array<V, 3>& eps, const typename V::mask_type& only) {
  std::array<V, 3> squared{V(1.0), V(1.0), V(1.0)};
  for (int k = 0; k < lanes_of<V>; ++k) {
    if (!only[k]) continue;
    const vec3 lane = squared_stretches(vec3(eps[0][k], eps[1][k], eps[2][k]));
    for (int i = 0; i < 3; ++i) squared[i][k] = lane(i);
  }
  return squared;
}

// The elastic predictor (25)-(27) of one step from (F_n, b_e,n) to F and the radial return
// (30)-(31) of an increment dgamma: shared by j2_plasticity, its batched update (j2_batch.hpp,
// T a vector of doubles, one point per lane), johnson_cook and zerilli_armstrong (T = double).
template <class T>
struct basic_j2_trial {
  basic_block_matrix<T> b;         // b_e^trial = f b_e,n f^T
  basic_principal_frame<T> frame;  // its principal frame
  T volumetric;                    // theta, the trace of the log strain
  principal_values<T> dev;         // e^trial (e^e after return_by)
  T q;                             // q^trial, the trial von Mises stress

  RKPM_HOT_INLINE static basic_j2_trial of(const basic_block_matrix<T>& F, const basic_block_matrix<T>& b_e_n,
                                           const basic_block_matrix<T>& F_n, double mu) {
    // In block arithmetic (core/block_matrix.hpp): the values of the mat3 products, a third
    // of their cost.
    const basic_block_matrix<T> f = F * inverse(F_n);
    const basic_block_matrix<T> b_trial = f * b_e_n * f.transpose();
    const basic_hencky_strains<T> e = basic_hencky_strains<T>::of(b_trial);
    return {b_trial, e.frame, e.volumetric, e.dev, e.von_mises(mu)};
  }
  RKPM_HOT_INLINE static basic_j2_trial of(const mat3& F, const block_matrix& b_e_n, const block_matrix& F_n, double mu)
    requires std::same_as<T, double>
  {
    return of(block_matrix::of(F), b_e_n, F_n, mu);
  }

  // (30)-(31): scales the deviator back by dgamma (three_mu = 3 mu) and returns b_e,n+1; for
  // the lanes, only where `yields` holds (the deviator and the trial b kept elsewhere).
  RKPM_HOT_INLINE basic_block_matrix<T> return_by(const T& dgamma, double three_mu, const mask_of<T>& yields = true) {
    const T scale = 1.0 - three_mu * dgamma / q;
    for (int i = 0; i < 3; ++i) assign_where(yields, dev[i], T(dev[i] * scale));
    const T third = volumetric / 3.0;
    const principal_values<T> eps_e{dev[0] + third, dev[1] + third, dev[2] + third};
    basic_block_matrix<T> b_e = b;
    assign_where(yields, b_e, frame.assemble_block(squared_stretches(eps_e, yields)));
    return b_e;
  }
};

using j2_trial = basic_j2_trial<double>;

template <Hardening H>
class j2_plasticity {
 public:
  // "j2+linear", "j2+power": the hardening law is part of the name.
  static constexpr std::string_view name = joined_name<j2_name, H::name>::value;
  using hardening_type = H;
  using state_type = j2_state;

  // newton_tolerance is relative to the trial von Mises stress (see radial_return.hpp).
  j2_plasticity(elastic_constants constants, H hardening, double newton_tolerance = 1e-12,
                int max_newton_iterations = 50)
      : constants_(constants),
        hardening_(hardening),
        tolerance_(newton_tolerance),
        max_iterations_(max_newton_iterations) {
    constants_.validate();
    if constexpr (requires { hardening_.validate(); }) hardening_.validate();
    if (!(std::isfinite(tolerance_) && tolerance_ > 0.0 && tolerance_ < 1.0))
      fail("j2_plasticity: newton_tolerance = {} is invalid: give a relative tolerance in (0, 1), "
           "e.g. 1e-12",
           tolerance_);
    if (max_iterations_ < 1)
      fail("j2_plasticity: max_newton_iterations = {} is invalid: give at least 1 (e.g. 50)",
           max_iterations_);
    mu_ = constants_.shear_modulus();
    bulk_ = constants_.bulk_modulus();
    if constexpr (BoundedBelow<H>) lowest_flow_stress_ = hardening_.lowest_flow_stress();
  }

  state_type initial_state() const { return {}; }

  // F: block-structured total deformation gradient (see concepts/material.hpp). Advances s from
  // s.previous_deformation to F and returns the Kirchhoff stress. The step (dt, temperature)
  // reaches the hardening law when it depends on the rate or temperature (concepts/material.hpp).
  // Any state with j2_state's members will do (the case files' material keeps more,
  // tools/runner/case_file/case_material.hpp).
  template <class State>
  mat3 kirchhoff_stress(const mat3& F, State& s, const material_step& step = {}) const {
    check_deformation_gradient(F, "material::j2_plasticity");
    j2_trial t = j2_trial::of(F, s.elastic_left_cauchy_green, s.previous_deformation, mu_);
    const plastic_flow flow = plastic_flow_of(t.q, s.equivalent_plastic_strain, step);
    if (flow.yields) {
      s.elastic_left_cauchy_green = t.return_by(flow.increment, 3.0 * mu_);
      s.plastic_work += flow.work;
      s.equivalent_plastic_strain += flow.increment;
    } else {
      s.elastic_left_cauchy_green = t.b;
    }
    s.previous_deformation = block_matrix::of(F);
    return hencky_stress(t.frame, t.volumetric, t.dev, bulk_, mu_);
  }

  // The stress the last kirchhoff_stress(F, s) returned, from the state it left: tau =
  // Hencky(b_e). The solver asks for it at output instead of storing tau at every point (80
  // bytes a particle). Points that stayed elastic get the same bits (b_e is the trial tensor
  // the update decomposed); after a return the principal frame is found again from b_e =
  // sum exp(2 eps_e_i) n_i n_i^T, which agrees to rounding.
  template <class State>
  mat3 current_kirchhoff_stress(const mat3& /*F*/, const State& s) const {
    const hencky_strains e = hencky_strains::of(s.elastic_left_cauchy_green.full());
    return hencky_stress(e.frame, e.volumetric, e.dev, bulk_, mu_);
  }

  double density() const { return constants_.density; }
  double dilatational_wave_speed() const { return constants_.dilatational_wave_speed(); }
  const elastic_constants& constants() const { return constants_; }
  const H& hardening() const { return hardening_; }
  // What the batched update (j2_batch.hpp) computes with, the values this class uses.
  double shear_modulus() const { return mu_; }
  double bulk_modulus() const { return bulk_; }

  // The plastic flow of a step from the trial von Mises stress q_trial at eps_p (a point of
  // kirchhoff_stress, or a lane of the batched update): whether it yields, dgamma and the plastic
  // work per reference volume it adds.
  struct plastic_flow {
    bool yields = false;
    double increment = 0.0;
    double work = 0.0;
  };
  plastic_flow plastic_flow_of(double q_trial, double eps_p, const material_step& step) const {
    // The yield check at the static curve (rate 0) and the step's temperature; a trial stress at
    // or below the lowest flow stress of a law that only hardens is elastic without evaluating
    // the curve: a costly law (the power law's pow) is then evaluated only at points that may
    // yield, and most points of a forging are below yield for most of the run. The result is
    // the same bits either way.
    if (!(q_trial > lowest_flow_stress_)) return {};
    const double yield = flow_stress_at(hardening_, eps_p, flow_point{0.0, step.temperature});
    if (!(q_trial > yield)) return {};
    const radial_return_result rr =
        radial_return(hardening_, q_trial, 3.0 * mu_, eps_p, tolerance_, max_iterations_, yield, step);
    return {true, rr.increment, plastic_work_increment(hardening_, eps_p, rr.increment, yield, rr.flow_stress)};
  }

 private:

  elastic_constants constants_;
  H hardening_;
  double tolerance_;
  int max_iterations_;
  double mu_ = 0.0;
  double bulk_ = 0.0;
  double lowest_flow_stress_ = -std::numeric_limits<double>::infinity();  // no shortcut for other laws
};

}  // namespace rkpm::material
