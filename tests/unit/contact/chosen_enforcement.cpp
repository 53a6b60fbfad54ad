// enforcement::chosen (contact/chosen_enforcement.hpp): the policy picked by name at run time
// gives the forces of that policy compiled in, to the bit, through the force kernel of every
// contact pass (contact_increment), in every sweep, with and without friction; its sweeps and
// relaxation are the chosen policy's; a name it does not know and a penalty without stiffness
// are refused, saying what to give.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include <rkpm/contact/chosen_enforcement.hpp>
#include <rkpm/contact/contact_kernel.hpp>
#include <rkpm/contact/friction.hpp>

#include "support/error_message.hpp"

namespace test_unit_contact_chosen_enforcement {

using namespace rkpm;
using namespace rkpm::contact;

// The forces of three sweeps of one contact under `e` (gap and slip measured anew each sweep).
template <class E, class F>
std::vector<double> three_sweeps(const E& e, const F& f) {
  contact_state c{.gap = 2e-3, .relative_velocity = vec2(0.5, -3.0), .normal = vec2(0.0, 1.0), .own_mass = 2.0,
                  .shared_mass = 0.5};
  double fn = 0.0;
  vec2 ft = vec2::Zero();
  std::vector<double> out;
  for (int sweep = 0; sweep < 3; ++sweep) {
    const vec2 df = contact_increment(c, 1e-4, sweep, e, f, fn, ft);
    out.insert(out.end(), {fn, ft.x(), ft.y(), df.x(), df.y()});
    c.gap *= -0.3;  // overshot, then back: the later sweeps see other gaps and slips
    c.relative_velocity *= 0.4;
  }
  return out;
}

TEST_CASE("chosen by name: the forces of the typed policy, bit for bit, in every sweep") {
  const friction::coulomb mu{.coefficient = 0.3};
  CHECK(three_sweeps(enforcement::chosen::named("paper", 0.0), mu) == three_sweeps(enforcement::paper{}, mu));
  CHECK(three_sweeps(enforcement::chosen::named("effective_mass", 0.0), mu) ==
        three_sweeps(enforcement::effective_mass{}, mu));
  CHECK(three_sweeps(enforcement::chosen::named("penalty", 1e9), mu) ==
        three_sweeps(enforcement::penalty{.stiffness = 1e9}, mu));
  CHECK(three_sweeps(enforcement::chosen::named("penalty", 1e9), friction::frictionless{}) ==
        three_sweeps(enforcement::penalty{.stiffness = 1e9}, friction::frictionless{}));
  // The three differ from each other here, so the comparisons above can tell them apart.
  CHECK(three_sweeps(enforcement::paper{}, mu) != three_sweeps(enforcement::effective_mass{}, mu));
  CHECK(three_sweeps(enforcement::paper{}, mu) != three_sweeps(enforcement::penalty{.stiffness = 1e9}, mu));
}

TEST_CASE("chosen: the sweeps, relaxation and name of the policy it holds") {
  const auto effective = enforcement::chosen::named("effective_mass", 0.0);
  CHECK(effective.sweeps == enforcement::effective_mass{}.sweeps);
  CHECK(effective.relaxation == enforcement::effective_mass{}.relaxation);
  CHECK(effective.chosen_name() == "effective_mass");
  const enforcement::chosen three(enforcement::effective_mass{.sweeps = 3, .relaxation = 0.5});
  CHECK(three.sweeps == 3);
  CHECK(three.relaxation == 0.5);
  CHECK(enforcement::chosen{}.chosen_name() == "paper");
  CHECK(enforcement::chosen::named("penalty", 1.0).sweeps == 1);
}

TEST_CASE("chosen: an unknown name and a penalty without stiffness are refused") {
  const std::string unknown = test::error_message([] { enforcement::chosen::named("lagrange", 0.0); });
  CHECK(unknown.find("'lagrange'") != std::string::npos);
  CHECK(unknown.find("effective_mass") != std::string::npos);
  const std::string soft = test::error_message([] { enforcement::chosen::named("penalty", 0.0).validate(); });
  CHECK(soft.find("stiffness") != std::string::npos);
}

}  // namespace test_unit_contact_chosen_enforcement
