#pragma once
// The checks particle_to_segment makes once, at set-up (docs/method.md section 6.1): the body
// and slave data are consistent, and no tool starts inside the body (it may touch it).

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include <rkpm/concepts/contact.hpp>
#include <rkpm/contact/rigid_tool.hpp>
#include <rkpm/contact/segment_grid.hpp>
#include <rkpm/core/error.hpp>

namespace rkpm::contact {

inline void check_contact_inputs(const contact_body& body, const contact_slaves& slaves) {
  const index_t np = static_cast<index_t>(body.reference_position.size());
  if (static_cast<index_t>(body.mass.size()) != np)
    fail("contact setup: {} reference positions but {} masses; give one mass per particle", np, body.mass.size());
  for (index_t I = 0; I < np; ++I)
    if (!(body.mass[I] > 0.0) || !std::isfinite(body.mass[I]))
      fail("contact setup: particle {} has mass {}; lumped masses must be positive and finite", I, body.mass[I]);
  const shape_table<2>& table = slaves.table;
  const index_t ns = static_cast<index_t>(slaves.particle.size());
  if (table.points() != ns)
    fail("contact setup: the slave table has {} rows but there are {} slave particles; build it at the "
         "slaves' reference positions",
         table.points(), ns);
  if (static_cast<index_t>(table.N.size()) != table.entries())
    fail("contact setup: the slave table has {} neighbors but {} values", table.entries(), table.N.size());
  for (index_t j = 0; j < ns; ++j)
    if (slaves.particle[j] < 0 || slaves.particle[j] >= np)
      fail("contact setup: slave {} is particle {}, outside 0..{}", j, slaves.particle[j], np - 1);
  for (index_t I : table.neighbor)
    if (I < 0 || I >= np) fail("contact setup: the slave table names particle {}, outside 0..{}", I, np - 1);
  // A slave no shape function reaches could not be moved: 1 / m_eff (61) would be zero.
  for (index_t j = 0; j < ns; ++j) {
    double s = 0.0;
    for (index_t e = table.offset[j]; e < table.offset[j + 1]; ++e)
      s += table.N[e] * table.N[e] / body.mass[table.neighbor[e]];
    if (!(s > 0.0))
      fail("contact setup: slave {} (particle {}) has no shape function support; check the slave table", j,
           slaves.particle[j]);
  }
}

// A tool may touch the body at t = 0 but not start inside it.
inline void check_tools_outside(const std::vector<rigid_tool>& tools, const std::vector<segment_grid>& grids,
                                std::span<const vec2> X) {
  if (X.empty()) return;
  vec2 lo = X[0], hi = X[0];
  for (const vec2& x : X) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  const double tolerance = 1e-9 * std::max((hi - lo).norm(), 1e-300);
  for (std::size_t k = 0; k < tools.size(); ++k) {
    const rigid_tool& tool = tools[k];
    const vec2 u0 = tool.displacement(0.0);
    for (std::size_t I = 0; I < X.size(); ++I) {
      const vec2 y = X[I] - u0;
      for (const index_t s : grids[k].candidates(y)) {
        double g;
        if (tool.catches(s, y, g) && g > tolerance)
          fail("contact setup: tool '{}' starts inside the body: particle {} at ({}, {}) is {} behind its "
               "segment {}; move the tool (or its motion at t = 0) so that it at most touches the body",
               tool.name(), I, X[I].x(), X[I].y(), g, s);
      }
    }
  }
}

}  // namespace rkpm::contact
