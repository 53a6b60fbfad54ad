#pragma once
// shared_effective_mass: the effective mass of a slave particle among the slaves in contact with
// it in the same step (docs/method.md (61a), section 6.5).
// Slaves that share coefficients move each other: a force f_K on slave K moves slave J by
// dt^2 C_JK f_K with C_JK = sum_I N_I(X_J) N_I(X_K) / m_I, and (61) keeps only C_JJ. In a row of
// slaves on a flat tool sum_K C_JK is about 2 C_JJ, so the isolated-slave correction with m_eff
// overshoots by about 2: the slip reverses and the row is pushed off the tool, where the Coulomb
// cap (58) zeroes its friction (a sticking surface creeps; tests/numeric/contact_stick.cpp).
//   m_sh,J = 1 / sum_I |N_I(X_J)| S_I / m_I,   S_I = sum over active pairs K of |N_I(X_K)|   (61a)
// bounds sum_K |C_JK| from above, so a sweep with m_sh never overshoots any pattern of gaps or
// slips (Gershgorin), closes a uniform one in one step where the shape functions are positive,
// and equals (61) for an isolated slave.
// Needs no allocation per step: setup() sizes the per-particle sums.

#include <cmath>
#include <span>
#include <vector>

#include <rkpm/contact/contact_pair.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/discretization/shape_table.hpp>

namespace rkpm::contact {

class shared_effective_mass {
 public:
  void setup(index_t particles) { coverage_.assign(particles, 0.0); }

  // mass[q] = m_sh of pairs[q]'s slave (61a); table rows are slaves, m the coefficients' masses.
  void compute(std::span<const contact_pair> pairs, const shape_table<2>& table, std::span<const double> m,
               std::span<double> mass) {
    for (const contact_pair& p : pairs)
      for (index_t e = table.offset[p.slave]; e < table.offset[p.slave + 1]; ++e)
        coverage_[table.neighbor[e]] += std::abs(table.N[e]);
    for (std::size_t q = 0; q < pairs.size(); ++q) {
      const index_t j = pairs[q].slave;
      double s = 0.0;
      for (index_t e = table.offset[j]; e < table.offset[j + 1]; ++e)
        s += std::abs(table.N[e]) * coverage_[table.neighbor[e]] / m[table.neighbor[e]];
      mass[q] = 1.0 / s;
    }
    for (const contact_pair& p : pairs)
      for (index_t e = table.offset[p.slave]; e < table.offset[p.slave + 1]; ++e) coverage_[table.neighbor[e]] = 0.0;
  }

 private:
  std::vector<double> coverage_;  // S_I, #particles, zero between calls
};

}  // namespace rkpm::contact
