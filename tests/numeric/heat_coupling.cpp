// Heat conduction coupled to the mechanics (thermal/heat_coupling.hpp, docs/method.md section
// 5.11), against theory:
//   - plastic heat (98): a block in homogeneous uniaxial strain, insulated: the heat is beta
//     times the solver's plastic work, and the capacity-weighted mean temperature rises by
//     beta W_p / (M c_p), to round-off;
//   - friction (99): a block sliding on a fixed tool under a body force g decelerates at mu g;
//     friction makes mu M g integral v dt of heat, the contact's lost work, and the body keeps the
//     stated share;
//   - tool contact (100): a block resting on a tool at T_t with conductance h and a small Biot
//     number h H / k cools as one lump, T = T_t + (T0 - T_t) exp(-h W t / (M c_p)).
// The constants are chosen for short runs (a specific heat of 1 J/(kg K) in the contact test),
// not for a material.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <type_traits>
#include <numeric>

#include <rkpm/solver/checkpoint.hpp>
#include <rkpm/thermal/heat_coupling.hpp>

#include "support/solver_fixtures.hpp"

namespace test_numeric_heat_coupling {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

namespace {

const material::elastic_constants steel{200e9, 0.3, 7800.0};

}  // namespace

TEST_CASE("plastic heat (98): beta times the plastic work, the mean temperature up by beta W_p / (M c_p)") {
  using cfg = config<kernel::cubic_spline, correction::linear, quadrature::q4, geometry::plane_strain,
                     material::j2_plasticity<material::hardening::linear>, contact::none>;
  const double L = 10e-3, H = 6e-3, V = 20.0, c_p = 460.0, beta = 0.9, T0 = 300.0;
  problem_for<cfg> p{.particles = make_grid_particles<2>(vec2(0, 0), vec2(L, H), Eigen::Vector2i(11, 7), 2.0),
                     .mesh = make_grid_mesh(vec2(0, 0), vec2(L, H), Eigen::Vector2i(11, 7)),
                     .material = material::j2_plasticity<material::hardening::linear>(steel, {400e6, 2e9}),
                     .contact = {},
                     .initial_velocity = [&](const vec2& X) { return vec2(V * X[0] / L, 0.0); }};
  for (index_t I = 0; I < p.particles.size(); ++I) {
    const double vx = V * p.particles.position[I][0] / L;
    p.constraints.push_back({I, 0, [vx](double) { return vx; }});
    p.constraints.push_back({I, 1, {}});
  }
  run_options o;
  o.end_time = 0.01 * L / V;  // 1% strain: several times the yield strain
  auto s = make_solver<cfg>(std::move(p), o);
  auto heat = std::make_shared<thermal::heat_coupling<decltype(s)>>(
      s, std::vector<thermal::thermal_properties>{{.conductivity = 50.0, .specific_heat = c_p}}, std::vector{beta}, T0);
  s.attach(heat);
  s.run();
  const double M = std::accumulate(s.physical_mass().begin(), s.physical_mass().end(), 0.0);
  MESSAGE("plastic work ", s.energy().plastic, " J/m, heat ", heat->ledger().plastic, " J/m over ",
          heat->exchanges(), " exchanges; mean T ", heat->mean_temperature(), " K");
  REQUIRE(s.energy().plastic > 0.0);
  CHECK(heat->ledger().plastic == doctest::Approx(beta * s.energy().plastic).epsilon(1e-12));
  CHECK(heat->conduction().ledger().sources == doctest::Approx(heat->ledger().plastic).epsilon(1e-12));
  CHECK(heat->conduction().ledger().relative_imbalance() < 1e-12);
  CHECK(heat->mean_temperature() - T0 == doctest::Approx(beta * s.energy().plastic / (M * c_p)).epsilon(1e-9));
}

TEST_CASE("friction (99) and tool contact (100)") {
  using contact_t = contact::particle_to_segment<contact::enforcement::paper, contact::friction::coulomb>;
  using cfg = config<kernel::cubic_spline, correction::linear, quadrature::q4, geometry::plane_strain, material::elastic,
                     contact_t>;
  const double W = 20e-3, H = 5e-3, mu = 0.3, g = 2000.0;
  const auto block = [&](vec2 v0, double friction) {
    problem_for<cfg> p{.particles = make_grid_particles<2>(vec2(0, 0), vec2(W, H), Eigen::Vector2i(21, 6), 2.0),
                       .mesh = make_grid_mesh(vec2(0, 0), vec2(W, H), Eigen::Vector2i(21, 6)),
                       .material = material::elastic(steel),
                       .contact = contact_t({contact::rigid_tool("floor", {vec2(-1.0, 0.0), vec2(1.0, 0.0)},
                                                                 contact::side::left)},
                                            contact::friction::coulomb{friction}),
                       .initial_velocity = [v0](const vec2&) { return v0; }};
    p.body_force = vec2(0.0, -g);
    return p;
  };

  SUBCASE("a block sliding at v0 = 2 m/s heats at mu M g v, and keeps the stated share") {
    const double v0 = 2.0, T = 2e-4, share = 0.6;
    run_options o;
    o.end_time = T;
    auto s = make_solver<cfg>(block(vec2(v0, 0.0), mu), o);
    auto heat = std::make_shared<thermal::heat_coupling<decltype(s)>>(
        s, std::vector<thermal::thermal_properties>{{.conductivity = 50.0, .specific_heat = 460.0}},
        std::vector{0.0}, 300.0, std::vector<thermal::thermal_boundary>{},
        thermal::tool_heat{.friction_to_body = share});
    s.attach(heat);
    s.run();
    const double M = std::accumulate(s.physical_mass().begin(), s.physical_mass().end(), 0.0);
    const double exact = mu * M * g * (v0 * T - 0.5 * mu * g * T * T);
    MESSAGE("friction heat ", heat->ledger().friction, " J/m (mu M g integral v dt ", exact, "), contact work ",
            s.energy().contact, ", to the body ", heat->ledger().friction_to_body);
    CHECK(heat->ledger().friction == doctest::Approx(exact).epsilon(0.03));
    CHECK(heat->ledger().friction == doctest::Approx(-s.energy().contact).epsilon(0.03));
    CHECK(heat->ledger().friction_to_body == doctest::Approx(share * heat->ledger().friction).epsilon(1e-12));
    CHECK(heat->conduction().ledger().sources == doctest::Approx(heat->ledger().friction_to_body).epsilon(1e-12));
  }

  SUBCASE("a block on a cold tool cools as one lump at the interface conductance") {
    const double h = 2e5, c_p = 1.0, k = h * H / 0.01, T0 = 1000.0, Tt = 300.0;  // Biot number 0.01
    const double M0 = steel.density * W * H, tau = M0 * c_p / (h * W);
    run_options o;
    o.end_time = tau;
    auto s = make_solver<cfg>(block(vec2::Zero(), 0.0), o);
    auto heat = std::make_shared<thermal::heat_coupling<decltype(s)>>(
        s, std::vector<thermal::thermal_properties>{{.conductivity = k, .specific_heat = c_p}}, std::vector{0.0}, T0,
        std::vector<thermal::thermal_boundary>{}, thermal::tool_heat{.temperature = {Tt}, .conductance = h});
    s.attach(heat);
    s.run();
    const double exact = Tt + (T0 - Tt) * std::exp(-s.time() / tau);
    MESSAGE("mean T after one time constant ", heat->mean_temperature(), " K (lumped ", exact, "), heat from the tool ",
            heat->ledger().from_tools, " J/m, ", heat->exchanges(), " exchanges, ", s.steps(), " steps");
    CHECK(heat->mean_temperature() == doctest::Approx(exact).epsilon(0.02));
    CHECK(heat->conduction().ledger().stored == doctest::Approx(heat->ledger().from_tools).epsilon(1e-9));
  }
}

TEST_CASE("contact between bodies (100): a hot block on a cold slab, the two exchange h (T1 - T2) per area") {
  // A block at 1000 K resting (a body force g) on a slab at 300 K fixed at its bottom; both
  // conduct fast (Biot number 0.01 each), so each is one lump and their difference decays as
  // exp(-h W t (1 / C_block + 1 / C_slab)) while in contact. Nothing leaves the two: their heat
  // changes only by the frictional heat of their contact, to round-off.
  using Ct = contact::particle_to_segment<contact::enforcement::effective_mass, contact::friction::coulomb>;
  using Cfg = config<kernel::cubic_spline, correction::linear, quadrature::q4, geometry::plane_strain,
                     material::elastic, Ct>;
  const double W = 20e-3, H = 5e-3, h = 2e5, c_p = 1.0, k = h * H / 0.01, g = 2000.0;
  problem_for<Cfg> p{.particles = {}, .mesh = {}, .material = material::elastic(steel),
                     .contact = Ct({}, {contact::body_pair{1, 0}}, contact::friction::coulomb{0.3})};
  const Eigen::Vector2i n(21, 6);
  append_body(p.particles, p.mesh, make_grid_particles<2>(vec2(0, -H), vec2(W, 0), n, 2.0),
              make_grid_mesh(vec2(0, -H), vec2(W, 0), n));  // body 0: the slab
  const index_t slab = p.particles.size();
  append_body(p.particles, p.mesh, make_grid_particles<2>(vec2(0, 0), vec2(W, H), n, 2.0),
              make_grid_mesh(vec2(0, 0), vec2(W, H), n));  // body 1: the block
  for (index_t I = 0; I < slab; ++I)
    if (p.particles.position[I][1] < -H + 1e-9)
      for (int dir : {0, 1}) p.constraints.push_back({I, dir, [](double) { return 0.0; }});
  p.body_force = vec2(0.0, -g);
  const double C = steel.density * W * H * c_p, tau = C / (2.0 * h * W);  // each body's heat capacity
  run_options o;
  o.end_time = tau;
  auto s = make_solver<Cfg>(std::move(p), o);
  const std::vector<thermal::thermal_properties> props(2, {.conductivity = k, .specific_heat = c_p});
  auto heat = std::make_shared<thermal::heat_coupling<decltype(s)>>(
      s, props, std::vector{0.0, 0.0}, 300.0, std::vector<thermal::thermal_boundary>{},
      thermal::tool_heat{.conductance = h});
  std::vector<double> T0(s.model().particle_count(), 300.0);
  for (index_t I = slab; I < s.model().particle_count(); ++I) T0[I] = 1000.0;
  heat->set_temperatures(s, T0);
  s.attach(heat);
  const double stored0 = heat->conduction().stored_heat();
  // The block was set down unloaded and rings on the slab: a slave is in contact in most steps, not
  // all (about 93% here), and exchanges heat in those only.
  double in_contact = 0.0;
  while (s.before_end()) {
    s.step_to_end();
    in_contact += static_cast<double>(s.contact().bodies().active_pairs().size()) / static_cast<double>(n[0]);
  }
  in_contact /= static_cast<double>(s.steps());
  const auto& Cap = heat->conduction().capacities();
  const auto& T = heat->conduction().coefficients();
  double mean[2] = {0.0, 0.0}, cap[2] = {0.0, 0.0};
  for (index_t I = 0; I < s.model().particle_count(); ++I) {
    const int b = I < slab ? 0 : 1;
    mean[b] += Cap[I] * T[I];
    cap[b] += Cap[I];
  }
  const double difference = mean[1] / cap[1] - mean[0] / cap[0], exact = 700.0 * std::exp(-s.time() / tau);
  MESSAGE("block - slab after one time constant: ", difference, " K (lumped, always in contact: ", exact,
          "; bottom particles in contact ", in_contact, " of the steps); conducted ",
          heat->ledger().between_bodies, " J/m; heat kept to ", heat->conduction().stored_heat() / stored0 - 1.0,
          " (friction ", heat->ledger().friction, " J/m)");
  // Between the lumped decay in full contact and the one at 85% of it.
  CHECK(difference > 0.99 * exact);
  CHECK(difference < 700.0 * std::exp(-0.85 * s.time() / tau));
  CHECK(in_contact > 0.85);
  CHECK(heat->ledger().between_bodies < 0.0);  // from the master (slab) to the slave (block): negative
  CHECK(heat->conduction().stored_heat() - stored0 == doctest::Approx(heat->ledger().friction_to_body).epsilon(1e-9));
}

TEST_CASE("heat coupling across a checkpoint: the run continued from it is the uninterrupted one, bit for bit") {
  using contact_t = contact::particle_to_segment<contact::enforcement::paper, contact::friction::coulomb>;
  using cfg = config<kernel::cubic_spline, correction::linear, quadrature::q4, geometry::plane_strain, material::elastic,
                     contact_t>;
  const auto sliding = [] {
    problem_for<cfg> p{
        .particles = make_grid_particles<2>(vec2(0, 0), vec2(20e-3, 5e-3), Eigen::Vector2i(11, 4), 2.0),
        .mesh = make_grid_mesh(vec2(0, 0), vec2(20e-3, 5e-3), Eigen::Vector2i(11, 4)),
        .material = material::elastic(steel),
        .contact = contact_t({contact::rigid_tool("floor", {vec2(-1.0, 0.0), vec2(1.0, 0.0)}, contact::side::left)},
                             contact::friction::coulomb{0.3}),
        .initial_velocity = [](const vec2&) { return vec2(2.0, 0.0); }};
    p.body_force = vec2(0.0, -2000.0);
    run_options o;
    o.end_time = 1e-4;
    return make_solver<cfg>(std::move(p), o);
  };
  const auto attach = [](auto& s) {
    auto heat = std::make_shared<thermal::heat_coupling<std::remove_reference_t<decltype(s)>>>(
        s, std::vector<thermal::thermal_properties>{{.conductivity = 50.0, .specific_heat = 460.0}},
        std::vector{0.0}, 300.0, std::vector<thermal::thermal_boundary>{},
        thermal::tool_heat{.temperature = {900.0}, .conductance = 1e6, .friction_to_body = 0.5});
    s.attach(heat);
    return heat;
  };
  auto whole = sliding();
  auto whole_heat = attach(whole);
  whole.run();

  auto first = sliding();
  auto first_heat = attach(first);
  for (int n = 0; n < 37; ++n) first.step_to_end();
  const auto path = std::filesystem::temp_directory_path() / "rkpm_heat_coupling_restart.rkpmcp";
  write_checkpoint(first, path, cfg::name());
  auto second = sliding();
  auto second_heat = attach(second);
  read_checkpoint(second, path, cfg::name());
  std::filesystem::remove(path);
  second.run();
  REQUIRE(whole_heat->ledger().from_tools > 0.0);
  CHECK(second.steps() == whole.steps());
  CHECK(second_heat->conduction().coefficients() == whole_heat->conduction().coefficients());
  CHECK(second_heat->ledger().friction == whole_heat->ledger().friction);
  CHECK(second_heat->ledger().from_tools == whole_heat->ledger().from_tools);
  CHECK(second.coefficients() == whole.coefficients());
}

TEST_CASE("heat coupling's errors name the fix") {
  using cfg = config<kernel::cubic_spline, correction::linear, quadrature::q4, geometry::plane_strain, material::elastic,
                     contact::none>;
  problem_for<cfg> p{.particles = make_grid_particles<2>(vec2(0, 0), vec2(1, 1), Eigen::Vector2i(5, 5), 2.0),
                     .mesh = make_grid_mesh(vec2(0, 0), vec2(1, 1), Eigen::Vector2i(5, 5)),
                     .material = material::elastic(steel),
                     .contact = {}};
  run_options o;
  o.end_time = 1e-3;
  auto s = make_solver<cfg>(std::move(p), o);
  using coupling = thermal::heat_coupling<decltype(s)>;
  const std::vector<thermal::thermal_properties> props{{.conductivity = 50.0, .specific_heat = 460.0}};
  const std::vector<thermal::thermal_boundary> none;
  CHECK_THROWS_WITH_AS(coupling(s, props, {1.5}, 300.0), doctest::Contains("must lie in [0, 1]"), error);
  CHECK_THROWS_WITH_AS(coupling(s, props, {0.9, 0.9}, 300.0), doctest::Contains("give one per body"), error);
  CHECK_THROWS_WITH_AS(coupling(s, props, {0.9}, 300.0, none, thermal::tool_heat{.temperature = {300.0}}),
                       doctest::Contains("1 tool temperatures for 0 tools"), error);
  CHECK_THROWS_WITH_AS(coupling(s, props, {0.9}, 300.0, none, thermal::tool_heat{.conductance = -1.0}),
                       doctest::Contains("must be finite and not negative"), error);
}

}  // namespace test_numeric_heat_coupling
