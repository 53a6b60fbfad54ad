#pragma once
// Beyond the paper: two coaxial copper rods with the Taylor bar's data meet head on
// (docs/method.md section 6.9), axisymmetric. The lower rod (z from -lower_height to 0) moves
// up and the upper rod (z from 0 to upper_height) down, each at velocity_m_s; they touch at
// z = 0 at t = 0. Contact is between the two deformable bodies: each rod is slave against the
// other in turn (two_pass = 1, the default), or, with two_pass = 0, the upper rod's particles
// are slaves against the lower rod's surface (the paper's slave and master bodies; the slave on
// the axis then escapes the master's last segment, docs/method.md section 6.9). By
// symmetry the contact plane of two identical rods is a frictionless rigid wall, so the default
// case reproduces taylor_bar. Parameters SI; results in millimetres.

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <rkpm/contact/body_contact.hpp>
#include <rkpm/core/exact_sum.hpp>
#include <rkpm/discretization/body_partition.hpp>
#include <rkpm/discretization/background_mesh.hpp>
#include <rkpm/discretization/particle_set.hpp>
#include <rkpm/geometry/axisymmetric.hpp>
#include <rkpm/material/j2_plasticity.hpp>
#include <rkpm/solver/fields.hpp>
#include <rkpm/solver/problem.hpp>

#include "cases/contact_setup.hpp"
#include "cases/parameters.hpp"
#include "cases/taylor_bar.hpp"

namespace rkpm::cases {

struct rod_on_rod_parameters : taylor_copper {
  double velocity_m_s = 227.0;
  double radius_m = 3.2e-3;
  double lower_height_m = 32.4e-3;
  double upper_height_m = 32.4e-3;
  double friction = 0.0;
  double end_time_s = 80e-6;
  int radial_particles = 21;
  int axial_particles = 51;
  double support_factor = 2.0;
  double penalty_stiffness_N_m = 1e11;
  bool two_pass = true;

  using P = rod_on_rod_parameters;
  static constexpr auto fields = join_fields<P>(
      std::array{parameter<P>{"velocity_m_s", "m/s", "speed of each rod toward the other", &P::velocity_m_s},
                 parameter<P>{"radius_m", "m", "radius of both rods", &P::radius_m},
                 parameter<P>{"lower_height_m", "m", "height of the lower rod", &P::lower_height_m},
                 parameter<P>{"upper_height_m", "m", "height of the upper rod", &P::upper_height_m}},
      taylor_copper::fields<P>(),
      std::array{
          parameter<P>{"friction", "-", "Coulomb coefficient between the rods", &P::friction},
          parameter<P>{"end_time_s", "s", "simulated time", &P::end_time_s},
          parameter<P>{"radial_particles", "-", "particles along r at resolution 1", &P::radial_particles, 2},
          parameter<P>{"axial_particles", "-",
                       "particles along z of the lower rod at resolution 1 (the upper rod at the same spacing)",
                       &P::axial_particles, 2},
          parameter<P>{"support_factor", "-", "support a = factor x spacing", &P::support_factor},
          parameter<P>{"penalty_stiffness_N_m", "N/m", "stiffness of the penalty contact policy",
                       &P::penalty_stiffness_N_m},
          parameter<P>{"two_pass", "-",
                       "1: each rod slave against the other; 0: the upper rod's particles against the lower rod only",
                       &P::two_pass}});
};

struct rod_on_rod {
  static constexpr std::string_view name = "rod_on_rod";
  static constexpr std::string_view description =
      "two rods meeting head on, contact between deformable bodies (axisymmetric, beyond the paper)";
  using parameters = rod_on_rod_parameters;
  using geometry_type = geometry::axisymmetric;
  using material_type = material::j2_plasticity<material::hardening::linear>;

  static double end_time(const parameters& p) { return p.end_time_s; }

  template <class Contact>
  static problem<material_type, Contact> build(const parameters& p, int resolution) {
    for (const auto& [label, value] : {std::pair{"velocity_m_s", p.velocity_m_s}, {"radius_m", p.radius_m},
                                       {"lower_height_m", p.lower_height_m}, {"upper_height_m", p.upper_height_m},
                                       {"end_time_s", p.end_time_s}})
      require_positive(label, value);
    if (resolution < 1) fail("resolution {} must be a whole number >= 1", resolution);
    const int nr = refined_count(p.radial_particles, resolution);
    const int n_lower = refined_count(p.axial_particles, resolution);
    const double h = p.lower_height_m / (n_lower - 1);
    const int n_upper = std::max(2, static_cast<int>(std::lround(p.upper_height_m / h)) + 1);
    particle_set<2> particles;
    background_mesh mesh;
    const auto add_rod = [&](const vec2& lo, const vec2& hi, int axial) {
      const Eigen::Vector2i n(nr, axial);
      append_body(particles, mesh, make_grid_particles<2>(lo, hi, n, p.support_factor), make_grid_mesh(lo, hi, n));
    };
    add_rod(vec2(0.0, -p.lower_height_m), vec2(p.radius_m, 0.0), n_lower);
    add_rod(vec2(0.0, 0.0), vec2(p.radius_m, p.upper_height_m), n_upper);
    // Bodies are numbered by their first cells: 0 the lower rod, 1 the upper.
    std::vector<contact::body_pair> pairs{{1, 0}};
    if (p.two_pass) pairs.push_back({0, 1});
    const double v = p.velocity_m_s;
    return problem<material_type, Contact>{
        .particles = std::move(particles),
        .mesh = std::move(mesh),
        .material = p.material(),
        .contact = make_contact<Contact>({}, p.friction, p.penalty_stiffness_N_m, std::move(pairs)),
        // The lower rod's particles lie at z <= 0, the upper's at z >= 0; the two rows at z = 0
        // are told apart by their index (the upper rod's come second).
        .initial_particle_velocity = [v, lower = static_cast<index_t>(nr * n_lower)](index_t I, const vec2&) {
          return vec2(0.0, I < lower ? v : -v);
        },
    };
  }

  // Measures at the solver's current time (mm): each rod's height (extent in z) and the largest
  // radius of the particles that started on its impact face (z = 0), the deepest penetration
  // found so far, and the change of the total axial momentum relative to sum m |v0|.
  template <class Solver>
  static std::vector<std::pair<std::string, double>> measure(const Solver& s, const parameters& p,
                                                             const std::vector<vec2>& tool_force) {
    return measure_from(measure_maxima(s), measure_sums(s, p), s, p, tool_force);
  }
  // Per rod, the maxima over the solver's own particles of z, -z and the face's radius; the
  // exact sums over them of the axial momentum's change and of m |v0|: on several processes each
  // rank takes its part's, and one maximum and one exact sum combine them
  // (tools/runner/row_reduction.hpp).
  template <class Solver>
  static std::array<double, 6> measure_maxima(const Solver& s) {
    const auto& X = s.initial_positions();
    std::array<double, 6> m{-1e300, -1e300, -1e300, -1e300, 0.0, 0.0};  // zmax, -zmin, radius per rod
    for (index_t I = s.model().own.particles.begin; I < s.model().own.particles.end; ++I) {
      const vec2 x = position_at_particle(s.model(), s.coefficients(), I);
      const auto b = static_cast<std::size_t>(s.body_of_particle(I));
      m[b] = std::max(m[b], x[1]);
      m[2 + b] = std::max(m[2 + b], -x[1]);
      if (std::abs(X[I][1]) <= 1e-12) m[4 + b] = std::max(m[4 + b], x[0]);  // on the face, to round-off
    }
    return m;
  }
  template <class Solver>
  static std::array<exact_sum, 2> measure_sums(const Solver& s, const parameters& p) {
    std::array<exact_sum, 2> sum;  // sum m (v - v0), sum m |v0|
    for (index_t I = s.model().own.particles.begin; I < s.model().own.particles.end; ++I) {
      const double m = s.mass()[I];
      sum[0].add(m * s.coefficient_velocities()[I][1]);
      sum[0].add(-(m * (s.body_of_particle(I) == 0 ? p.velocity_m_s : -p.velocity_m_s)));
      sum[1].add(m * p.velocity_m_s);
    }
    return sum;
  }
  template <class Solver>
  static std::vector<std::pair<std::string, double>> measure_from(const std::array<double, 6>& m,
                                                                  const std::array<exact_sum, 2>& sum, const Solver& s,
                                                                  const parameters&,
                                                                  const std::vector<vec2>& /*tool_force*/) {
    return {{"lower_final_height_mm", (m[0] + m[2]) * 1e3},
            {"upper_final_height_mm", (m[1] + m[3]) * 1e3},
            {"lower_final_radius_mm", m[4] * 1e3},
            {"upper_final_radius_mm", m[5] * 1e3},
            {"max_penetration_mm", s.max_penetration() * 1e3},
            {"momentum_error", std::abs(sum[0].value()) / sum[1].value()}};
  }
};

}  // namespace rkpm::cases
