#pragma once
// Builds the contact policy object of a configuration from the case's tools, the pairs of its
// deformable bodies in contact (contact/body_contact.hpp; or all_body_pairs) and numbers:
// the friction coefficient (Coulomb; frictionless ignores it and must be given 0) and the
// penalty stiffness (used only by the penalty enforcement).

#include <type_traits>
#include <vector>

#include <rkpm/contact/particle_to_segment.hpp>

namespace rkpm::cases {

template <class T>
struct is_particle_to_segment : std::false_type {};
template <class E, class F>
struct is_particle_to_segment<contact::particle_to_segment<E, F>> : std::true_type {};

// Pairs: a std::vector<contact::body_pair>, or contact::all_body_pairs.
template <class Contact, class Pairs = std::vector<contact::body_pair>>
Contact make_contact(std::vector<contact::rigid_tool> tools, double friction, double penalty_stiffness,
                     Pairs body_pairs = {}) {
  static_assert(is_particle_to_segment<Contact>::value,
                "this case has rigid tools: its configuration needs a contact policy "
                "contact::particle_to_segment<Enforcement, Friction>, not contact::none");
  using enforcement_type = typename Contact::enforcement_type;
  using friction_type = typename Contact::friction_type;
  friction_type f{};
  if constexpr (std::is_same_v<friction_type, contact::friction::coulomb>) {
    f.coefficient = friction;
  } else if (friction != 0.0) {
    fail("friction coefficient {} given, but the contact policy is frictionless: use "
         "contact::friction::coulomb", friction);
  }
  enforcement_type e{};
  if constexpr (std::is_same_v<enforcement_type, contact::enforcement::penalty>) e.stiffness = penalty_stiffness;
  return Contact(std::move(tools), std::move(body_pairs), f, e);
}

}  // namespace rkpm::cases
