#pragma once
// Case 2 of the paper (docs/method.md section 10.2): plane-strain forging of a square block.
// A 500 mm x 500 mm copper block (21 x 21 particles) between two flat rigid tools 1300 mm wide
// that move toward each other at 10 m/s each, Coulomb friction 0.2, for 0.015 s: 300 mm of
// closure, 60% reduction. Forces are per metre of depth.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <rkpm/contact/rigid_tool.hpp>
#include <rkpm/discretization/background_mesh.hpp>
#include <rkpm/discretization/particle_set.hpp>
#include <rkpm/geometry/plane_strain.hpp>
#include <rkpm/material/j2_plasticity.hpp>
#include <rkpm/solver/fields.hpp>
#include <rkpm/solver/problem.hpp>

#include "cases/contact_setup.hpp"
#include "cases/parameters.hpp"

namespace rkpm::cases {

struct block_forging_parameters {
  double tool_velocity_m_s = 10.0;
  double width_m = 0.5;
  double height_m = 0.5;
  double tool_width_m = 1.3;
  double friction = 0.2;
  double youngs_modulus_Pa = 117e9;
  double poisson_ratio = 0.35;
  double density_kg_m3 = 8930.0;
  double yield_stress_Pa = 400e6;
  double hardening_modulus_Pa = 100e6;
  double end_time_s = 0.015;
  int particles_per_side = 21;
  double support_factor = 2.0;
  double penalty_stiffness_N_m = 1e12;

  using P = block_forging_parameters;
  static constexpr std::array fields = {
      parameter<P>{"tool_velocity_m_s", "m/s", "speed of each tool toward the other", &P::tool_velocity_m_s},
      parameter<P>{"width_m", "m", "initial block width", &P::width_m},
      parameter<P>{"height_m", "m", "initial block height", &P::height_m},
      parameter<P>{"tool_width_m", "m", "width of the flat tools", &P::tool_width_m},
      parameter<P>{"friction", "-", "Coulomb coefficient on both tools", &P::friction},
      parameter<P>{"youngs_modulus_Pa", "Pa", "Young's modulus", &P::youngs_modulus_Pa},
      parameter<P>{"poisson_ratio", "-", "Poisson's ratio", &P::poisson_ratio},
      parameter<P>{"density_kg_m3", "kg/m^3", "density", &P::density_kg_m3},
      parameter<P>{"yield_stress_Pa", "Pa", "initial yield stress", &P::yield_stress_Pa},
      parameter<P>{"hardening_modulus_Pa", "Pa", "linear hardening modulus H", &P::hardening_modulus_Pa},
      parameter<P>{"end_time_s", "s", "simulated time", &P::end_time_s},
      parameter<P>{"particles_per_side", "-", "particles per side at resolution 1", &P::particles_per_side, 2},
      parameter<P>{"support_factor", "-", "support a = factor x spacing", &P::support_factor},
      parameter<P>{"penalty_stiffness_N_m", "N/m", "stiffness of the penalty contact policy", &P::penalty_stiffness_N_m},
  };
};

struct block_forging {
  static constexpr std::string_view name = "block_forging";
  static constexpr std::string_view description = "plane-strain forging of a square block between flat tools (paper section 6)";
  using parameters = block_forging_parameters;
  using geometry_type = geometry::plane_strain;
  using material_type = material::j2_plasticity<material::hardening::linear>;

  static double end_time(const parameters& p) { return p.end_time_s; }
  // Tool gap at time t.
  static double gap(const parameters& p, double t) { return p.height_m - 2.0 * p.tool_velocity_m_s * t; }

  template <class Contact>
  static problem<material_type, Contact> build(const parameters& p, int resolution) {
    require_positive("tool_velocity_m_s", p.tool_velocity_m_s);
    require_positive("width_m", p.width_m);
    require_positive("height_m", p.height_m);
    require_positive("end_time_s", p.end_time_s);
    if (!(p.tool_width_m > p.width_m)) fail("tool_width_m = {} must exceed the block width {}", p.tool_width_m, p.width_m);
    if (!(gap(p, p.end_time_s) > 0.0))
      fail("the tools would meet before end_time_s = {} s: shorten it below {} s", p.end_time_s,
           p.height_m / (2.0 * p.tool_velocity_m_s));
    if (resolution < 1) fail("resolution {} must be a whole number >= 1", resolution);
    const int n = refined_count(p.particles_per_side, resolution);
    const vec2 lo(-0.5 * p.width_m, 0.0), hi(0.5 * p.width_m, p.height_m);
    const double w = 0.5 * p.tool_width_m, v = p.tool_velocity_m_s;
    std::vector<contact::rigid_tool> tools{
        contact::rigid_tool("bottom_tool", {vec2(-w, 0.0), vec2(w, 0.0)}, contact::side::left,
                            contact::tool_motion::constant_velocity(vec2(0.0, v))),
        contact::rigid_tool("top_tool", {vec2(w, p.height_m), vec2(-w, p.height_m)}, contact::side::left,
                            contact::tool_motion::constant_velocity(vec2(0.0, -v)))};
    problem<material_type, Contact> pr{
        .particles = make_grid_particles<2>(lo, hi, Eigen::Vector2i(n, n), p.support_factor),
        .mesh = make_grid_mesh(lo, hi, Eigen::Vector2i(n, n)),
        .material = material_type({p.youngs_modulus_Pa, p.poisson_ratio, p.density_kg_m3},
                                  material::hardening::linear{p.yield_stress_Pa, p.hardening_modulus_Pa}),
        .contact = make_contact<Contact>(std::move(tools), p.friction, p.penalty_stiffness_N_m),
        .initial_velocity = {},
    };
    return pr;
  }

  // Key measures at the solver's current time: tool gap (the block's height), body width,
  // largest penetration so far (mm) and the reaction of the top tool per metre of depth,
  // averaged over the last output interval.
  template <class Solver>
  static std::vector<std::pair<std::string, double>> measure(const Solver& s, const parameters& p,
                                                             const std::vector<vec2>& tool_force) {
    return measure_from(measure_maxima(s), s, p, tool_force);
  }
  // The measures' maxima over the solver's own particles: the largest x and minus the smallest.
  // On several processes each rank takes its part's and one maximum combines them
  // (tools/runner/row_reduction.hpp); the penetration is the same on every rank.
  template <class Solver>
  static std::array<double, 2> measure_maxima(const Solver& s) {
    constexpr double none = -std::numeric_limits<double>::infinity();
    std::array<double, 2> m{none, none};
    for (index_t I = s.model().own.particles.begin; I < s.model().own.particles.end; ++I) {
      const vec2 x = position_at_particle(s.model(), s.coefficients(), I);
      m[0] = std::max(m[0], x[0]);
      m[1] = std::max(m[1], -x[0]);
    }
    return m;
  }
  template <class Solver>
  static std::vector<std::pair<std::string, double>> measure_from(const std::array<double, 2>& m, const Solver& s,
                                                                  const parameters& p,
                                                                  const std::vector<vec2>& tool_force) {
    const double hi = m[0], lo = -m[1];
    return {{"tool_gap_mm", gap(p, s.time()) * 1e3},
            {"width_mm", (hi - lo) * 1e3},
            {"max_penetration_mm", s.max_penetration() * 1e3},
            {"tool_force_N_per_m", tool_force.size() > 1 ? std::abs(tool_force[1][1]) : 0.0}};
  }
};

}  // namespace rkpm::cases
