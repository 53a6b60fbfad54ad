#pragma once
// Brittle fracture: Hencky elasticity (material/elastic.hpp, docs/method.md (22)) with isotropic
// Rankine damage and linear softening, regularized by a crack band of width h so that a crack
// dissipates the fracture energy G_c per unit area whatever the resolution (docs/method.md
// section 4.7, (102)-(107)):
//   tau~_i = lambda tr(eps) + 2 mu eps_i               the effective principal stresses
//   kappa = max over the history of max_i tau~_i / E   the Rankine equivalent strain     (102)
//   eps0 = sigma_t / E,  eps_f = 2 G_c / (sigma_t h) > eps0                               (103)
//   D = 1 - (eps0 / kappa) (eps_f - kappa) / (eps_f - eps0) on [eps0, eps_f]              (104)
//   tau_i = (1 - D) <tau~_i>_+ + <tau~_i>_-            tension degraded, compression kept (105)
//   W_d = (G_c / h) (kappa - eps0) / (eps_f - eps0) on [eps0, eps_f]                      (106)
// (106) is int Y dD with Y = E kappa^2 / 2, the Rankine energy at the damage surface, integrated
// exactly: a function of kappa alone, so the dissipation does not depend on the step, and in
// uniaxial stress it is the work of the stress minus the stored energy. h follows the kernel's
// support, h = 3a/4 for the cubic spline (107), so that W_d h = G_c per unit crack area at every
// resolution.

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>
#include <utility>

#include <rkpm/concepts/kernel.hpp>
#include <rkpm/concepts/material.hpp>
#include <rkpm/core/bitwise.hpp>
#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/material/elastic_constants.hpp>
#include <rkpm/material/hencky.hpp>

namespace rkpm::material {

struct rankine_fracture_state {
  double equivalent_plastic_strain = 0.0;  // always 0: the law has no plastic flow
  double plastic_work = 0.0;               // J/m^3 of reference volume: the dissipation W_d (106)
  double fracture_work = 0.0;              // J/m^3, the same W_d, for a ledger that names fracture
  double kappa = 0.0;                      // (102), dimensionless
  double damage = 0.0;                     // D (104), >= 1 failed
  // Unused: fills the 8 bytes before crack_normal's 16-byte alignment, which would otherwise be
  // padding a copy may leave as it was, so that a state's bytes (a checkpoint's) are its values
  // and a run on several processes writes one process's file.
  double unused = 0.0;
  // Unit normal of the crack in the current configuration: the in-plane principal direction of
  // the larger in-plane effective stress at the update where D first grew; zero before, and zero
  // after when the out-of-plane stress was the largest (a hoop crack in axisymmetry).
  vec2 crack_normal = vec2::Zero();

  bool failed() const { return damage >= 1.0; }
  // The snapshot fields (io/solver_output.hpp).
  static constexpr auto output_fields() {
    return std::array{std::pair{std::string_view("damage"), &rankine_fracture_state::damage},
                      std::pair{std::string_view("fracture_work_J_m3"), &rankine_fracture_state::fracture_work}};
  }
};

static_assert(bitwise_value<rankine_fracture_state>, "checkpoints write the state as raw bytes");
static_assert(sizeof(rankine_fracture_state) == 8 * sizeof(double), "no padding: every byte a checkpoint writes is a value");

class rankine_fracture {
 public:
  static constexpr std::string_view name = "rankine";
  using state_type = rankine_fracture_state;

  // The band width for kernel K of support radius a (m): the window's width at equal area,
  // h = a int K / K(0) (107), 3a/4 for the cubic spline and 4a/5 for the quartic. The RK
  // approximation spreads a displacement jump over the window, so the softening strain localizes
  // over that width (docs/method.md section 4.7).
  template <Kernel K>
  static double band_width_of_support(double support) {
    constexpr int intervals = 2000;  // Simpson's rule on z in [-1, 1]: exact to round-off for the splines' pieces
    double area = 0.0;
    for (int i = 0; i <= intervals; ++i) {
      const double z = -1.0 + 2.0 * i / intervals;
      area += (i == 0 || i == intervals ? 1.0 : i % 2 ? 4.0 : 2.0) * K::value(z);
    }
    area *= 2.0 / (3.0 * intervals);
    return support * area / K::value(0.0);
  }

  // tensile_strength sigma_t in Pa, fracture_energy G_c in J/m^2, band_width h in m.
  rankine_fracture(elastic_constants constants, double tensile_strength, double fracture_energy, double band_width)
      : constants_(constants), sigma_t_(tensile_strength), G_c_(fracture_energy), h_(band_width) {
    constants_.validate();
    if (!(std::isfinite(sigma_t_) && sigma_t_ > 0.0))
      fail("material::rankine_fracture: tensile_strength = {} Pa is invalid: give a finite value > 0 (PMMA: 70e6 Pa, "
           "concrete: 3e6 Pa)",
           sigma_t_);
    if (!(std::isfinite(G_c_) && G_c_ > 0.0))
      fail("material::rankine_fracture: fracture_energy = {} J/m^2 is invalid: give a finite value > 0 (PMMA: 500 "
           "J/m^2, concrete: 100 J/m^2)",
           G_c_);
    if (!(std::isfinite(h_) && h_ > 0.0))
      fail("material::rankine_fracture: band_width = {} m is invalid: give a finite value > 0 (the kernel's support "
           "radius, rankine_fracture::band_width_of_support<Kernel>(a))",
           h_);
    E_ = constants_.youngs_modulus;
    mu_ = constants_.shear_modulus();
    lambda_ = constants_.lame_lambda();
    eps0_ = sigma_t_ / E_;
    eps_f_ = 2.0 * G_c_ / (sigma_t_ * h_);
    if (!(eps_f_ > eps0_))
      fail("material::rankine_fracture: band_width h = {} m is too wide: the largest allowed is 2 G_c E / sigma_t^2 = "
           "{} m (beyond it the softening snaps back, eps_f = 2 G_c / (sigma_t h) <= sigma_t / E); use finer "
           "particles or a smaller band width",
           h_, largest_band_width());
    // On [eps0, eps_f]: 1 - D = c (eps_f / kappa - 1) with c = eps0 / (eps_f - eps0) (104).
    softening_ = eps0_ / (eps_f_ - eps0_);
  }

  state_type initial_state() const { return {}; }

  // F: block-structured deformation gradient (concepts/material.hpp). Advances kappa, D, W_d and
  // the crack normal to F and returns the Kirchhoff stress (105).
  mat3 kirchhoff_stress(const mat3& F, state_type& s) const {
    check_deformation_gradient(F, "material::rankine_fracture");
    const principal_frame frame = principal_frame::of(F * F.transpose());
    const vec3 effective = effective_stress(frame);
    const double largest = effective.maxCoeff();
    const double kappa = largest / E_;  // (102)
    if (kappa > s.kappa) {
      const bool starts = s.damage == 0.0 && kappa > eps0_;
      s.kappa = kappa;
      s.damage = damage_at(kappa);
      s.fracture_work = dissipation_at(kappa);
      s.plastic_work = s.fracture_work;
      if (starts) s.crack_normal = effective(0) >= effective(2) ? principal_direction(frame) : vec2::Zero();
    }
    return degraded(frame, effective, s.damage);
  }

  // The stress the last kirchhoff_stress(F, s) returned (the same bits: the same F and D), so the
  // solver need not store it.
  mat3 current_kirchhoff_stress(const mat3& F, const state_type& s) const {
    const principal_frame frame = principal_frame::of(F * F.transpose());
    return degraded(frame, effective_stress(frame), s.damage);
  }

  // D(kappa) (104): 0 up to eps0, 1 from eps_f on.
  double damage_at(double kappa) const {
    if (!(kappa > eps0_)) return 0.0;
    if (!(kappa < eps_f_)) return 1.0;
    return 1.0 - softening_ * (eps_f_ / kappa - 1.0);
  }
  // W_d(kappa) (106) in J/m^3: 0 up to eps0, G_c / h from eps_f on.
  double dissipation_at(double kappa) const {
    if (!(kappa > eps0_)) return 0.0;
    if (!(kappa < eps_f_)) return G_c_ / h_;
    return G_c_ / h_ * (kappa - eps0_) / (eps_f_ - eps0_);
  }

  double tensile_strength() const { return sigma_t_; }
  double fracture_energy() const { return G_c_; }
  double band_width() const { return h_; }
  // eps0 and eps_f (103).
  double damage_onset_strain() const { return eps0_; }
  double failure_strain() const { return eps_f_; }
  // 2 G_c E / sigma_t^2 in m: the widest band without snap-back (103).
  double largest_band_width() const { return 2.0 * G_c_ * constants_.youngs_modulus / (sigma_t_ * sigma_t_); }

  double density() const { return constants_.density; }
  double dilatational_wave_speed() const { return constants_.dilatational_wave_speed(); }
  const elastic_constants& constants() const { return constants_; }

 private:
  // tau~_i (22) of the principal stretches.
  vec3 effective_stress(const principal_frame& frame) const {
    const vec3 eps = principal_log_strains(frame.values);
    return vec3::Constant(lambda_ * eps.sum()) + 2.0 * mu_ * eps;
  }
  // (105): the positive principal stresses times 1 - D, the negative ones whole.
  static mat3 degraded(const principal_frame& frame, const vec3& effective, double damage) {
    const double integrity = 1.0 - damage;
    vec3 tau;
    for (int i = 0; i < 3; ++i) tau(i) = effective(i) > 0.0 ? integrity * effective(i) : effective(i);
    return frame.assemble(tau);
  }

  elastic_constants constants_;
  double sigma_t_, G_c_, h_;
  double E_ = 0.0, mu_ = 0.0, lambda_ = 0.0;
  double eps0_ = 0.0, eps_f_ = 0.0, softening_ = 0.0;
};

static_assert(Material<rankine_fracture>);

}  // namespace rkpm::material
