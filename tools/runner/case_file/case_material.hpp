#pragma once
// The material types of the case files: material::j2_plasticity with its hardening law chosen at
// run time (hardening_law), material::johnson_cook, material::zerilli_armstrong or
// material::rankine_fracture, so that the
// runner compiles one material per geometry and state, whatever law the files name. hardening_law holds one law of the
// library's list (material::hardening::laws) and hands every call to it, so a case file runs
// bit for bit as the typed case with j2_plasticity<that law>
// (tests/unit/case_file/hardening_law.cpp); a law added to the list is read and run with no edit
// here. Two states, so that a run keeps per point only what its laws need:
//   j2_material     J2 and elastic bodies: material::j2_state (96 B per point)
//   material_type   any law, Johnson-Cook, Zerilli-Armstrong and Rankine included:
//                   material::johnson_cook_state (152 B); its J2 points leave temperature and
//                   damage NaN (no temperature: the solver passes NaN as before, and the
//                   snapshots leave out a field that is NaN everywhere, io/solver_output.hpp),
//                   its Zerilli-Armstrong points damage, its Rankine points temperature (their
//                   kappa (102) is kept where a Johnson-Cook point keeps its flow stress at rest,
//                   their dissipation (106) as the plastic work, and their F as every point's,
//                   which the solver reads at a re-reference; rankine_state_of)
// The runner takes j2_material for a file whose bodies carry neither temperature nor damage
// (uses_johnson_cook_state, case_description.hpp): at 10^6 particles and two points each, 82 MB less.
//
// "elastic" is J2 that never yields (flow stress +infinity). Its elastic part is the Hencky law
// of material::elastic (tau = K tr(eps) + 2 mu dev(eps) = lambda tr(eps) + 2 mu eps in principal
// log strains), reached through b_e = f b_e_n f^T step by step instead of b = F F^T: the same
// stress up to round-off.

#include <boost/hana.hpp>
#include <cmath>
#include <limits>
#include <optional>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>

#include <rkpm/concepts/material.hpp>
#include <rkpm/core/error.hpp>
#include <rkpm/material/hardening.hpp>
#include <rkpm/material/j2_batch.hpp>
#include <rkpm/material/j2_plasticity.hpp>
#include <rkpm/material/johnson_cook.hpp>
#include <rkpm/material/radial_return.hpp>
#include <rkpm/material/rankine_fracture.hpp>
#include <rkpm/material/zerilli_armstrong.hpp>

namespace rkpm::runner::case_file {

namespace detail {
struct never_yields {};
// std::variant<never_yields, the laws of material::hardening::laws...>
inline constexpr auto law_variant = boost::hana::unpack(material::hardening::laws, [](auto... law) {
  return boost::hana::type_c<std::variant<never_yields, typename decltype(law)::type...>>;
});
}  // namespace detail

struct hardening_law {
  static constexpr std::string_view name = "case_file";
  using variant = typename decltype(detail::law_variant)::type;

  variant law;

  static hardening_law no_yield() { return {}; }
  template <class Law>
  static hardening_law of(const Law& h) { return {variant(h)}; }

  bool yields() const { return !std::holds_alternative<detail::never_yields>(law); }
  void validate() const {
    visit([](const auto& h) { h.validate(); return 0; }, 0);
  }
  double flow_stress(double eps_p, const flow_point& at = {}) const {
    return visit([&](const auto& h) { return flow_stress_at(h, eps_p, at); },
                 std::numeric_limits<double>::infinity());
  }
  double slope(double eps_p, const flow_point& at = {}) const {
    return visit([&](const auto& h) { return slope_at(h, eps_p, at); }, 0.0);
  }
  // The work integral where the law has one (j2_plasticity's choices, in the same order), so
  // that a case file's law gives the typed law's arithmetic bit for bit.
  double plastic_work(double from, double dgamma, double flow_from, double flow_to) const {
    return visit([&](const auto& h) { return material::plastic_work_increment(h, from, dgamma, flow_from, flow_to); },
                 0.0);
  }

  // f(law) for the law held; `otherwise` when it never yields.
  template <class F, class R>
  R visit(F&& f, R otherwise) const {
    return std::visit(
        [&](const auto& h) -> R {
          if constexpr (std::is_same_v<std::decay_t<decltype(h)>, detail::never_yields>) return otherwise;
          else return f(h);
        },
        law);
  }
};

// Found by argument-dependent lookup from j2_plasticity (a non-template beats the library's
// template): each law gets the library's own return mapping (linear hardening its closed form,
// as radial_return<hardening::linear> does), not the Newton iteration of an unknown law.
inline material::radial_return_result radial_return(const hardening_law& h, double q_trial, double three_mu,
                                                    double eps_p_n, double tolerance, int max_iterations,
                                                    double flow_at_start, const material_step& step = {}) {
  if (!h.yields())
    fail("case-file material: a return mapping was asked of a material that never yields (q_trial = {} Pa)",
         q_trial);
  return h.visit(
      [&](const auto& law) {
        return material::radial_return(law, q_trial, three_mu, eps_p_n, tolerance, max_iterations, flow_at_start,
                                       step);
      },
      material::radial_return_result{});
}

// Found the same way by j2_plasticity's plastic work.
inline double plastic_work_increment(const hardening_law& h, double from, double dgamma, double flow_from,
                                     double flow_to) {
  return h.plastic_work(from, dgamma, flow_from, flow_to);
}

// A Rankine point's state in a Johnson-Cook state, and back: the fields the law reads and writes,
// so that a point updates bit for bit as with material::rankine_fracture_state.
inline material::rankine_fracture_state rankine_state_of(const material::johnson_cook_state& s) {
  material::rankine_fracture_state r;
  r.plastic_work = r.fracture_work = s.plastic_work;
  r.kappa = s.flow_stress_at_rest;
  r.damage = s.damage;
  r.crack_normal = vec2(s.crack_normal);
  return r;
}
inline void store_rankine_state(const material::rankine_fracture_state& r, material::johnson_cook_state& s) {
  s.plastic_work = r.plastic_work;
  s.flow_stress_at_rest = r.kappa;
  s.damage = r.damage;
  s.crack_normal = r.crack_normal;
}

// J2 with the file's hardening law or, with State = johnson_cook_state, Johnson-Cook,
// Zerilli-Armstrong or Rankine too (a branch or three per point update).
template <class State>
class basic_material_type {
 public:
  using j2_type = material::j2_plasticity<hardening_law>;
  static constexpr std::string_view name = j2_type::name;
  using state_type = State;
  // Whether the state has room for Johnson-Cook (temperature, damage and the rest) and so for
  // Zerilli-Armstrong (temperature).
  static constexpr bool holds_johnson_cook = std::is_same_v<State, material::johnson_cook_state>;

  basic_material_type(const material::elastic_constants& constants, const hardening_law& law) : j2_(constants, law) {}
  explicit basic_material_type(material::johnson_cook jc)
    requires holds_johnson_cook
      : j2_(jc.constants(), hardening_law::no_yield()), johnson_cook_(std::move(jc)) {}
  explicit basic_material_type(material::zerilli_armstrong za)
    requires holds_johnson_cook
      : j2_(za.constants(), hardening_law::no_yield()), zerilli_armstrong_(std::move(za)) {}
  explicit basic_material_type(material::rankine_fracture rankine)
    requires holds_johnson_cook
      : j2_(rankine.constants(), hardening_law::no_yield()), rankine_(std::move(rankine)) {}

  state_type initial_state() const {
    if constexpr (holds_johnson_cook) {
      if (johnson_cook_) return johnson_cook_->initial_state();
      state_type s;
      s.damage = std::numeric_limits<double>::quiet_NaN();  // J2: neither temperature nor damage
      if (zerilli_armstrong_) s.temperature = zerilli_armstrong_->initial_state().temperature;
      if (rankine_) store_rankine_state(rankine_->initial_state(), s);
      return s;
    } else {
      return j2_.initial_state();
    }
  }
  mat3 kirchhoff_stress(const mat3& F, state_type& s, const material_step& step = {}) const {
    if constexpr (holds_johnson_cook) {
      if (johnson_cook_) return johnson_cook_->kirchhoff_stress(F, s, step);
      if (zerilli_armstrong_) return zerilli_armstrong_->kirchhoff_stress(F, s, step);
      if (rankine_) {
        material::rankine_fracture_state r = rankine_state_of(s);
        const mat3 tau = rankine_->kirchhoff_stress(F, r);
        store_rankine_state(r, s);
        s.previous_deformation = block_matrix::of(F);  // the total F, which a re-reference reads
        return tau;
      }
    }
    return j2_.kirchhoff_stress(F, s, step);
  }
  // With ln dt from the force loop (UpdatesWithStepLog, concepts/material.hpp), for Johnson-Cook.
  mat3 kirchhoff_stress(const mat3& F, state_type& s, const material_step& step, double log_dt) const {
    if constexpr (holds_johnson_cook)
      if (johnson_cook_) return johnson_cook_->kirchhoff_stress(F, s, step, log_dt);
    return kirchhoff_stress(F, s, step);
  }
  mat3 current_kirchhoff_stress(const mat3& F, const state_type& s) const {
    if constexpr (holds_johnson_cook) {
      if (johnson_cook_) return johnson_cook_->current_kirchhoff_stress(F, s);
      if (zerilli_armstrong_) return zerilli_armstrong_->current_kirchhoff_stress(F, s);
      if (rankine_) return rankine_->current_kirchhoff_stress(F, rankine_state_of(s));
    }
    return j2_.current_kirchhoff_stress(F, s);
  }

  // The point at a conducted temperature T (K) (thermal/heat_coupling.hpp): Johnson-Cook's keeps
  // its flow stress at rest and T*^m with it; a J2 point records T (its flow stress ignores it).
  void set_temperature(state_type& s, double T) const
    requires holds_johnson_cook
  {
    if (johnson_cook_) johnson_cook_->set_temperature(s, T);
    else s.temperature = T;
  }

  double density() const { return j2_.density(); }
  double dilatational_wave_speed() const { return j2_.dilatational_wave_speed(); }
  const material::elastic_constants& constants() const { return j2_.constants(); }
  // The J2 hardening law (never yields for elastic, Johnson-Cook and Zerilli-Armstrong materials).
  const hardening_law& hardening() const { return j2_.hardening(); }
  // The Johnson-Cook material, nullptr for J2 and elastic.
  const material::johnson_cook* johnson_cook() const { return johnson_cook_ ? &*johnson_cook_ : nullptr; }
  // The Zerilli-Armstrong material, nullptr for the others.
  const material::zerilli_armstrong* zerilli_armstrong() const {
    return zerilli_armstrong_ ? &*zerilli_armstrong_ : nullptr;
  }
  // The Rankine material, nullptr for the others.
  const material::rankine_fracture* rankine() const { return rankine_ ? &*rankine_ : nullptr; }
  // Whether failed points open cracks (OpensCracks, concepts/material.hpp): Johnson-Cook's
  // damage with opens_cracks, and Rankine's always.
  bool opens_cracks() const { return (johnson_cook_ && johnson_cook_->opens_cracks()) || rankine_; }
  // The J2 material (with a law that never yields for an elastic body).
  const j2_type& j2() const { return j2_; }

 private:
  j2_type j2_;
  std::optional<material::johnson_cook> johnson_cook_;  // empty unless holds_johnson_cook
  std::optional<material::zerilli_armstrong> zerilli_armstrong_;  // likewise
  std::optional<material::rankine_fracture> rankine_;             // likewise
};

using j2_material = basic_material_type<material::j2_state>;
using material_type = basic_material_type<material::johnson_cook_state>;

// The force loop's batched update (material/j2_batch.hpp, solver/point_materials.hpp): J2 and
// elastic bodies in lanes, Johnson-Cook's, Zerilli-Armstrong's and Rankine's points one by one.
template <class State>
bool updates_in_lanes(const basic_material_type<State>& m) {
  return m.johnson_cook() == nullptr && m.zerilli_armstrong() == nullptr && m.rankine() == nullptr;
}
template <class State, class V>
basic_block_lanes<V> kirchhoff_stress_batch(const basic_material_type<State>& m, const basic_block_lanes<V>& F,
                                            State* s, const material_step& step) {
  return material::kirchhoff_stress_batch(m.j2(), F, s, step);
}

}  // namespace rkpm::runner::case_file
