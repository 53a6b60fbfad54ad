#pragma once
// Case 1 of the paper (docs/method.md section 10.1): Taylor bar impact, axisymmetric.
// A copper cylinder (R0 = 3.2 mm, L0 = 32.4 mm) hits a rigid frictionless wall at 227 m/s;
// half of the (r, z) section, 21 x 51 particles, 80 microseconds. The paper's Table 3 gives
// the final radius of the impact face and the final height. Parameters are SI; results are
// reported in millimetres, as the paper does.

#include <algorithm>
#include <array>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <rkpm/contact/rigid_tool.hpp>
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

// The copper of the Taylor bar (the paper's Table 2), shared by the cases that use it.
struct taylor_copper {
  double youngs_modulus_Pa = 117e9;
  double poisson_ratio = 0.35;
  double density_kg_m3 = 8930.0;
  double yield_stress_Pa = 400e6;
  double hardening_modulus_Pa = 100e6;

  template <class P>
  static constexpr std::array<parameter<P>, 5> fields() {
    return {parameter<P>{"youngs_modulus_Pa", "Pa", "Young's modulus", &P::youngs_modulus_Pa},
            parameter<P>{"poisson_ratio", "-", "Poisson's ratio", &P::poisson_ratio},
            parameter<P>{"density_kg_m3", "kg/m^3", "density", &P::density_kg_m3},
            parameter<P>{"yield_stress_Pa", "Pa", "initial yield stress", &P::yield_stress_Pa},
            parameter<P>{"hardening_modulus_Pa", "Pa", "linear hardening modulus H", &P::hardening_modulus_Pa}};
  }
  material::j2_plasticity<material::hardening::linear> material() const {
    return material::j2_plasticity<material::hardening::linear>(
        {youngs_modulus_Pa, poisson_ratio, density_kg_m3},
        material::hardening::linear{yield_stress_Pa, hardening_modulus_Pa});
  }
};

struct taylor_bar_parameters : taylor_copper {
  double velocity_m_s = 227.0;
  double radius_m = 3.2e-3;
  double height_m = 32.4e-3;
  double friction = 0.0;
  double end_time_s = 80e-6;
  int radial_particles = 21;
  int axial_particles = 51;
  double support_factor = 2.0;
  double penalty_stiffness_N_m = 1e11;
  double wall_extent = 8.0;  // the wall reaches from r = -R0 to r = wall_extent R0
  int slave_layers = 1;      // 1: the boundary particles (the problem's default slaves)

  using P = taylor_bar_parameters;
  static constexpr auto fields = join_fields<P>(
      std::array{parameter<P>{"velocity_m_s", "m/s", "impact velocity", &P::velocity_m_s},
                 parameter<P>{"radius_m", "m", "initial radius R0", &P::radius_m},
                 parameter<P>{"height_m", "m", "initial height L0", &P::height_m}},
      taylor_copper::fields<P>(),
      std::array{
          parameter<P>{"friction", "-", "Coulomb coefficient at the wall", &P::friction},
          parameter<P>{"end_time_s", "s", "simulated time", &P::end_time_s},
          parameter<P>{"radial_particles", "-", "particles along r at resolution 1", &P::radial_particles, 2},
          parameter<P>{"axial_particles", "-", "particles along z at resolution 1", &P::axial_particles, 2},
          parameter<P>{"support_factor", "-", "support a = factor x spacing", &P::support_factor},
          parameter<P>{"penalty_stiffness_N_m", "N/m", "stiffness of the penalty contact policy",
                       &P::penalty_stiffness_N_m},
          parameter<P>{"wall_extent", "-", "the wall reaches from r = -R0 to this many R0 (a face that spreads "
                       "past it at high speed needs more)", &P::wall_extent},
          parameter<P>{"slave_layers", "-", "contact slaves: 1 the boundary particles, k the particles within k "
                       "cell layers of the surface, 0 every particle (a face that spreads so far that the rows "
                       "behind it reach the wall between its particles)", &P::slave_layers, 0}});
};

struct taylor_bar {
  static constexpr std::string_view name = "taylor_bar";
  static constexpr std::string_view description = "Taylor bar impact on a rigid wall (axisymmetric, paper section 5)";
  using parameters = taylor_bar_parameters;
  using geometry_type = geometry::axisymmetric;
  using material_type = material::j2_plasticity<material::hardening::linear>;

  // The paper's Table 3 (RKPM rows), in mm.
  static constexpr double paper_radius_q4_mm = 7.06, paper_height_q4_mm = 21.58;
  static constexpr double paper_radius_q2_mm = 7.11, paper_height_q2_mm = 21.59;

  static double end_time(const parameters& p) { return p.end_time_s; }

  template <class Contact>
  static problem<material_type, Contact> build(const parameters& p, int resolution) {
    require_positive("velocity_m_s", p.velocity_m_s);
    require_positive("radius_m", p.radius_m);
    require_positive("height_m", p.height_m);
    require_positive("end_time_s", p.end_time_s);
    require_positive("wall_extent", p.wall_extent);
    if (resolution < 1) fail("resolution {} must be a whole number >= 1", resolution);
    const Eigen::Vector2i n(refined_count(p.radial_particles, resolution), refined_count(p.axial_particles, resolution));
    const vec2 lo(0.0, 0.0), hi(p.radius_m, p.height_m);
    problem<material_type, Contact> pr{
        .particles = make_grid_particles<2>(lo, hi, n, p.support_factor),
        .mesh = make_grid_mesh(lo, hi, n),
        .material = p.material(),
        .contact = make_contact<Contact>(
            {contact::rigid_tool("wall", {vec2(-p.radius_m, 0.0), vec2(p.wall_extent * p.radius_m, 0.0)},
                                 contact::side::left, contact::tool_motion::fixed())},
            p.friction, p.penalty_stiffness_N_m),
        .initial_velocity = [v = p.velocity_m_s](const vec2&) { return vec2(0.0, -v); },
    };
    if (p.slave_layers == 0)
      for (index_t I = 0; I < pr.particles.size(); ++I) pr.slave_particles.push_back(I);
    else if (p.slave_layers > 1)  // the particles are the mesh nodes; the axis r = 0 is not a surface
      pr.slave_particles = surface_layers(pr.mesh, p.slave_layers, [&](index_t I) { return pr.particles.position[I][0] <= 0.0; });
    return pr;
  }

  // Key measures at the solver's current time (mm): the largest radius of the impact face
  // (particles that started on it), the height (largest z), the length (largest minus smallest
  // z: what experiments and other codes report, since the bar lifts off the wall after the
  // impact and the height then exceeds it) and the largest equivalent plastic strain.
  template <class Solver>
  static std::vector<std::pair<std::string, double>> measure(const Solver& s, const parameters& p,
                                                             const std::vector<vec2>& tool_force) {
    return measure_from(measure_maxima(s), s, p, tool_force);
  }
  // The measures' maxima over the solver's own particles and its points: the radius, the
  // height, minus the lowest z, the plastic strain. On several processes each rank takes its
  // part's and one maximum combines them (tools/runner/row_reduction.hpp).
  template <class Solver>
  static std::array<double, 4> measure_maxima(const Solver& s) {
    const auto& X = s.initial_positions();
    std::array<double, 4> m{0.0, 0.0, -std::numeric_limits<double>::infinity(), 0.0};
    for (index_t I = s.model().own.particles.begin; I < s.model().own.particles.end; ++I) {
      const vec2 x = position_at_particle(s.model(), s.coefficients(), I);
      if (X[I][1] <= 1e-12) m[0] = std::max(m[0], x[0]);
      m[1] = std::max(m[1], x[1]);
      m[2] = std::max(m[2], -x[1]);
    }
    for (const auto& st : s.point_states()) m[3] = std::max(m[3], st.equivalent_plastic_strain);
    return m;
  }
  template <class Solver>
  static std::vector<std::pair<std::string, double>> measure_from(const std::array<double, 4>& m, const Solver&,
                                                                  const parameters&,
                                                                  const std::vector<vec2>& /*tool_force*/) {
    const double radius = m[0], height = m[1], lowest = -m[2];
    return {{"radius_mm", radius * 1e3},
            {"height_mm", height * 1e3},
            {"length_mm", (height - lowest) * 1e3},
            {"max_equivalent_plastic_strain", m[3]}};
  }
};

}  // namespace rkpm::cases
