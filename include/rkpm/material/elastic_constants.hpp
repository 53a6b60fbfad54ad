#pragma once
// Isotropic elastic constants shared by every material law: Young's modulus E, Poisson's ratio
// nu and the reference density rho0 (docs/method.md sections 10.1 and 10.3), with the derived moduli
// the Hencky law and the stable time step need (docs/method.md (20)-(21)):
//   mu = E / (2 (1 + nu)),  K = E / (3 (1 - 2 nu)),  lambda = E nu / ((1 + nu) (1 - 2 nu)).

#include <cmath>

#include <rkpm/core/error.hpp>

namespace rkpm::material {

struct elastic_constants {
  double youngs_modulus;  // E in Pa
  double poisson_ratio;   // nu, dimensionless
  double density;         // rho0 in kg/m^3, per unit reference volume

  // Every material constructor calls this, so a bad constant is reported once, at set-up,
  // instead of surfacing later as a NaN stress or a zero time step.
  void validate() const {
    if (!(std::isfinite(youngs_modulus) && youngs_modulus > 0.0))
      fail("elastic_constants: youngs_modulus = {} Pa is invalid: give a finite value > 0 "
           "(copper: 117e9 Pa)",
           youngs_modulus);
    // nu -> 0.5 sends K and lambda to infinity, nu -> -1 sends mu to infinity: both ends open.
    if (!(std::isfinite(poisson_ratio) && poisson_ratio > -1.0 && poisson_ratio < 0.5))
      fail("elastic_constants: poisson_ratio = {} is invalid: give a value in the open range "
           "(-1, 0.5) (copper: 0.35; an incompressible 0.5 needs a mixed formulation)",
           poisson_ratio);
    if (!(std::isfinite(density) && density > 0.0))
      fail("elastic_constants: density = {} kg/m^3 is invalid: give a finite value > 0 "
           "(copper: 8930 kg/m^3)",
           density);
  }

  double shear_modulus() const { return youngs_modulus / (2.0 * (1.0 + poisson_ratio)); }
  double bulk_modulus() const { return youngs_modulus / (3.0 * (1.0 - 2.0 * poisson_ratio)); }
  double lame_lambda() const {
    return youngs_modulus * poisson_ratio / ((1.0 + poisson_ratio) * (1.0 - 2.0 * poisson_ratio));
  }
  // P-wave modulus lambda + 2 mu: the stiffness behind the dilatational wave speed.
  double p_wave_modulus() const { return lame_lambda() + 2.0 * shear_modulus(); }
  double dilatational_wave_speed() const { return std::sqrt(p_wave_modulus() / density); }
};

}  // namespace rkpm::material
