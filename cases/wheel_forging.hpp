#pragma once
// Case 3 of the paper (docs/method.md section 10.3, with our reconstruction of its lost figure):
// axisymmetric forging of an aluminium slug into a wheel. The slug (r 0..22 mm, z 0..28 mm,
// 31 x 30 particles) sits on a fixed die (floor z = 0 to r = 35 mm, wall r = 35 mm); the punch
// (0,38)-(10,38)-(12,28)-(24,28)-(26,38)-(34.5,38) mm moves down at 10 m/s for 20 mm, driving
// material up into the hub recess (r < 12 mm) and out into the rim recess (r > 24 mm).
// Frictionless; power-law flow stress 576.79 (0.01658 + eps_p)^0.3593 MPa.

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <rkpm/contact/rigid_tool.hpp>
#include <rkpm/core/exact_sum.hpp>
#include <rkpm/discretization/background_mesh.hpp>
#include <rkpm/discretization/boundary_chains.hpp>
#include <rkpm/discretization/particle_set.hpp>
#include <rkpm/geometry/axisymmetric.hpp>
#include <rkpm/material/j2_plasticity.hpp>
#include <rkpm/solver/fields.hpp>
#include <rkpm/solver/problem.hpp>

#include "cases/contact_setup.hpp"
#include "cases/parameters.hpp"

namespace rkpm::cases {

struct wheel_forging_parameters {
  double tool_velocity_m_s = 10.0;
  double stroke_m = 20e-3;
  double friction = 0.0;
  double slug_radius_m = 22e-3;
  double slug_height_m = 28e-3;
  double youngs_modulus_Pa = 71e9;
  double poisson_ratio = 0.3;
  double density_kg_m3 = 2700.0;
  double flow_coefficient_Pa = 576.79e6;
  double flow_offset = 0.01658;
  double flow_exponent = 0.3593;
  int radial_particles = 31;
  int axial_particles = 30;
  double support_factor = 2.0;
  double penalty_stiffness_N_m = 1e11;
  // Contact slaves: the particles within this many cell layers of the slug's surface (1: the
  // surface only), 0: every particle. The punch's convex corners (r = 12 and 24 mm) cut the
  // chord between two surface particles as the material flows round them, and with surface
  // slaves only they drag the particles just below into the punch (about 1 mm deep by the end of
  // the stroke); the particles of the layers below then meet the punch's faces as slaves.
  int slave_layers = 3;
  // 1: the tools' vertices are also checked as slaves against the body's surface (two-pass tool
  // contact, docs/method.md section 6.10), which keeps the punch's corners out of the chords
  // between surface particles but holds material flowing round a corner back by a spacing.
  bool tool_vertex_slaves = false;
  // Deepest penetration a tool face still acts on. The default of rigid_tool (half the
  // shortest segment: 18 mm for the die) would make every particle within 18 mm of the floor a
  // candidate at every step; a few particle spacings is plenty.
  double contact_depth_m = 2e-3;

  using P = wheel_forging_parameters;
  static constexpr std::array fields = {
      parameter<P>{"tool_velocity_m_s", "m/s", "punch speed (downward)", &P::tool_velocity_m_s},
      parameter<P>{"stroke_m", "m", "punch stroke (end time = stroke / speed)", &P::stroke_m},
      parameter<P>{"friction", "-", "Coulomb coefficient on punch and die", &P::friction},
      parameter<P>{"slug_radius_m", "m", "slug radius", &P::slug_radius_m},
      parameter<P>{"slug_height_m", "m", "slug height", &P::slug_height_m},
      parameter<P>{"youngs_modulus_Pa", "Pa", "Young's modulus", &P::youngs_modulus_Pa},
      parameter<P>{"poisson_ratio", "-", "Poisson's ratio", &P::poisson_ratio},
      parameter<P>{"density_kg_m3", "kg/m^3", "density", &P::density_kg_m3},
      parameter<P>{"flow_coefficient_Pa", "Pa", "K in sigma_y = K (eps0 + eps_p)^n", &P::flow_coefficient_Pa},
      parameter<P>{"flow_offset", "-", "eps0 in the flow law", &P::flow_offset},
      parameter<P>{"flow_exponent", "-", "n in the flow law", &P::flow_exponent},
      parameter<P>{"radial_particles", "-", "particles along r at resolution 1", &P::radial_particles, 2},
      parameter<P>{"axial_particles", "-", "particles along z at resolution 1", &P::axial_particles, 2},
      parameter<P>{"support_factor", "-", "support a = factor x spacing", &P::support_factor},
      parameter<P>{"penalty_stiffness_N_m", "N/m", "stiffness of the penalty contact policy", &P::penalty_stiffness_N_m},
      parameter<P>{"slave_layers", "-", "contact slaves: the particles within this many cell layers of the surface (0: all)", &P::slave_layers, 0},
      parameter<P>{"tool_vertex_slaves", "0/1", "1: the tools' vertices are checked against the body's surface too", &P::tool_vertex_slaves},
      parameter<P>{"contact_depth_m", "m", "deepest penetration a tool face acts on", &P::contact_depth_m},
  };
};

struct wheel_forging {
  static constexpr std::string_view name = "wheel_forging";
  static constexpr std::string_view description = "axisymmetric wheel forging between a punch and a die (paper section 7)";
  using parameters = wheel_forging_parameters;
  using geometry_type = geometry::axisymmetric;
  using material_type = material::j2_plasticity<material::hardening::power_law>;

  static double end_time(const parameters& p) { return p.stroke_m / p.tool_velocity_m_s; }

  // Punch and die at t = 0 (m): the reconstruction of docs/method.md section 10.3.
  static std::vector<vec2> punch_outline() {
    return {vec2(-1e-3, 38e-3), vec2(10e-3, 38e-3), vec2(12e-3, 28e-3), vec2(24e-3, 28e-3),
            vec2(26e-3, 38e-3), vec2(34.5e-3, 38e-3)};
  }
  static std::vector<vec2> die_outline() { return {vec2(-1e-3, 0.0), vec2(35e-3, 0.0), vec2(35e-3, 45e-3)}; }

  template <class Contact>
  static problem<material_type, Contact> build(const parameters& p, int resolution) {
    require_positive("tool_velocity_m_s", p.tool_velocity_m_s);
    require_positive("stroke_m", p.stroke_m);
    require_positive("slug_radius_m", p.slug_radius_m);
    require_positive("slug_height_m", p.slug_height_m);
    if (!(p.stroke_m < p.slug_height_m)) fail("stroke_m = {} must be below the slug height {}", p.stroke_m, p.slug_height_m);
    if (!(p.slug_radius_m < 35e-3)) fail("slug_radius_m = {} must fit inside the die (35 mm)", p.slug_radius_m);
    require_positive("contact_depth_m", p.contact_depth_m);
    if (resolution < 1) fail("resolution {} must be a whole number >= 1", resolution);
    const Eigen::Vector2i n(refined_count(p.radial_particles, resolution), refined_count(p.axial_particles, resolution));
    const vec2 lo(0.0, 0.0), hi(p.slug_radius_m, p.slug_height_m);
    std::vector<contact::rigid_tool> tools{
        contact::rigid_tool("punch", punch_outline(), contact::side::right,
                            contact::tool_motion::constant_velocity(vec2(0.0, -p.tool_velocity_m_s)), p.contact_depth_m),
        contact::rigid_tool("die", die_outline(), contact::side::left, contact::tool_motion::fixed(), p.contact_depth_m)};
    problem<material_type, Contact> pr{
        .particles = make_grid_particles<2>(lo, hi, n, p.support_factor),
        .mesh = make_grid_mesh(lo, hi, n),
        .material = material_type({p.youngs_modulus_Pa, p.poisson_ratio, p.density_kg_m3},
                                  material::hardening::power_law{p.flow_coefficient_Pa, p.flow_offset, p.flow_exponent}),
        .contact = make_contact<Contact>(std::move(tools), p.friction, p.penalty_stiffness_N_m),
        .initial_velocity = {},
    };
    pr.contact.set_tool_vertex_slaves(p.tool_vertex_slaves);
    if (p.slave_layers == 0)
      for (index_t I = 0; I < pr.particles.size(); ++I) pr.slave_particles.push_back(I);
    else  // the particles are the mesh nodes; the axis r = 0 is not a surface
      pr.slave_particles = surface_layers(pr.mesh, p.slave_layers, [&](index_t I) { return pr.particles.position[I][0] <= 0.0; });
    return pr;
  }

  // Key measures at the solver's current time: penetration (mm), relative change of the
  // deformed volume sum_q J_q w_q, heights reached in the hub (r < 10 mm) and rim (r > 26 mm)
  // recesses, punch force (N, averaged over the last output interval).
  template <class Solver>
  static std::vector<std::pair<std::string, double>> measure(const Solver& s, const parameters& p,
                                                             const std::vector<vec2>& tool_force) {
    return measure_from(measure_maxima(s), measure_sums(s, p), s, p, tool_force);
  }
  // The heights' maxima over the solver's own particles, and the volumes' exact sums over its
  // own points: on several processes each rank takes its part's, and one maximum and one exact
  // sum combine them (tools/runner/row_reduction.hpp).
  template <class Solver>
  static std::array<double, 2> measure_maxima(const Solver& s) {
    std::array<double, 2> m{0.0, 0.0};  // hub, rim
    for (index_t I = s.model().own.particles.begin; I < s.model().own.particles.end; ++I) {
      const vec2 x = position_at_particle(s.model(), s.coefficients(), I);
      if (x[0] < 10e-3) m[0] = std::max(m[0], x[1]);
      if (x[0] > 26e-3) m[1] = std::max(m[1], x[1]);
    }
    return m;
  }
  template <class Solver>
  static std::array<exact_sum, 2> measure_sums(const Solver& s, const parameters&) {
    std::array<exact_sum, 2> v;  // sum_q w_q, sum_q J_q w_q
    const auto& w = s.model().points.weight;
    for_each_owned_point(s.model(), [&](index_t q) {
      v[0].add(w[q]);
      v[1].add(w[q] * s.point_det_F(q));
    });
    return v;
  }
  template <class Solver>
  static std::vector<std::pair<std::string, double>> measure_from(const std::array<double, 2>& m,
                                                                  const std::array<exact_sum, 2>& v, const Solver& s,
                                                                  const parameters&,
                                                                  const std::vector<vec2>& tool_force) {
    return {{"max_penetration_mm", s.max_penetration() * 1e3},
            {"volume_change", v[1].value() / v[0].value() - 1.0},
            {"hub_height_mm", m[0] * 1e3},
            {"rim_height_mm", m[1] * 1e3},
            {"punch_force_N", tool_force.empty() ? 0.0 : std::abs(tool_force[0][1])}};
  }
};

}  // namespace rkpm::cases
