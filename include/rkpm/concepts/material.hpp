#pragma once
// Material and Hardening: what the explicit solver calls at every quadrature point
// (docs/method.md section 4).
//
// Material: `kirchhoff_stress(F, s)` takes the current total deformation gradient F (3x3, with
// the 2D block structure [[F11, F12, 0], [F21, F22, 0], [0, 0, F33]], F33 = 1 in plane strain
// and the hoop stretch in axisymmetric geometry), advances the internal state s from the last
// accepted F to this one and returns the Kirchhoff stress tau = J sigma with the same block
// structure. The state exposes the equivalent plastic strain and the cumulative plastic work
// per unit REFERENCE volume (J/m^3) for output and the energy balance.
// Optional: `current_kirchhoff_stress(F, s)` (const, s const), the stress the last
// kirchhoff_stress(F, s) returned, recomputed from its F and the state it left; with it the
// solver stores no stress per point (solver/point_materials.hpp).
//
// Hardening: the flow stress sigma_y(eps_p) in Pa and its slope, for J2 return mappings.

#include <concepts>
#include <string_view>

#include <rkpm/core/types.hpp>

namespace rkpm {

template <class M>
concept Material = requires(const M& m, typename M::state_type& s, const mat3& F) {
  { M::name } -> std::convertible_to<std::string_view>;
  { m.initial_state() } -> std::same_as<typename M::state_type>;
  { m.kirchhoff_stress(F, s) } -> std::same_as<mat3>;
  { m.density() } -> std::same_as<double>;
  { m.dilatational_wave_speed() } -> std::same_as<double>;
  // The small-strain elastic constants (material/elastic_constants.hpp) the stable step is
  // estimated with; required by shape so that this header does not depend on a material.
  { m.constants().lame_lambda() } -> std::convertible_to<double>;
  { m.constants().shear_modulus() } -> std::convertible_to<double>;
  m.constants().validate();
  { s.equivalent_plastic_strain } -> std::convertible_to<double>;
  { s.plastic_work } -> std::convertible_to<double>;
};

template <class H>
concept Hardening = requires(const H& h, double e) {
  { H::name } -> std::convertible_to<std::string_view>;
  { h.flow_stress(e) } -> std::same_as<double>;
  { h.slope(e) } -> std::same_as<double>;
};

}  // namespace rkpm
