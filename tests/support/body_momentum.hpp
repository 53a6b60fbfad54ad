#pragma once
// The x momentum and the mass of one body of a solver's model (body -1: all of them), from the
// coefficient velocities and the lumped masses: what the contact tests between bodies conserve.

#include <utility>

#include <rkpm/core/types.hpp>

namespace rkpm::test {

template <class Solver>
std::pair<double, double> body_momentum_x(const Solver& s, int body) {
  double P = 0.0, M = 0.0;
  for (index_t I = 0; I < s.model().particle_count(); ++I)
    if (body < 0 || s.body_of_particle(I) == body) {
      P += s.mass()[I] * s.coefficient_velocities()[I][0];
      M += s.mass()[I];
    }
  return {P, M};
}

}  // namespace rkpm::test
