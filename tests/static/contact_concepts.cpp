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

static_assert(c::particle_to_segment<c::enforcement::effective_mass>::name == "effective_mass");
static_assert(c::particle_to_segment<c::enforcement::paper, c::friction::coulomb>::friction_name == "coulomb");

namespace {
struct missing_enforce {
  static constexpr std::string_view name = "missing_enforce";
  void setup(const c::body_view&) {}
  const std::vector<c::rigid_tool>& tools() const;
};
struct wrong_result {
  static constexpr std::string_view name = "wrong_result";
  void setup(const c::body_view&) {}
  double enforce(double, double, std::vector<rkpm::vec2>&, std::vector<rkpm::vec2>&) { return 0; }
  const std::vector<c::rigid_tool>& tools() const;
};
struct missing_name {
  void setup(const c::body_view&) {}
  c::step_result enforce(double, double, std::vector<rkpm::vec2>&, std::vector<rkpm::vec2>&) { return {}; }
  const std::vector<c::rigid_tool>& tools() const;
};
struct missing_tools {
  static constexpr std::string_view name = "missing_tools";
  void setup(const c::body_view&) {}
  c::step_result enforce(double, double, std::vector<rkpm::vec2>&, std::vector<rkpm::vec2>&) { return {}; }
};
}  // namespace

static_assert(!rkpm::Contact<missing_enforce>, "a type without enforce() is not a Contact");
static_assert(!rkpm::Contact<wrong_result>, "enforce() must return contact::step_result");
static_assert(!rkpm::Contact<missing_name>);
static_assert(!rkpm::Contact<missing_tools>);

TEST_CASE("contact concepts hold at compile time") { CHECK(c::none::name == "none"); }
