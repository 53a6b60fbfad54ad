#pragma once
// The solver the benchmarks time: the Taylor bar of docs/method.md section 10.1 (axisymmetric,
// J2 plasticity with linear hardening, the paper's contact enforcement against the rigid wall),
// built by make_solver as everything else builds it. Also a contact-free twin whose impact
// face rolls on the plane z = 0 (u_z = 0 there), which deforms almost as the frictionless wall
// does, to price the contact step by difference.

#include <utility>

#include <rkpm/contact/none.hpp>
#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/correction/polynomial_bases.hpp>
#include <rkpm/kernel/cubic_spline.hpp>
#include <rkpm/material/johnson_cook.hpp>
#include <rkpm/material/zerilli_armstrong.hpp>
#include <rkpm/quadrature/cell_rules.hpp>
#include <rkpm/solver/make_solver.hpp>

#include "cases/taylor_bar.hpp"

namespace rkpm::bench {

using bar = cases::taylor_bar;
using wall_contact = contact::particle_to_segment<contact::enforcement::paper, contact::friction::frictionless>;
template <class Q>
using wall_method = config<kernel::cubic_spline, correction::linear, Q, bar::geometry_type, bar::material_type, wall_contact>;
template <class Q>
using rolling_method = typename wall_method<Q>::template with_contact<contact::none>;

inline run_options bench_options() {
  run_options o;
  o.end_time = bar::end_time(bar::parameters{});
  return o;
}

// The discrete model alone (the set-up benchmark prices it apart from the solver).
template <class Q>
discrete_model bar_model(const problem<bar::material_type, wall_contact>& p) {
  return build_discrete_model<kernel::cubic_spline, correction::linear, Q, bar::geometry_type>(
      p.particles, p.mesh, bench_options().max_moment_condition);
}

template <class Q>
solver_for<wall_method<Q>> make_wall_solver(int resolution) {
  return make_solver<wall_method<Q>>(bar::build<wall_contact>(bar::parameters{}, resolution), bench_options());
}

// Same particles, cells, material and initial velocity; no contact policy, instead the
// impact-face particles are held at u_z = 0 (r stays free, like the frictionless wall).
template <class Q>
solver_for<rolling_method<Q>> make_rolling_solver(int resolution) {
  auto p = bar::build<wall_contact>(bar::parameters{}, resolution);
  problem<bar::material_type, contact::none> q{
      .particles = std::move(p.particles),
      .mesh = std::move(p.mesh),
      .material = std::move(p.material),
      .contact = {},
      .initial_velocity = std::move(p.initial_velocity),
  };
  for (index_t I = 0; I < q.particles.size(); ++I)
    if (q.particles.position[I][1] <= 1e-12) q.constraints.push_back({I, 1, {}});
  return make_solver<rolling_method<Q>>(std::move(q), bench_options());
}

// The same bar with Johnson-Cook plasticity whose curve at the reference rate and room
// temperature is the case's J2 curve (A = yield stress, B = hardening modulus, n = 1), with
// OFHC copper's rate and thermal terms (C = 0.025, m = 1.09, T_melt = 1356 K, c_p = 383
// J/(kg K); G. R. Johnson, W. H. Cook, 7th Int. Symp. on Ballistics, 1983, Table 1), so that
// a step of each prices the material update on about the same plastic zone.
template <class Q>
using johnson_cook_method = typename wall_method<Q>::template with_material<material::johnson_cook>;

template <class Q>
solver_for<johnson_cook_method<Q>> make_johnson_cook_solver(int resolution) {
  const bar::parameters b{};
  auto p = bar::build<wall_contact>(b, resolution);
  problem<material::johnson_cook, wall_contact> q{
      .particles = std::move(p.particles),
      .mesh = std::move(p.mesh),
      .material = material::johnson_cook(
          p.material.constants(),
          material::hardening::johnson_cook{.A = b.yield_stress_Pa, .B = b.hardening_modulus_Pa, .n = 1.0,
                                            .C = 0.025, .reference_rate = 1.0, .m = 1.09,
                                            .room_temperature = 294.0, .melt_temperature = 1356.0},
          material::johnson_cook_heating{.specific_heat = 383.0}),
      .contact = std::move(p.contact),
      .initial_velocity = std::move(p.initial_velocity),
  };
  return make_solver<johnson_cook_method<Q>>(std::move(q), bench_options());
}

// The same bar with Zerilli-Armstrong fcc plasticity (docs/method.md section 4.6): the athermal
// stress C0 is the case's yield stress, so that the same points yield first, with OFHC copper's
// hardening, thermal and rate constants (C2 = 890 MPa, C3 = 0.0028 /K, C4 = 0.000115 /K; Zerilli &
// Armstrong, J. Appl. Phys. 61 (1987) 1816) and heating (c_p = 383 J/(kg K), 294 K at the start).
template <class Q>
using zerilli_armstrong_method = typename wall_method<Q>::template with_material<material::zerilli_armstrong>;

template <class Q>
solver_for<zerilli_armstrong_method<Q>> make_zerilli_armstrong_solver(int resolution) {
  const bar::parameters b{};
  auto p = bar::build<wall_contact>(b, resolution);
  using za = material::hardening::zerilli_armstrong;
  problem<material::zerilli_armstrong, wall_contact> q{
      .particles = std::move(p.particles),
      .mesh = std::move(p.mesh),
      .material = material::zerilli_armstrong(
          p.material.constants(),
          za{.lattice = za::lattice_type::fcc, .C0 = b.yield_stress_Pa, .C1 = 0.0, .C2 = 890e6, .C3 = 0.0028,
             .C4 = 0.000115, .C5 = 0.0, .n = 0.0, .reference_rate = 1.0, .melt_temperature = 1356.0},
          material::zerilli_armstrong_heating{.specific_heat = 383.0, .initial_temperature = 294.0}),
      .contact = std::move(p.contact),
      .initial_velocity = std::move(p.initial_velocity),
  };
  return make_solver<zerilli_armstrong_method<Q>>(std::move(q), bench_options());
}

// Steps taken before timing, 200 per unit of resolution (the step shrinks with the spacing), so
// that every resolution is timed at about the same moment of the impact: the bar starts on the
// wall, so contact is active from the first step, and by then a plastic zone has formed.
inline int warm_up_steps(int resolution) { return 200 * resolution; }

}  // namespace rkpm::bench
