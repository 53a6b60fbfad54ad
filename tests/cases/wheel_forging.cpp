// Wheel forging (cases/wheel_forging.hpp, docs/method.md section 10.3), reduced: about half the
// paper's particles per direction and a 4 mm stroke instead of 20 mm. Physical invariants:
//   - plastic incompressibility: sum_q J_q w_q (axisymmetric weights, 2 pi r included or not,
//     the ratio is what counts) changes by less than 2%;
//   - no particle lies inside the punch (above its moving outline) or the die (below z = 0,
//     beyond r = 35 mm) by more than 2% of the particle spacing; the depth inside the punch is
//     the true distance to its outline, not the vertical one, because of the 5:1 flanks. With
//     the surface particles only as slaves this fails from about 5 mm of stroke on: the punch's
//     convex corners cut between two surface particles and the particles below enter the punch;
//     the case's three layers of slaves keep them out (the second test, over 10 mm; docs/method.md
//     section 6.10).
//   - material flows outward and stays in the die: the punch's land (r 12..24 mm) presses the
//     slug's top ring down to its own level and stays in contact; the slug spreads (largest r
//     grows) but stays inside the die wall r = 35 mm. Early in the stroke nothing is pushed up
//     into the hub recess: frictionless, the pressed ring flows outward like a ring in the
//     ring-compression test (whose hole widens without friction), pulling the free core r < 12 mm
//     outward and so shortening it; the core's top lowers, but by less than the stroke.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/solver/make_solver.hpp>

#include "cases/wheel_forging.hpp"

namespace test_cases_wheel_forging {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

namespace {

using wf = cases::wheel_forging;
using contact_t = contact::particle_to_segment<contact::enforcement::paper, contact::friction::coulomb>;
using cfg = config<kernel::cubic_spline, correction::linear, quadrature::q2, wf::geometry_type, wf::material_type,
                   contact_t>;

double segment_distance(const vec2& x, const vec2& a, const vec2& b) {
  const vec2 ab = b - a;
  const double s = std::clamp((x - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (x - (a + s * ab)).norm();
}

// Depth of x inside the punch whose outline (a graph z = f(r), body above it) is `outline`
// shifted down by `drop`; 0 outside.
double punch_depth(const vec2& x, std::vector<vec2> outline, double drop) {
  for (vec2& c : outline) c.y() -= drop;
  for (std::size_t k = 0; k + 1 < outline.size(); ++k) {
    const vec2 a = outline[k], b = outline[k + 1];
    if (x.x() < a.x() || x.x() > b.x()) continue;
    const double f = a.y() + (b.y() - a.y()) * (x.x() - a.x()) / (b.x() - a.x());
    if (x.y() <= f) return 0.0;
    double d = 1e30;
    for (std::size_t m = 0; m + 1 < outline.size(); ++m) d = std::min(d, segment_distance(x, outline[m], outline[m + 1]));
    return d;
  }
  return 0.0;  // beyond the punch's ends
}

}  // namespace

TEST_CASE("wheel forging, 4 mm stroke: volume kept, punch and die not crossed, outward flow inside the die") {
  wf::parameters p;
  p.radial_particles = 16;
  p.axial_particles = 15;
  p.stroke_m = 4e-3;
  run_options o;
  o.end_time = wf::end_time(p);
  auto s = make_solver<cfg>(wf::build<contact_t>(p, 1), o);

  const double h = std::min(p.slug_radius_m / (p.radial_particles - 1.0), p.slug_height_m / (p.axial_particles - 1.0));
  const double die_r = wf::die_outline()[1].x();
  double worst_punch = 0.0, worst_die = 0.0;
  const auto punch = wf::punch_outline();
  s.run(
      [&](const auto& s) {
        const auto x = s.particle_positions();
        const double drop = p.tool_velocity_m_s * s.time();
        // Every particle, not only the slaves: a tool corner can cut between slave particles
        // (one-pass particle-to-segment contact stops slaves, not the tool's corners), and the
        // particles behind the surface then end up inside the tool.
        for (const vec2& xi : x) {
          worst_punch = std::max(worst_punch, punch_depth(xi, punch, drop));
          worst_die = std::max({worst_die, -xi.y(), xi.x() - die_r});
        }
      },
      1);

  double v0 = 0.0, v = 0.0;
  for (index_t q = 0; q < s.model().point_count(); ++q) {
    v0 += s.model().points.weight[q];
    v += s.model().points.weight[q] * s.point_det_F(q);
  }
  const auto x = s.particle_positions();
  const auto& X = s.model().particles.position;
  const double land = wf::punch_outline()[2].y() - p.stroke_m;  // punch land height at the end
  double hub = 0.0, r_max = 0.0, land_lo = 1e30, land_hi = -1e30;
  for (std::size_t I = 0; I < x.size(); ++I) {
    if (x[I].x() < 10e-3) hub = std::max(hub, x[I].y());
    r_max = std::max(r_max, x[I].x());
    // Top-row particles that started well under the land (r 13..21 mm).
    if (X[I].y() > p.slug_height_m - 1e-9 && X[I].x() > 13e-3 && X[I].x() < 21e-3) {
      land_lo = std::min(land_lo, x[I].y());
      land_hi = std::max(land_hi, x[I].y());
    }
  }
  MESSAGE(s.steps(), " steps; volume change ", v / v0 - 1.0, "; depth in punch ", worst_punch / h, " h, in die ",
          worst_die / h, " h; hub height ", hub * 1e3, " mm (slug ", p.slug_height_m * 1e3, " mm); top under the land ", land_lo * 1e3, "..", land_hi * 1e3, " mm (land at ", land * 1e3,
          " mm); largest r ",
          r_max * 1e3, " mm; balance error ", s.energy().balance_error());

  CHECK(std::abs(v / v0 - 1.0) < 0.02);
  CHECK(worst_punch < 0.02 * h);
  CHECK(worst_die < 0.02 * h);
  CHECK(land_hi < land + 0.02 * h);
  CHECK(land_lo > land - 0.1 * h);  // still in contact: the land pushed them all the way
  CHECK(hub < p.slug_height_m);
  CHECK(hub > p.slug_height_m - p.stroke_m);
  CHECK(r_max < die_r + 0.02 * h);
  CHECK(r_max > p.slug_radius_m);  // the slug spreads
  CHECK(s.energy().balance_error() < 0.02);
}

TEST_CASE("wheel forging, 10 mm stroke: the punch's corners drag particles under a surface of slaves; three layers of slaves keep them out") {
  // docs/method.md section 6.10: with the surface particles only as slaves, the punch's convex
  // corners cut the chord between two of them and the particles below enter the punch; with the
  // particles of three cell layers as slaves (the case's default) the particles below meet the
  // punch's faces. Measured as the deepest particle inside the punch over the stroke.
  auto deepest_in_punch = [](int layers) {
    wf::parameters p;
    p.radial_particles = 12;
    p.axial_particles = 11;
    p.stroke_m = 10e-3;
    p.slave_layers = layers;
    run_options o;
    o.end_time = wf::end_time(p);
    auto s = make_solver<cfg>(wf::build<contact_t>(p, 1), o);
    const double h = std::min(p.slug_radius_m / (p.radial_particles - 1.0), p.slug_height_m / (p.axial_particles - 1.0));
    double worst = 0.0;
    s.run(
        [&](const auto& s) {
          for (const vec2& xi : s.particle_positions())
            worst = std::max(worst, punch_depth(xi, wf::punch_outline(), p.tool_velocity_m_s * s.time()));
        },
        10);
    return worst / h;
  };
  const double surface = deepest_in_punch(1), layers = deepest_in_punch(3);
  MESSAGE("deepest particle inside the punch: surface slaves " << surface << " h, three layers " << layers << " h");
  CHECK(layers < 0.02);
  CHECK(surface > 0.1);  // the check above sees what the layers remove
}

}  // namespace test_cases_wheel_forging
