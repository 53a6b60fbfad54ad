#pragma once
// Hencky hyperelasticity (logarithmic strains): the J2 model of j2_plasticity.hpp without
// yield, tau = sum_i (lambda tr(eps) + 2 mu eps_i) n_i n_i^T with b = F F^T = sum_i lambda_i^2
// n_i n_i^T and eps_i = ln(lambda_i) (docs/method.md (22)). Path-independent, so the state
// carries only the two always-zero plastic members the solver reads for output and energy.

#include <string_view>

#include <rkpm/core/types.hpp>
#include <rkpm/material/elastic_constants.hpp>
#include <rkpm/material/hencky.hpp>

namespace rkpm::material {

struct elastic_state {
  double equivalent_plastic_strain = 0.0;
  double plastic_work = 0.0;  // J/m^3 of reference volume
};

class elastic {
 public:
  static constexpr std::string_view name = "elastic";
  using state_type = elastic_state;

  explicit elastic(elastic_constants constants) : constants_(constants) {
    constants_.validate();
    mu_ = constants_.shear_modulus();
    lambda_ = constants_.lame_lambda();
  }

  state_type initial_state() const { return {}; }

  // F: block-structured deformation gradient (see concepts/material.hpp); s is left unchanged.
  mat3 kirchhoff_stress(const mat3& F, state_type& /*s*/) const {
    check_deformation_gradient(F, "material::elastic");
    const mat3 b = F * F.transpose();
    const principal_frame frame = principal_frame::of(b);
    const vec3 eps = principal_log_strains(frame.values);
    const vec3 tau = vec3::Constant(lambda_ * eps.sum()) + 2.0 * mu_ * eps;
    return frame.assemble(tau);
  }

  // The stress at F (path-independent: the same bits as kirchhoff_stress(F, s)), so the solver
  // need not store it.
  mat3 current_kirchhoff_stress(const mat3& F, const state_type& s) const {
    state_type unchanged = s;
    return kirchhoff_stress(F, unchanged);
  }

  double density() const { return constants_.density; }
  double dilatational_wave_speed() const { return constants_.dilatational_wave_speed(); }
  const elastic_constants& constants() const { return constants_; }

 private:
  elastic_constants constants_;
  double mu_ = 0.0;
  double lambda_ = 0.0;
};

}  // namespace rkpm::material
