// Compile-time checks of rkpm::Material and rkpm::Hardening: the shipped laws satisfy them and
// types missing any one required member do not.
#include <doctest/doctest.h>

#include <rkpm/concepts/material.hpp>
#include <rkpm/material/elastic.hpp>
#include <rkpm/material/hardening.hpp>
#include <rkpm/material/j2_plasticity.hpp>

namespace m = rkpm::material;
namespace h = rkpm::material::hardening;

static_assert(rkpm::Material<m::elastic>);
static_assert(rkpm::Material<m::j2_plasticity<h::linear>>);
static_assert(rkpm::Material<m::j2_plasticity<h::power_law>>);
static_assert(rkpm::Hardening<h::linear>);
static_assert(rkpm::Hardening<h::power_law>);

static_assert(std::same_as<m::j2_plasticity<h::power_law>::hardening_type, h::power_law>);
static_assert(m::elastic::name == "elastic" && m::j2_plasticity<h::linear>::name == "j2");
static_assert(h::linear::name == "linear" && h::power_law::name == "power");

namespace wrong {

using rkpm::mat3;

struct full_state {
  double equivalent_plastic_strain = 0.0;
  double plastic_work = 0.0;
};
struct state_without_work {
  double equivalent_plastic_strain = 0.0;
};
struct state_without_eps_p {
  double plastic_work = 0.0;
};

// A complete material, parameterised on its state, with one member switched off at a time.
template <class State, bool has_density = true, bool has_wave_speed = true,
          bool stress_is_mat3 = true, bool has_constants = true, bool has_name = true>
struct material {
  using state_type = State;
  static constexpr std::string_view name = "wrong";
  State initial_state() const { return {}; }
  auto kirchhoff_stress(const mat3& F, State&) const {
    if constexpr (stress_is_mat3) return mat3(F);
    else return 0.0;
  }
  double density() const requires has_density { return 1.0; }
  double dilatational_wave_speed() const requires has_wave_speed { return 1.0; }
  const m::elastic_constants& constants() const requires has_constants { return c; }
  m::elastic_constants c{1.0, 0.0, 1.0};
};

struct nameless_material {
  using state_type = full_state;
  full_state initial_state() const { return {}; }
  mat3 kirchhoff_stress(const mat3& F, full_state&) const { return F; }
  double density() const { return 1.0; }
  double dilatational_wave_speed() const { return 1.0; }
  const m::elastic_constants& constants() const { return c; }
  m::elastic_constants c{1.0, 0.0, 1.0};
};

struct material_with_mutating_stress {  // kirchhoff_stress must be callable on a const material
  using state_type = full_state;
  static constexpr std::string_view name = "mutating";
  full_state initial_state() const { return {}; }
  mat3 kirchhoff_stress(const mat3& F, full_state&) { return F; }
  double density() const { return 1.0; }
  double dilatational_wave_speed() const { return 1.0; }
  const m::elastic_constants& constants() const { return c; }
  m::elastic_constants c{1.0, 0.0, 1.0};
};

struct hardening_without_slope {
  static constexpr std::string_view name = "no slope";
  double flow_stress(double e) const { return e; }
};
struct hardening_without_name {
  double flow_stress(double e) const { return e; }
  double slope(double) const { return 1.0; }
};
struct hardening_with_float_stress {
  static constexpr std::string_view name = "float";
  float flow_stress(double e) const { return static_cast<float>(e); }
  double slope(double) const { return 1.0; }
};

}  // namespace wrong

// The test double itself is a Material, so each negative below fails for the one missing piece.
static_assert(rkpm::Material<wrong::material<wrong::full_state>>);
static_assert(!rkpm::Material<wrong::material<wrong::state_without_work>>);
static_assert(!rkpm::Material<wrong::material<wrong::state_without_eps_p>>);
static_assert(!rkpm::Material<wrong::material<wrong::full_state, false>>);
static_assert(!rkpm::Material<wrong::material<wrong::full_state, true, false>>);
static_assert(!rkpm::Material<wrong::material<wrong::full_state, true, true, false>>);
static_assert(!rkpm::Material<wrong::material<wrong::full_state, true, true, true, false>>);
static_assert(!rkpm::Material<wrong::nameless_material>);
static_assert(!rkpm::Material<wrong::material_with_mutating_stress>);
static_assert(!rkpm::Material<h::linear>);
static_assert(!rkpm::Material<double>);

static_assert(!rkpm::Hardening<wrong::hardening_without_slope>);
static_assert(!rkpm::Hardening<wrong::hardening_without_name>);
static_assert(!rkpm::Hardening<wrong::hardening_with_float_stress>);
static_assert(!rkpm::Hardening<m::elastic>);

TEST_CASE("material concepts are checked at compile time") { CHECK(true); }
