#pragma once
// The bodies' initial velocity and body force in the problem a case file builds
// (build_problem.hpp). Numbers give what they always gave: one velocity function, or one per
// body, and problem::body_force. Expressions (read_expressions.hpp) are evaluated here at every
// particle's reference position, once for the initial velocity (problem::initial_particle_velocity)
// and at t = 0 for the body force, whose problem::body_force_field the solver then evaluates
// each step; a value that is not finite is refused with its body's pointer and the point.

#include <algorithm>
#include <array>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>

#include "case_description.hpp"
#include "diagnostics.hpp"
#include "vector_expression.hpp"

namespace rkpm::runner::case_file {

namespace detail {

inline std::string at_point(const vec2& X) { return fmt::format("the reference point ({:.6g}, {:.6g}) m", X.x(), X.y()); }

}  // namespace detail

// Body k's particles are start[k] to start[k + 1] - 1 of pr.particles.
template <class Problem>
void set_initial_velocity(const case_description& c, Problem& pr, const std::vector<index_t>& start) {
  const body_description& first = c.bodies.front();
  const bool expressions = std::any_of(c.bodies.begin(), c.bodies.end(),
                                       [](const body_description& b) { return b.initial_velocity.varies(); });
  const bool one_velocity = std::all_of(c.bodies.begin(), c.bodies.end(), [&](const body_description& b) {
    return b.initial_velocity.value == first.initial_velocity.value;
  });
  if (!expressions && one_velocity) {
    if (first.initial_velocity.value != vec2::Zero())
      pr.initial_velocity = [v = first.initial_velocity.value](const vec2&) { return v; };
    return;
  }
  if (!expressions) {
    std::vector<vec2> v0;
    for (const auto& b : c.bodies) v0.push_back(b.initial_velocity.value);
    pr.initial_particle_velocity = [v0, start](index_t I, const vec2&) {
      const auto k = std::upper_bound(start.begin(), start.end(), I) - start.begin() - 1;
      return v0[static_cast<std::size_t>(k)];
    };
    return;
  }
  // Expressions of x, y: evaluated once per particle, here.
  auto v0 = std::make_shared<std::vector<vec2>>(pr.particles.size(), vec2::Zero());
  for (std::size_t k = 0; k < c.bodies.size(); ++k) {
    const vector_field& field = c.bodies[k].initial_velocity;
    if (!field.varies()) {
      std::fill(v0->begin() + start[k], v0->begin() + start[k + 1], field.value);
      continue;
    }
    const vector_expression velocity(field, position_variables(), c.constants);
    for (index_t I = start[k]; I < start[k + 1]; ++I) {
      const vec2& X = pr.particles.position[I];
      (*v0)[I] = velocity(std::array{X.x(), X.y()});
      if (const auto bad = velocity.not_finite((*v0)[I], detail::at_point(X), "make it finite over the body"))
        fail_in_file(c.file.string(), bad->first, bad->second);
    }
  }
  pr.initial_particle_velocity = [v0 = std::shared_ptr<const std::vector<vec2>>(v0)](index_t I, const vec2&) {
    return (*v0)[I];
  };
}

// One body force for all bodies (build_problem.hpp refuses others): problem::body_force, or for
// expressions of x, y, t problem::body_force_field, checked at every particle at t = 0.
template <class Problem>
void set_body_force(const case_description& c, Problem& pr) {
  const vector_field& field = c.bodies.front().body_force;
  pr.body_force = field.value;
  if (!field.varies()) return;
  const auto force = std::make_shared<const vector_expression>(field, position_time_variables(), c.constants);
  for (const vec2& X : pr.particles.position)
    if (const auto bad = force->not_finite((*force)(std::array{X.x(), X.y(), 0.0}), detail::at_point(X) + " at t = 0 s",
                                           "make it finite over the body"))
      fail_in_file(c.file.string(), bad->first, bad->second);
  // Later times are checked as the solver reaches them: the run stops with the same line.
  pr.body_force_field = [force, file = c.file.string()](const vec2& X, double t) {
    const vec2 b = (*force)(std::array{X.x(), X.y(), t});
    if (const auto bad = force->not_finite(b, fmt::format("{} at t = {:.9g} s", detail::at_point(X), t),
                                           "make it finite over the body and the run"))
      throw rkpm::error(fmt::format("{}: {}: {}", file, bad->first, bad->second));
    return b;
  };
}

}  // namespace rkpm::runner::case_file
