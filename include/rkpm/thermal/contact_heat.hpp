#pragma once
// contact_heat: the heat of the contacts in one mechanical step (docs/method.md section 5.11,
// (99)-(100)), for thermal::heat_coupling, as heat (J) on the coefficients:
//   friction       at each slave in contact with a tool, -f_t . v_T (the tangential force
//                  against the slip), a fraction to the body at the slave's row, the rest to
//                  the tool (99);
//   tool contact   h_c (T_tool - T^h(x_J)) A_J at each slave in contact with a tool (100), A_J the
//                  slave's share of the body's boundary in the current configuration;
//   body contact   h_c (T^h(x_c) - T^h(x_J)) A_J from a master body's contact point x_c to a slave
//                  in contact with it, and the frictional heat half to each (100), so that
//                  what one body gains the other loses.
// It keeps the model's boundary edges and per-particle scratch: bind() again when the model is
// rebuilt (a re-reference, section 5.8).

#include <algorithm>
#include <array>
#include <vector>

#include <rkpm/concepts/contact.hpp>
#include <rkpm/solver/discrete_model.hpp>
#include <rkpm/thermal/heat_sources.hpp>
#include <rkpm/thermal/tool_heat.hpp>

namespace rkpm::thermal {

class contact_heat {
 public:
  void bind(const discrete_model& m) {
    touching_.assign(m.particle_count(), 0);
    area_.assign(m.particle_count(), 0.0);
    boundary_edges_ = m.mesh.boundary_edges();
  }

  // (99)-(100) of the step of length dt just taken, added to heat_in (J, #particles) and booked.
  // A slave's area is half of each boundary edge whose two ends touch the same tool, in the
  // current configuration, times omega (16): the body's contact length, without the sides at its
  // corners.
  template <class Solver, class Conduction>
  void add(const Solver& s, double dt, const Conduction& heat, const tool_heat& tools, coupling_ledger& ledger,
           std::vector<double>& heat_in) {
    if constexpr (ReportsToolPairs<typename Solver::contact_type>) tool_contact(s, dt, heat, tools, ledger, heat_in);
    if constexpr (ReportsBodyPairs<typename Solver::contact_type>) body_contact(s, dt, heat, tools, ledger, heat_in);
  }

 private:
  // A_J of (100): half of each boundary edge whose two ends carry the same contact mark
  // (touching_), in the current configuration, times omega (16). Only those edges' ends are
  // interpolated: no pass over the body in the step.
  template <class Solver>
  void add_contact_areas(const Solver& s) {
    const discrete_model& m = s.model();
    const auto position = [&](index_t I) {
      return vec2(m.particles.position[I] + m.at_particles.interpolate(I, s.coefficients()));
    };
    for (const auto& [a, b] : boundary_edges_)
      if (touching_[a] != 0 && touching_[a] == touching_[b]) {
        const vec2 xa = position(a), xb = position(b);
        const double half = 0.5 * (xb - xa).norm();
        area_[a] += half * Solver::geometry_type::weight_factor(xa);
        area_[b] += half * Solver::geometry_type::weight_factor(xb);
      }
  }

  template <class Solver, class Conduction>
  void tool_contact(const Solver& s, double dt, const Conduction& heat, const tool_heat& tools,
                    coupling_ledger& ledger, std::vector<double>& heat_in) {
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
      ledger.friction += friction;
      ledger.friction_to_body += tools.friction_to_body * friction;
      add_particle_heat(m, J, tools.friction_to_body * friction, heat_in);
      touching_[J] = p.tool + 1;
    }
    if (!tools.temperature.empty()) {
      add_contact_areas(s);
      for (const auto& p : pairs) {
        const index_t J = s.slave_particles()[p.slave];
        const double T_tool = tools.temperature[p.tool](t);
        const double conducted = tools.conductance * (T_tool - heat.temperature_at_particle(J)) * area_[J] * dt;
        ledger.from_tools += conducted;
        add_particle_heat(m, J, conducted, heat_in);
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
  template <class Solver, class Conduction>
  void body_contact(const Solver& s, double dt, const Conduction& heat, const tool_heat& tools,
                    coupling_ledger& ledger, std::vector<double>& heat_in) {
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
      const double T_master = wa * heat.temperature_at_particle(p.a) + wb * heat.temperature_at_particle(p.b);
      const double conducted =
          tools.conductance * (T_master - heat.temperature_at_particle(p.slave)) * area_[p.slave] * dt;
      ledger.friction += friction;
      ledger.friction_to_body += friction;  // both halves stay in the bodies
      ledger.between_bodies += conducted;
      const double to_slave = 0.5 * friction + conducted, to_master = 0.5 * friction - conducted;
      add_particle_heat(m, p.slave, to_slave, heat_in);
      add_particle_heat(m, p.a, wa * to_master, heat_in);
      add_particle_heat(m, p.b, wb * to_master, heat_in);
    });
    each([&](const auto& p) { touching_[p.slave] = 0, area_[p.slave] = 0.0; });
  }

  std::vector<index_t> touching_;  // per particle: 1 + the tool it touches this step, -(1 + pair), or 0
  std::vector<double> area_;       // per particle: its contact area this step
  std::vector<std::array<index_t, 2>> boundary_edges_;
};

}  // namespace rkpm::thermal
