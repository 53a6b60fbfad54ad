#pragma once
// Contact: what the explicit solver calls on a contact policy (spec/paper.md section 3,
// design.md section 4 "Contact"): setup(body) once, enforce(t_next, dt, d, v) every step
// (correcting d_{n+1} and v_{n+1/2} in place, no heap allocation) and tools() for output.
// ContactEnforcement and FrictionLaw are the building blocks of contact::particle_to_segment.

#include <concepts>
#include <string_view>
#include <vector>

#include <rkpm/contact/body_view.hpp>
#include <rkpm/core/types.hpp>

namespace rkpm {

template <class C>
concept Contact = requires(C& c, const contact::body_view& b, double t, double dt, std::vector<vec2>& d,
                           std::vector<vec2>& v) {
  { C::name } -> std::convertible_to<std::string_view>;
  c.setup(b);
  { c.enforce(t, dt, d, v) } -> std::same_as<contact::step_result>;
  { c.tools() };
};

template <class E>
concept ContactEnforcement = requires(const E& e, double g, double dt, double m) {
  { E::name } -> std::convertible_to<std::string_view>;
  { e.sweeps } -> std::convertible_to<int>;
  { e.relaxation } -> std::convertible_to<double>;
  { e.normal_force(g, dt, m, m) } -> std::same_as<double>;
  { e.stick_mass(m, m) } -> std::same_as<double>;
  e.validate();
};

template <class F>
concept FrictionLaw = requires(const F& f, const vec2& trial, double normal) {
  { F::name } -> std::convertible_to<std::string_view>;
  { f.limit(trial, normal) } -> std::same_as<vec2>;
  f.validate();
};

}  // namespace rkpm
