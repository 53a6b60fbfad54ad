#pragma once
// heat_coupling<Solver>: heat conduction coupled to the explicit solver (docs/method.md section
// 5.11, (98)-(101)): the mechanical step runs as before, and every few steps the heat of those
// steps goes into the conduction field (thermal/heat_conduction.hpp), which then gives every
// quadrature point its temperature back:
//   plastic heat   beta times the plastic work of each point since the last exchange (98),
//                  scattered to the coefficients through the point's row N_I(x_q);
//   friction       at each slave in contact with a tool, -f_t . v_T (the tangential force
//                  against the slip), a fraction to the body at the slave's row, the rest to
//                  the tool (99);
//   tool contact   h_c (T_tool - T^h(x_J)) A_J at each slave in contact with a tool (100), A_J the
//                  slave's share of the body's boundary in the current configuration;
//   body contact   h_c (T^h(x_c) - T^h(x_J)) A_J from a master body's contact point x_c to a slave
//                  in contact with it, and the frictional heat half to each (100), so that
//                  what one body gains the other loses;
//   temperatures   T_q = T^h(x_q) written into the point states (the material's set_temperature),
//                  so the flow stress of the next steps follows the field (101).
// The exchange interval is the largest whole number of mechanical steps within the conduction's
// stable step (at most max_interval): conduction costs a pass over the points per exchange, not
// per step. Between exchanges a material with a temperature heats its points adiabatically, as
// without conduction; the exchange replaces that by the conducted field, whose heat includes it.
// Attached to the solver (explicit_solver::attach, solver/step_companion.hpp), it is stepped by
// every step, saved in the solver's checkpoints and reported in the runner's history:
//   solver.attach(std::make_shared<thermal::heat_coupling<Solver>>(solver, bodies, betas, T0, ...));
// One process, a Lagrangian run (no re-referencing), particles at the mesh nodes.

#include <algorithm>
#include <cmath>
#include <vector>

#include <rkpm/core/error.hpp>
#include <rkpm/solver/fields.hpp>
#include <rkpm/solver/step_companion.hpp>
#include <rkpm/thermal/heat_conduction.hpp>
#include <rkpm/thermal/heat_sources.hpp>
#include <rkpm/thermal/tool_heat.hpp>

namespace rkpm::thermal {

template <class Solver>
class heat_coupling : public step_companion<Solver> {
 public:
  using geometry_type = typename Solver::geometry_type;

  // bodies: one thermal_properties per body; taylor_quinney: beta per body (98).
  heat_coupling(Solver& s, std::vector<thermal_properties> bodies, std::vector<double> taylor_quinney,
                double initial_temperature, std::vector<thermal_boundary> boundaries = {}, tool_heat tools = {},
                index_t max_interval = 50)
      : heat_(s.model(), std::move(bodies), s.physical_mass(), initial_temperature, std::move(boundaries)),
        beta_(std::move(taylor_quinney)),
        tools_(std::move(tools)),
        max_interval_(max_interval) {
    const discrete_model& m = s.model();
    if (s.options().rereference.enabled())
      fail("heat conduction with re-referencing is not available yet: run without \"rereference\"");
    if (!m.bodies.nodes_are_particles())
      fail("heat conduction's contact areas need the particles at the mesh nodes (make_grid_particles with "
           "make_grid_mesh, or particles from the mesh)");
    if (beta_.size() != static_cast<std::size_t>(std::max<index_t>(1, s.bodies())))
      fail("heat coupling: {} Taylor-Quinney fractions for {} bodies: give one per body", beta_.size(), s.bodies());
    for (double b : beta_)
      if (!(b >= 0.0 && b <= 1.0)) fail("heat coupling: a Taylor-Quinney fraction of {} must lie in [0, 1]", b);
    tools_.validate(std::ranges::size(s.contact().tools()));
    if (max_interval_ < 1) fail("heat coupling: max_interval {} must be at least 1", max_interval_);
    heat_.impose_fixed_temperatures();
    last_work_.assign(m.point_count(), 0.0);
    for (index_t q = 0; q < m.point_count(); ++q) last_work_[q] = plastic_work(s, q);
    point_heat_.assign(m.point_count(), 0.0);
    rate_.assign(m.particle_count(), 0.0);
    heat_in_.assign(m.particle_count(), 0.0);
    touching_.assign(m.particle_count(), 0);
    area_.assign(m.particle_count(), 0.0);
    boundary_edges_ = m.mesh.boundary_edges();
    last_time_ = s.time();
    write_temperatures(s);
  }

  // The heat of the step just taken; the exchange when its interval is complete or the run has
  // reached its end time.
  void after_step(Solver& s) override {
    heat_.use_model(s.model());
    const double dt = s.time() - last_time_;
    last_time_ = s.time();
    ++steps_since_;
    since_ += dt;
    contact_heat(s, dt);
    if (steps_since_ >= interval(s) || !s.before_end()) {
      exchange(s);
      write_temperatures(s);
    }
  }

  void save(io::checkpoint_writer& w) const override { sections(w, *this); }
  void load(io::checkpoint_reader& r) override { sections(r, *this); }

  // The heat flows (J) and the temperatures at the particles (K).
  std::vector<std::pair<std::string, double>> report(const Solver& s) const override {
    heat_.use_model(s.model());
    const heat_ledger& l = heat_.ledger();
    const std::vector<double> T = heat_.particle_temperatures();
    const auto [lo, hi] = std::minmax_element(T.begin(), T.end());
    return {{"heat_stored_J", l.stored},
            {"heat_plastic_J", ledger_.plastic},
            {"heat_friction_J", ledger_.friction},
            {"heat_friction_to_body_J", ledger_.friction_to_body},
            {"heat_from_tools_J", ledger_.from_tools},
            {"heat_between_bodies_J", ledger_.between_bodies},
            {"heat_convection_J", l.convection},
            {"heat_flux_J", l.flux},
            {"heat_fixed_J", l.fixed},
            {"heat_balance_error", l.relative_imbalance()},
            {"temperature_min_K", *lo},
            {"temperature_mean_K", mean_temperature()},
            {"temperature_max_K", *hi}};
  }

  // A field other than the initial temperature's, T_I at each particle (K; a body's value on
  // all of its particles is that value everywhere in it), the fixed temperatures imposed on it.
  void set_temperatures(Solver& s, std::vector<double> T) {
    heat_.use_model(s.model());
    heat_.set_coefficients(std::move(T));
    heat_.impose_fixed_temperatures();
    write_temperatures(s);
  }
  const heat_conduction<geometry_type>& conduction() const { return heat_; }
  // The capacity-weighted mean temperature, sum C_I T_I / sum C_I (K).
  double mean_temperature() const {
    const std::vector<double>& C = heat_.capacities();
    const std::vector<double>& T = heat_.coefficients();
    double ct = 0.0, c = 0.0;
    for (std::size_t I = 0; I < C.size(); ++I) ct += C[I] * T[I], c += C[I];
    return ct / c;
  }
  const coupling_ledger& ledger() const { return ledger_; }
  // The temperatures at the particles, T^h(x_I) (K).
  std::vector<double> particle_temperatures() const { return heat_.particle_temperatures(); }
  index_t exchanges() const { return exchanges_; }

 private:
  static double plastic_work(const Solver& s, index_t q) {
    if constexpr (requires { s.point_states()[q].plastic_work; }) return s.point_states()[q].plastic_work;
    else return 0.0;
  }

  index_t interval(const Solver& s) const {
    const double bound = heat_.stable_time_step() / s.time_step();
    return std::clamp<index_t>(static_cast<index_t>(std::floor(bound)), 1, max_interval_);
  }

  template <class Archive, class Self>
  static void sections(Archive& a, Self& s) {
    a.part(s.heat_);
    a.value("heat.coupling_ledger", s.ledger_);
    a.array("heat.last_plastic_work", s.last_work_);
    a.array("heat.pending", s.heat_in_);
    for (auto [name, field] : {std::pair{"heat.since", &s.since_}, {"heat.last_time", &s.last_time_}})
      a.value(name, *field);
    for (auto [name, field] : {std::pair{"heat.steps_since", &s.steps_since_}, {"heat.exchanges", &s.exchanges_}})
      a.value(name, *field);
  }

  // (101): every point at the field's temperature, when the material has one.
  void write_temperatures(Solver& s) const {
    if constexpr (TemperatureState<typename Solver::state_type>)
      s.set_point_temperatures([&](index_t q) { return heat_.temperature_at_point(q); });
  }

  // (99)-(100) of the step just taken, as heat (J) on the coefficients. A slave's area is half of
  // each boundary edge whose two ends touch the same tool, in the current configuration, times
  // omega (16): the body's contact length, without the sides at its corners.
  void contact_heat(const Solver& s, double dt) {
    if constexpr (ReportsToolPairs<typename Solver::contact_type>) tool_contact_heat(s, dt);
    if constexpr (ReportsBodyPairs<typename Solver::contact_type>) body_contact_heat(s, dt);
  }

  // A_J of (100): half of each boundary edge whose two ends carry the same contact mark
  // (touching_), in the current configuration, times omega (16). Only those edges' ends are
  // interpolated: no pass over the body in the step.
  void add_contact_areas(const Solver& s) {
    const discrete_model& m = s.model();
    const auto position = [&](index_t I) {
      return vec2(m.particles.position[I] + m.at_particles.interpolate(I, s.coefficients()));
    };
    for (const auto& [a, b] : boundary_edges_)
      if (touching_[a] != 0 && touching_[a] == touching_[b]) {
        const vec2 xa = position(a), xb = position(b);
        const double half = 0.5 * (xb - xa).norm();
        area_[a] += half * geometry_type::weight_factor(xa);
        area_[b] += half * geometry_type::weight_factor(xb);
      }
  }

  void tool_contact_heat(const Solver& s, double dt) {
    const auto pairs = s.contact().active_pairs();
    if (pairs.empty()) return;
    const discrete_model& m = s.model();
    const double t = s.time();
    const std::vector<vec2>& v = s.coefficient_velocities();
    for (const auto& p : pairs) {
      const index_t J = s.slave_particles()[p.slave];
      const auto& tool = s.contact().tools()[p.tool];
      const vec2 v_tool = (tool.displacement(t) - tool.displacement(t - dt)) / dt;
      const vec2 rel = m.at_particles.interpolate(J, v) - v_tool;
      const vec2 slip = rel - rel.dot(p.normal) * p.normal;
      const double friction = std::max(0.0, -p.tangential_force.dot(slip)) * dt;
      ledger_.friction += friction;
      ledger_.friction_to_body += tools_.friction_to_body * friction;
      add_particle_heat(m, J, tools_.friction_to_body * friction, heat_in_);
      touching_[J] = p.tool + 1;
    }
    if (!tools_.temperature.empty()) {
      add_contact_areas(s);
      for (const auto& p : pairs) {
        const index_t J = s.slave_particles()[p.slave];
        const double T_tool = tools_.temperature[p.tool](t);
        const double conducted = tools_.conductance * (T_tool - heat_.temperature_at_particle(J)) * area_[J] * dt;
        ledger_.from_tools += conducted;
        add_particle_heat(m, J, conducted, heat_in_);
      }
    }
    for (const auto& p : pairs) {
      const index_t J = s.slave_particles()[p.slave];
      touching_[J] = 0;
      area_[J] = 0.0;
    }
  }

  // (99)-(100) between deformable bodies: each slave J against its master segment (a, b) at the
  // contact point (1 - lambda) x_a + lambda x_b, the slave's area as for the tools; none at crack faces.
  void body_contact_heat(const Solver& s, double dt) {
    const auto pairs = s.contact().bodies().active_pairs();
    if (pairs.empty()) return;
    const discrete_model& m = s.model();
    const std::vector<vec2>& v = s.coefficient_velocities();
    const auto each = [&, n = m.particle_count()](auto&& f) {  // faces' virtual points are numbered after n
      for (const auto& p : pairs) if (p.slave < n && p.a < n && p.b < n) f(p);
    };
    each([&](const auto& p) { touching_[p.slave] = -(p.pair + 1); });
    add_contact_areas(s);
    each([&](const auto& p) {
      const double wa = 1.0 - p.lambda, wb = p.lambda;
      const vec2 rel = m.at_particles.interpolate(p.slave, v) -
                       (wa * m.at_particles.interpolate(p.a, v) + wb * m.at_particles.interpolate(p.b, v));
      const vec2 slip = rel - rel.dot(p.normal) * p.normal;
      const double friction = std::max(0.0, -p.tangential_force.dot(slip)) * dt;
      const double T_master = wa * heat_.temperature_at_particle(p.a) + wb * heat_.temperature_at_particle(p.b);
      const double conducted =
          tools_.conductance * (T_master - heat_.temperature_at_particle(p.slave)) * area_[p.slave] * dt;
      ledger_.friction += friction;
      ledger_.friction_to_body += friction;  // both halves stay in the bodies
      ledger_.between_bodies += conducted;
      const double to_slave = 0.5 * friction + conducted, to_master = 0.5 * friction - conducted;
      add_particle_heat(m, p.slave, to_slave, heat_in_);
      add_particle_heat(m, p.a, wa * to_master, heat_in_);
      add_particle_heat(m, p.b, wb * to_master, heat_in_);
    });
    each([&](const auto& p) { touching_[p.slave] = 0, area_[p.slave] = 0.0; });
  }

  // (98) and the conduction over the interval; then the points' temperatures (101).
  void exchange(Solver& s) {
    const discrete_model& m = s.model();
    for (index_t q = 0; q < m.point_count(); ++q) {
      const double W = plastic_work(s, q);
      const double beta = beta_[beta_.size() == 1 ? 0 : static_cast<std::size_t>(m.bodies.of_point(q))];
      point_heat_[q] = beta * (W - last_work_[q]);  // J per reference volume
      ledger_.plastic += point_heat_[q] * m.points.weight[q];
      last_work_[q] = W;
    }
    add_point_heat(m, point_heat_, heat_in_);
    for (std::size_t I = 0; I < rate_.size(); ++I) {
      rate_[I] = heat_in_[I] / since_;
      heat_in_[I] = 0.0;
    }
    heat_.update_boundary_geometry(s.particle_positions());
    heat_.advance(since_, [&](index_t q) { return s.point_relative_deformation_gradient(q); }, rate_);
    since_ = 0.0;
    steps_since_ = 0;
    ++exchanges_;
  }

  mutable heat_conduction<geometry_type> heat_;  // mutable: its model pointer follows the solver
  std::vector<double> beta_;
  tool_heat tools_;
  index_t max_interval_;
  std::vector<double> last_work_;  // W_p per point at the last exchange (J/m^3)
  std::vector<double> point_heat_;  // beta (W_p - W_p^last) per point (J/m^3)
  std::vector<index_t> touching_;   // per particle: 1 + the tool it touches this step, or 0
  std::vector<double> area_;        // per particle: its contact area this step
  std::vector<double> heat_in_;    // J per coefficient since the last exchange
  std::vector<double> rate_;       // W per coefficient over the interval
  std::vector<std::array<index_t, 2>> boundary_edges_;
  coupling_ledger ledger_;
  double since_ = 0.0;      // s since the last exchange
  double last_time_ = 0.0;  // the solver's time at the last step
  index_t steps_since_ = 0;
  index_t exchanges_ = 0;
};

}  // namespace rkpm::thermal
