// Every shipped contact type satisfies Contact; types missing part of the interface do not.
#include <doctest/doctest.h>

#include <rkpm/concepts/contact.hpp>
#include <rkpm/contact/none.hpp>
#include <rkpm/contact/particle_to_segment.hpp>

namespace c = rkpm::contact;

static_assert(rkpm::Contact<c::none>);
static_assert(rkpm::Contact<c::particle_to_segment<>>);
static_assert(rkpm::Contact<c::particle_to_segment<c::enforcement::paper, c::friction::frictionless>>);
static_assert(rkpm::Contact<c::particle_to_segment<c::enforcement::paper, c::friction::coulomb>>);
static_assert(rkpm::Contact<c::particle_to_segment<c::enforcement::effective_mass, c::friction::frictionless>>);
static_assert(rkpm::Contact<c::particle_to_segment<c::enforcement::effective_mass, c::friction::coulomb>>);
static_assert(rkpm::Contact<c::particle_to_segment<c::enforcement::penalty, c::friction::frictionless>>);
static_assert(rkpm::Contact<c::particle_to_segment<c::enforcement::penalty, c::friction::coulomb>>);

static_assert(rkpm::ContactEnforcement<c::enforcement::paper>);
static_assert(rkpm::ContactEnforcement<c::enforcement::effective_mass>);
static_assert(rkpm::ContactEnforcement<c::enforcement::penalty>);
static_assert(rkpm::FrictionLaw<c::friction::frictionless>);
static_assert(rkpm::FrictionLaw<c::friction::coulomb>);
static_assert(!rkpm::FrictionLaw<c::enforcement::paper>);
static_assert(!rkpm::ContactEnforcement<c::friction::coulomb>);

// The optional protocols (concepts/contact.hpp): particle_to_segment offers them, none only rebind.
static_assert(rkpm::RebindsSlaves<c::particle_to_segment<>> && rkpm::RebindsSlaves<c::none>);
static_assert(rkpm::ContactsOnSurfaces<c::particle_to_segment<>> && !rkpm::ContactsOnSurfaces<c::none>);
static_assert(rkpm::ReportsToolPairs<c::particle_to_segment<>> && !rkpm::ReportsToolPairs<c::none>);
static_assert(rkpm::ReportsBodyPairs<c::particle_to_segment<>> && !rkpm::ReportsBodyPairs<c::none>);

static_assert(c::particle_to_segment<c::enforcement::effective_mass>::name == "effective_mass+frictionless");
static_assert(c::particle_to_segment<c::enforcement::paper, c::friction::coulomb>::name == "paper+coulomb");

namespace {
using rkpm::contact_body;
using rkpm::contact_result;
using rkpm::contact_slaves;
using rkpm::vec2;
// A complete policy, and copies of it that each lack or get wrong one requirement.
struct complete {
  static constexpr std::string_view name = "complete";
  void setup(const contact_body&, const contact_slaves&) {}
  contact_result enforce(const contact_body&, double, double, std::vector<vec2>&, std::vector<vec2>&) { return {}; }
  const std::vector<c::rigid_tool>& tools() const;
  const std::vector<vec2>& reactions() const;
  const std::vector<c::body_pair>& body_pairs() const;
  void save(rkpm::io::checkpoint_writer&) const;
  void load(rkpm::io::checkpoint_reader&);
};
struct missing_enforce {
  static constexpr std::string_view name = "missing_enforce";
  void setup(const contact_body&, const contact_slaves&) {}
  const std::vector<c::rigid_tool>& tools() const;
  const std::vector<vec2>& reactions() const;
  const std::vector<c::body_pair>& body_pairs() const;
  void save(rkpm::io::checkpoint_writer&) const;
  void load(rkpm::io::checkpoint_reader&);
};
struct wrong_result {
  static constexpr std::string_view name = "wrong_result";
  void setup(const contact_body&, const contact_slaves&) {}
  double enforce(const contact_body&, double, double, std::vector<vec2>&, std::vector<vec2>&) { return 0; }
  const std::vector<c::rigid_tool>& tools() const;
  const std::vector<vec2>& reactions() const;
  const std::vector<c::body_pair>& body_pairs() const;
  void save(rkpm::io::checkpoint_writer&) const;
  void load(rkpm::io::checkpoint_reader&);
};
struct missing_name {
  void setup(const contact_body&, const contact_slaves&) {}
  contact_result enforce(const contact_body&, double, double, std::vector<vec2>&, std::vector<vec2>&) { return {}; }
  const std::vector<c::rigid_tool>& tools() const;
  const std::vector<vec2>& reactions() const;
  const std::vector<c::body_pair>& body_pairs() const;
  void save(rkpm::io::checkpoint_writer&) const;
  void load(rkpm::io::checkpoint_reader&);
};
struct missing_tools {
  static constexpr std::string_view name = "missing_tools";
  void setup(const contact_body&, const contact_slaves&) {}
  contact_result enforce(const contact_body&, double, double, std::vector<vec2>&, std::vector<vec2>&) { return {}; }
  const std::vector<vec2>& reactions() const;
  const std::vector<c::body_pair>& body_pairs() const;
  void save(rkpm::io::checkpoint_writer&) const;
  void load(rkpm::io::checkpoint_reader&);
};
struct tools_not_a_range {
  static constexpr std::string_view name = "tools_not_a_range";
  void setup(const contact_body&, const contact_slaves&) {}
  contact_result enforce(const contact_body&, double, double, std::vector<vec2>&, std::vector<vec2>&) { return {}; }
  double tools() const;
  const std::vector<vec2>& reactions() const;
  const std::vector<c::body_pair>& body_pairs() const;
  void save(rkpm::io::checkpoint_writer&) const;
  void load(rkpm::io::checkpoint_reader&);
};
struct missing_reactions {
  static constexpr std::string_view name = "missing_reactions";
  void setup(const contact_body&, const contact_slaves&) {}
  contact_result enforce(const contact_body&, double, double, std::vector<vec2>&, std::vector<vec2>&) { return {}; }
  const std::vector<c::rigid_tool>& tools() const;
  const std::vector<c::body_pair>& body_pairs() const;
  void save(rkpm::io::checkpoint_writer&) const;
  void load(rkpm::io::checkpoint_reader&);
};
struct missing_body_pairs {  // the solver asks whether there are body pairs to enforce
  static constexpr std::string_view name = "missing_body_pairs";
  void setup(const contact_body&, const contact_slaves&) {}
  contact_result enforce(const contact_body&, double, double, std::vector<vec2>&, std::vector<vec2>&) { return {}; }
  const std::vector<c::rigid_tool>& tools() const;
  const std::vector<vec2>& reactions() const;
  void save(rkpm::io::checkpoint_writer&) const;
  void load(rkpm::io::checkpoint_reader&);
};
struct missing_save {  // checkpoints store the policy's state
  static constexpr std::string_view name = "missing_save";
  void setup(const contact_body&, const contact_slaves&) {}
  contact_result enforce(const contact_body&, double, double, std::vector<vec2>&, std::vector<vec2>&) { return {}; }
  const std::vector<c::rigid_tool>& tools() const;
  const std::vector<vec2>& reactions() const;
  const std::vector<c::body_pair>& body_pairs() const;
  void load(rkpm::io::checkpoint_reader&);
};
struct missing_load {
  static constexpr std::string_view name = "missing_load";
  void setup(const contact_body&, const contact_slaves&) {}
  contact_result enforce(const contact_body&, double, double, std::vector<vec2>&, std::vector<vec2>&) { return {}; }
  const std::vector<c::rigid_tool>& tools() const;
  const std::vector<vec2>& reactions() const;
  const std::vector<c::body_pair>& body_pairs() const;
  void save(rkpm::io::checkpoint_writer&) const;
};
struct old_interface {  // enforce without the body: the pointer-keeping interface of before
  static constexpr std::string_view name = "old_interface";
  void setup(const contact_body&, const contact_slaves&) {}
  contact_result enforce(double, double, std::vector<vec2>&, std::vector<vec2>&) { return {}; }
  const std::vector<c::rigid_tool>& tools() const;
  const std::vector<vec2>& reactions() const;
  const std::vector<c::body_pair>& body_pairs() const;
  void save(rkpm::io::checkpoint_writer&) const;
  void load(rkpm::io::checkpoint_reader&);
};
}  // namespace

static_assert(rkpm::Contact<complete>);
static_assert(!rkpm::Contact<missing_enforce>, "a type without enforce() is not a Contact");
static_assert(!rkpm::Contact<wrong_result>, "enforce() must return contact_result");
static_assert(!rkpm::Contact<missing_name>);
static_assert(!rkpm::Contact<missing_tools>);
static_assert(!rkpm::Contact<tools_not_a_range>);
static_assert(!rkpm::Contact<missing_reactions>);
static_assert(!rkpm::Contact<missing_body_pairs>);
static_assert(!rkpm::Contact<missing_save>);
static_assert(!rkpm::Contact<missing_load>);
static_assert(!rkpm::Contact<old_interface>);

TEST_CASE("the shipped contact policies report one reaction per tool") {
  c::none none;
  CHECK(none.tools().size() == none.reactions().size());
  c::particle_to_segment<c::enforcement::paper> wall({c::rigid_tool("wall", {{-1, 0}, {1, 0}}, c::side::left)});
  CHECK(wall.tools().size() == 1);
  CHECK(wall.reactions().size() == wall.tools().size());
}

TEST_CASE("has_contact: true with tools or body pairs, false with neither") {
  CHECK_FALSE(rkpm::has_contact(c::none{}));
  const c::particle_to_segment<> wall({c::rigid_tool("wall", {{-1, 0}, {1, 0}}, c::side::left)});
  CHECK(rkpm::has_contact(wall));
  const c::particle_to_segment<> bodies(std::vector<c::rigid_tool>{}, std::vector<c::body_pair>{{0, 1}});
  CHECK(bodies.tools().empty());
  CHECK(rkpm::has_contact(bodies));
  CHECK_FALSE(rkpm::has_contact(c::particle_to_segment<>(std::vector<c::rigid_tool>{})));
}
