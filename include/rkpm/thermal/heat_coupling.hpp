#pragma once
// heat_coupling<Solver>: heat conduction coupled to the explicit solver (docs/method.md section
// 5.11, (98)-(101)): the mechanical step runs as before, and every few steps the heat of those
// steps goes into the conduction field (thermal/heat_conduction.hpp), which then gives every
// quadrature point its temperature back:
//   plastic heat   beta times the plastic work of each point since the last exchange (98),
//                  scattered to the coefficients through the point's row N_I(x_q);
//   contact        friction and conduction at the tools and between bodies (99)-(100), each
//                  step (thermal/contact_heat.hpp);
//   temperatures   T_q = T^h(x_q) written into the point states (the material's set_temperature),
//                  so the flow stress of the next steps follows the field (101).
// The exchange interval is the largest whole number of mechanical steps within the conduction's
// stable step (at most max_interval): conduction costs a pass over the points per exchange, not
// per step. Between exchanges a material with a temperature heats its points adiabatically, as
// without conduction; the exchange replaces that by the conducted field, whose heat includes it.
// Attached to the solver (explicit_solver::attach, solver/step_companion.hpp), it is stepped by
// every step, saved in the solver's checkpoints and reported in the runner's history:
//   solver.attach(std::make_shared<thermal::heat_coupling<Solver>>(solver, bodies, betas, T0, ...));
// A re-reference (docs/method.md section 5.8) rebinds it (after_rebuild): the conduction on the
// new model, the coefficients T_I kept as the velocity's are (83). One process, particles at the
// mesh nodes.

#include <algorithm>
#include <cmath>
#include <vector>

#include <rkpm/core/error.hpp>
#include <rkpm/solver/fields.hpp>
#include <rkpm/solver/step_companion.hpp>
#include <rkpm/thermal/contact_heat.hpp>
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
    contact_.bind(m);
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
    contact_.add(s, dt, heat_, tools_, ledger_, heat_in_);
    if (steps_since_ >= interval(s) || !s.before_end()) {
      exchange(s);
      write_temperatures(s);
    }
  }

  // The model rebuilt (docs/method.md 5.8 and 5.11): the same particles and the same material
  // points, in the same order, so the coefficients T_I stay with their particles (the heat
  // sum_I m_I c_p T_I kept), the plastic work at the last exchange and the pending heat stay with
  // their points and particles; the conduction and the contact areas are built on the new model.
  // Reading a re-referenced checkpoint (remap_info::restart), the state is read next.
  void after_rebuild(Solver& s, const remap_info&) override {
    const discrete_model& m = s.model();
    if (m.point_count() != static_cast<index_t>(last_work_.size()) ||
        m.particle_count() != static_cast<index_t>(heat_in_.size()))
      fail("heat coupling: a model rebuilt with {} points and {} particles from {} and {}", m.point_count(),
           m.particle_count(), last_work_.size(), heat_in_.size());
    heat_.rebind(m, s.physical_mass());
    contact_.bind(m);
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

  // (98) and the conduction over the interval; then the points' temperatures (101).
  void exchange(Solver& s) {
    const discrete_model& m = s.model();
    for (index_t q = 0; q < m.point_count(); ++q) {
      const double W = plastic_work(s, q);
      const double beta = beta_[beta_.size() == 1 ? 0 : static_cast<std::size_t>(m.bodies.of_point(q))];
      // J per volume of the current reference: W_p is per initial volume (section 5.8)
      point_heat_[q] = beta * (W - last_work_[q]) * s.point_initial_volume_per_weight(q);
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
  std::vector<double> heat_in_;    // J per coefficient since the last exchange
  std::vector<double> rate_;       // W per coefficient over the interval
  contact_heat contact_;
  coupling_ledger ledger_;
  double since_ = 0.0;      // s since the last exchange
  double last_time_ = 0.0;  // the solver's time at the last step
  index_t steps_since_ = 0;
  index_t exchanges_ = 0;
};

}  // namespace rkpm::thermal
