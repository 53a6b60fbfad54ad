#pragma once
// The solver the benchmarks time: the Taylor bar of spec/paper.md section 5 (axisymmetric,
// J2 plasticity with linear hardening, the paper's contact enforcement against the rigid wall),
// built the way the runner builds it (tools/runner/dispatch.hpp): the discrete model for the
// kernel, correction and quadrature, then the dynamics of geometry, material and contact.
// Also a contact-free twin whose impact face rolls on the plane z = 0 (u_z = 0 there), which
// deforms almost as the frictionless wall does, to price the contact step by difference.

#include <memory>
#include <utility>

#include <rkpm/approximation/basis.hpp>
#include <rkpm/contact/none.hpp>
#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/discretization/quadrature_rules.hpp>
#include <rkpm/kernel/cubic_spline.hpp>
#include <rkpm/solver/discrete_model.hpp>
#include <rkpm/solver/dynamics.hpp>

#include "cases/taylor_bar.hpp"

namespace rkpm::bench {

using bar = cases::taylor_bar;
using wall_contact = contact::particle_to_segment<contact::enforcement::paper, contact::friction::frictionless>;
using wall_solver = dynamics<bar::geometry_type, bar::material_type, wall_contact>;
using free_solver = dynamics<bar::geometry_type, bar::material_type, contact::none>;

inline run_options bench_options() {
  run_options o;
  o.end_time = bar::end_time(bar::parameters{});
  return o;
}

template <class Q>
discrete_model bar_model(const problem<bar::material_type, wall_contact>& p) {
  return build_discrete_model<kernel::cubic_spline, correction::linear, Q, bar::geometry_type>(
      p.particles, p.mesh, bench_options().max_moment_condition);
}

// dynamics is neither copyable nor movable (contact keeps pointers into it): built in place.
template <class Q>
std::unique_ptr<wall_solver> make_wall_solver(int resolution) {
  auto p = bar::build<wall_contact>(bar::parameters{}, resolution);
  auto model = bar_model<Q>(p);
  return std::make_unique<wall_solver>(std::move(model), std::move(p), bench_options());
}

// Same particles, cells, material and initial velocity; no contact policy, instead the
// impact-face particles are held at u_z = 0 (r stays free, like the frictionless wall).
template <class Q>
std::unique_ptr<free_solver> make_rolling_solver(int resolution) {
  auto p = bar::build<wall_contact>(bar::parameters{}, resolution);
  auto model = bar_model<Q>(p);
  problem<bar::material_type, contact::none> q{
      .particles = std::move(p.particles),
      .mesh = std::move(p.mesh),
      .material = std::move(p.material),
      .contact = {},
      .initial_velocity = std::move(p.initial_velocity),
  };
  for (index_t I = 0; I < q.particles.size(); ++I)
    if (q.particles.position[I][1] <= 1e-12) q.constraints.push_back({I, 1, {}});
  return std::make_unique<free_solver>(std::move(model), std::move(q), bench_options());
}

// Steps taken before timing, 200 per unit of resolution (the step shrinks with the spacing), so
// that every resolution is timed at about the same moment of the impact: the bar starts on the
// wall, so contact is active from the first step, and by then a plastic zone has formed.
inline int warm_up_steps(int resolution) { return 200 * resolution; }

}  // namespace rkpm::bench
