#pragma once
// enforcement::chosen: one of the enforcement policies (enforcement.hpp: paper, effective_mass,
// penalty), picked at run time by its name. A configuration with it is one solver type for
// every enforcement, where the typed policies are one each: the runner (tools/runner) uses it
// so that each case compiles one solver instead of three. It calls the chosen policy's own
// normal_force and stick_mass, so a run gives the same numbers, bit for bit, as with that
// policy compiled in; the cost is a switch per contact and sweep.
// The policies it can hold, the names it accepts and the list its refusal gives all come from
// one list, enforcement::shipped: a new policy is added there.

#include <array>
#include <concepts>
#include <optional>
#include <string_view>
#include <variant>

#include <boost/hana.hpp>
#include <fmt/ranges.h>

#include <rkpm/contact/enforcement.hpp>
#include <rkpm/core/error.hpp>

namespace rkpm::contact::enforcement {

// The enforcement policies rkpm ships, in the order chosen names them.
inline constexpr auto shipped = boost::hana::tuple_t<paper, effective_mass, penalty>;

class chosen {
  using policy_type = typename decltype(boost::hana::unpack(shipped, boost::hana::template_<std::variant>))::type;
  static constexpr auto names =
      boost::hana::unpack(shipped, [](auto... e) { return std::array{std::string_view(decltype(e)::type::name)...}; });

 public:
  static constexpr std::string_view name = "chosen";

  chosen() : chosen(paper{}) {}
  template <class E>
    requires(decltype(boost::hana::contains(shipped, boost::hana::type_c<E>))::value)
  chosen(E e) : sweeps(e.sweeps), relaxation(e.relaxation), policy_(e) {}

  // "paper", "effective_mass" (with its default sweeps) or "penalty" (with this stiffness, N/m).
  static chosen named(std::string_view policy_name, double penalty_stiffness) {
    std::optional<chosen> found;
    boost::hana::for_each(shipped, [&](auto e) {
      using E = typename decltype(e)::type;
      if (found || policy_name != E::name) return;
      if constexpr (std::same_as<E, penalty>) found.emplace(penalty{.stiffness = penalty_stiffness});
      else found.emplace(E{});
    });
    if (!found) fail("contact enforcement '{}' is not one of {}", policy_name, fmt::join(names, ", "));
    return *found;
  }

  // The chosen policy's name ("paper", ...), where `name` is this policy's.
  std::string_view chosen_name() const { return names[policy_.index()]; }

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
  policy_type policy_;
};

}  // namespace rkpm::contact::enforcement
