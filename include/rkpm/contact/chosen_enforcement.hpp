#pragma once
// enforcement::chosen: one of the enforcement policies (enforcement.hpp: paper, effective_mass,
// penalty), picked at run time by its name. A configuration with it is one solver type for
// every enforcement, where the typed policies are one each: the runner (tools/runner) uses it
// so that each case compiles one solver instead of three. It calls the chosen policy's own
// normal_force and stick_mass, so a run gives the same numbers, bit for bit, as with that
// policy compiled in; the cost is a switch per contact and sweep.

#include <string_view>
#include <variant>

#include <rkpm/contact/enforcement.hpp>
#include <rkpm/core/error.hpp>

namespace rkpm::contact::enforcement {

class chosen {
 public:
  static constexpr std::string_view name = "chosen";

  chosen() : chosen(paper{}) {}
  template <class E>
    requires(std::same_as<E, paper> || std::same_as<E, effective_mass> || std::same_as<E, penalty>)
  chosen(E e) : sweeps(e.sweeps), relaxation(e.relaxation), policy_(e) {}

  // "paper", "effective_mass" (with its default sweeps) or "penalty" (with this stiffness, N/m).
  static chosen named(std::string_view policy_name, double penalty_stiffness) {
    if (policy_name == paper::name) return paper{};
    if (policy_name == effective_mass::name) return effective_mass{};
    if (policy_name == penalty::name) return penalty{.stiffness = penalty_stiffness};
    fail("contact enforcement '{}' is not one of {}, {}, {}", policy_name, paper::name, effective_mass::name,
         penalty::name);
  }

  // The chosen policy's name ("paper", ...), where `name` is this policy's.
  std::string_view chosen_name() const {
    return std::visit([](const auto& e) { return std::string_view(std::decay_t<decltype(e)>::name); }, policy_);
  }

  // The chosen policy's (read by contact_sweeps and contact_kernel as the typed policies' are).
  int sweeps;
  double relaxation;

  void validate() const {
    std::visit([](const auto& e) { e.validate(); }, policy_);
  }
  double normal_force(double gap, double dt, double m_s, double m_sh) const {
    return std::visit([&](const auto& e) { return e.normal_force(gap, dt, m_s, m_sh); }, policy_);
  }
  double stick_mass(double m_s, double m_sh) const {
    return std::visit([&](const auto& e) { return e.stick_mass(m_s, m_sh); }, policy_);
  }

 private:
  std::variant<paper, effective_mass, penalty> policy_;
};

}  // namespace rkpm::contact::enforcement
