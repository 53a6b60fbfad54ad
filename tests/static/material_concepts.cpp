// Checks of rkpm::Material and rkpm::Hardening: at compile time the shipped laws satisfy them
// and types missing any one required member do not; at run time each shipped law keeps what
// the concepts promise but cannot express (stress-free reference state, symmetric
// block-structured stress, Hooke's law for small strain, a slope that is the derivative).
#include <doctest/doctest.h>

#include <cmath>

#include <rkpm/concepts/material.hpp>
#include <rkpm/material/elastic.hpp>
#include <rkpm/material/hardening.hpp>
#include <rkpm/material/j2_batch.hpp>
#include <rkpm/material/j2_plasticity.hpp>
#include <rkpm/material/johnson_cook.hpp>
#include <rkpm/material/rankine_fracture.hpp>

namespace m = rkpm::material;
namespace h = rkpm::material::hardening;

static_assert(rkpm::Material<m::elastic>);
static_assert(rkpm::Material<m::j2_plasticity<h::linear>>);
static_assert(rkpm::Material<m::j2_plasticity<h::power_law>>);
static_assert(rkpm::Hardening<h::linear>);
static_assert(rkpm::Hardening<h::power_law>);

static_assert(std::same_as<m::j2_plasticity<h::power_law>::hardening_type, h::power_law>);
static_assert(m::elastic::name == "elastic" && m::j2_plasticity<h::linear>::name == "j2+linear");
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

// The optional protocols (concepts/material.hpp): who offers each, and that a plain Material
// offers none, so that it is never required.
static_assert(rkpm::UpdatesWithStepLog<m::johnson_cook> && !rkpm::UpdatesWithStepLog<m::j2_plasticity<h::power_law>>);
static_assert(rkpm::RecomputesStress<m::j2_plasticity<h::linear>> && rkpm::RecomputesStress<m::johnson_cook>);
static_assert(rkpm::RecordsDeformation<m::j2_state> && rkpm::RecordsDeformation<m::johnson_cook_state>);
static_assert(rkpm::UpdatesInLanes<m::j2_plasticity<h::voce>, rkpm::basic_block_lanes<rkpm::simd_of<2>>>);
static_assert(!rkpm::UpdatesInLanes<m::johnson_cook, rkpm::basic_block_lanes<rkpm::simd_of<2>>>);
static_assert(rkpm::FailingState<m::johnson_cook_state> && rkpm::BreakingState<m::johnson_cook_state>);
// Johnson-Cook's failed points break only when its damage opens cracks; Rankine's always do.
static_assert(rkpm::OpensCracks<m::johnson_cook> && !rkpm::OpensCracks<m::rankine_fracture>);
static_assert(rkpm::BreakingState<m::rankine_fracture::state_type>);
static_assert(rkpm::TemperatureState<m::johnson_cook_state> && !rkpm::TemperatureState<m::j2_state>);
static_assert(rkpm::ListsOutputFields<m::johnson_cook_state> && !rkpm::ListsOutputFields<m::j2_state>);
static_assert(rkpm::SlopeFromFlow<h::power_law> && !rkpm::SlopeFromFlow<h::johnson_cook>);
static_assert(rkpm::RateDependentHardening<h::johnson_cook> && !rkpm::RateDependentHardening<h::voce>);
static_assert(rkpm::SlopesFromFlow<h::johnson_cook::at_temperature_t> && !rkpm::SlopesFromFlow<h::johnson_cook>);
static_assert(rkpm::HardensAlongStep<h::johnson_cook::at_temperature_t> && !rkpm::HardensAlongStep<h::johnson_cook>);
static_assert(rkpm::WorkIntegralFromFlow<h::power_law> && !rkpm::WorkIntegralFromFlow<h::linear>);
static_assert(rkpm::WorkIntegral<h::linear> && rkpm::WorkIntegral<h::voce> && !rkpm::WorkIntegral<h::johnson_cook>);
static_assert(rkpm::BoundedBelow<h::voce> && rkpm::BoundedBelow<h::power_law> && !rkpm::BoundedBelow<h::linear>);

// ---- what the concepts cannot state, checked at run time on every shipped law -------------
// A Material starts with no plastic strain or work, is stress-free at F = I, returns a
// symmetric Kirchhoff stress with the 2D block structure of F, tends to Hooke's law with its
// own constants for small strain (without plastic flow), and reports the density and wave
// speed of those constants.
template <rkpm::Material M>
void check_material_contract(const M& material, const m::elastic_constants& c) {
  CAPTURE(M::name);
  auto s = material.initial_state();
  CHECK(s.equivalent_plastic_strain == 0.0);
  CHECK(s.plastic_work == 0.0);
  CHECK(material.kirchhoff_stress(rkpm::mat3::Identity(), s).norm() <= 1e-9 * c.youngs_modulus);
  CHECK(material.density() == c.density);
  CHECK(material.dilatational_wave_speed() ==
        doctest::Approx(std::sqrt((c.lame_lambda() + 2.0 * c.shear_modulus()) / c.density)).epsilon(1e-14));
  CHECK(material.constants().youngs_modulus == c.youngs_modulus);

  // A small block-structured displacement gradient (hoop stretch in F33), well below yield.
  rkpm::mat3 grad = rkpm::mat3::Zero();
  grad(0, 0) = 2e-6;
  grad(0, 1) = -1e-6;
  grad(1, 0) = 3e-6;
  grad(1, 1) = -1.5e-6;
  grad(2, 2) = 0.5e-6;
  const rkpm::mat3 eps = 0.5 * (grad + grad.transpose());
  const rkpm::mat3 hooke =
      c.lame_lambda() * eps.trace() * rkpm::mat3::Identity() + 2.0 * c.shear_modulus() * eps;
  const rkpm::mat3 tau = material.kirchhoff_stress(rkpm::mat3::Identity() + grad, s);
  CHECK((tau - tau.transpose()).norm() <= 1e-12 * tau.norm());
  CHECK(tau(0, 2) == 0.0);
  CHECK(tau(1, 2) == 0.0);
  CHECK(tau(2, 0) == 0.0);
  CHECK(tau(2, 1) == 0.0);
  CHECK((tau - hooke).norm() <= 1e-4 * hooke.norm());  // geometric terms are O(|grad|)
  CHECK(s.equivalent_plastic_strain == 0.0);
  CHECK(s.plastic_work == 0.0);
}

// A Hardening law starts at a positive yield stress, does not soften, and its slope is the
// derivative of its flow stress.
template <rkpm::Hardening H>
void check_hardening_contract(const H& law) {
  CAPTURE(H::name);
  CHECK(law.flow_stress(0.0) > 0.0);
  for (double e : {0.0, 0.01, 0.1, 0.5}) {
    CAPTURE(e);
    CHECK(law.slope(e) >= 0.0);
    CHECK(law.flow_stress(e + 0.01) >= law.flow_stress(e));
    const double h = 1e-7;
    CHECK(law.slope(e) ==
          doctest::Approx((law.flow_stress(e + h) - law.flow_stress(e)) / h).epsilon(1e-4).scale(1e6));
  }
}

TEST_CASE("the shipped materials keep the promises of Material that the type system cannot check") {
  const m::elastic_constants steel{200e9, 0.3, 7800.0}, copper{117e9, 0.35, 8930.0};
  check_material_contract(m::elastic(steel), steel);
  check_material_contract(m::j2_plasticity<h::linear>(copper, h::linear{400e6, 100e6}), copper);
  check_material_contract(m::j2_plasticity<h::power_law>(steel, h::power_law{576.79e6, 0.01658, 0.3593}), steel);
}

TEST_CASE("the shipped hardening laws keep the promises of Hardening that the type system cannot check") {
  check_hardening_contract(h::linear{400e6, 100e6});
  check_hardening_contract(h::linear{400e6, 0.0});  // perfect plasticity
  check_hardening_contract(h::power_law{576.79e6, 0.01658, 0.3593});
}
