#pragma once
// particle_to_segment<Enforcement, Friction>: the paper's contact subroutine against moving
// rigid tools (docs/method.md section 6, (P4)-(P7) = (56)-(59)).
// enforce(body, t_next, dt, d, v), with d = d_{n+1} predicted and v = v_{n+1/2}, tools at t_next:
//   (i)   slave positions x_J = X_J + sum_I N_I(X_J) d_I and velocities v_J = sum_I N_I(X_J) v_I;
//         per tool, the master segment each penetrating slave crossed (segment_search.hpp),
//         found through a grid in the tool frame (segment_grid.hpp);
//   (ii)  normal force (P4) along the segment normal n (out of the tool, toward the body), and the
//         tangential force from the sticking force (P6) limited by the friction law (P5), with
//         v_T the tangential velocity of J relative to the tool; redistribution (P7)
//         f_I = sum_J N_I(X_J) f_J. The enforcement policy gets the slave's own mass m_J and its
//         effective mass among the slaves in contact this step, m_sh (61a,
//         shared_effective_mass.hpp), which is (61) for an isolated slave;
//   (iii) da_I = f_I / m_I;   (iv) v_I += dt da_I, d_I += dt^2 da_I.
// The tool velocity used for v_T is its mean over the step, (u(t) - u(t - dt)) / dt, the one
// consistent with d_{n+1} = d_n + dt v_{n+1/2}; it equals the tool velocity for fixed and
// constant-velocity tools.
// Reported per step: the reaction on each tool (minus the sum of the contact forces its segments
// applied), the largest penetration before correction and the number of slave particles in
// contact. The work of the contact forces is booked by the solver's energy ledger
// (solver/energy.hpp, impulse_work), the same formula as for the constraints.
// Then, when asked for, the pairs of deformable bodies (body_contact.hpp: a body's slaves against
// another's surface) and the tools' vertices against the bodies' surfaces
// (tool_vertex_contact.hpp), each on the configuration the previous pass left.
// enforce() does not allocate: setup() sizes every buffer.

#include <algorithm>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include <rkpm/concepts/contact.hpp>
#include <rkpm/core/joined_name.hpp>
#include <rkpm/contact/body_contact.hpp>
#include <rkpm/contact/contact_checks.hpp>
#include <rkpm/contact/contact_pair.hpp>
#include <rkpm/contact/enforcement.hpp>
#include <rkpm/contact/friction.hpp>
#include <rkpm/contact/rigid_tool.hpp>
#include <rkpm/contact/segment_grid.hpp>
#include <rkpm/contact/segment_search.hpp>
#include <rkpm/contact/surface_scratch.hpp>
#include <rkpm/contact/tool_vertex_contact.hpp>
#include <rkpm/contact/shared_effective_mass.hpp>
#include <rkpm/core/error.hpp>
#include <rkpm/io/checkpoint.hpp>

namespace rkpm::contact {

template <ContactEnforcement Enforcement = enforcement::paper, FrictionLaw Friction = friction::frictionless>
class particle_to_segment {
 public:
  using enforcement_type = Enforcement;
  using friction_type = Friction;
  // "paper+coulomb": enforcement and friction law.
  static constexpr std::string_view name = joined_name<Enforcement::name, Friction::name>::value;

  explicit particle_to_segment(std::vector<rigid_tool> tools, Friction friction = {}, Enforcement enforcement = {})
      : tools_(std::move(tools)), friction_(friction), enforcement_(enforcement) {
    friction_.validate();
    enforcement_.validate();
    for (const rigid_tool& tool : tools_) grid_.emplace_back(tool);
    reaction_.assign(tools_.size(), vec2::Zero());
  }
  // Rigid tools and pairs of deformable bodies in contact (body_contact.hpp); either may be empty.
  particle_to_segment(std::vector<rigid_tool> tools, std::vector<body_pair> body_pairs, Friction friction = {},
                      Enforcement enforcement = {})
      : particle_to_segment(std::move(tools), friction, enforcement) {
    bodies_ = body_contact(std::move(body_pairs));
  }

  const std::vector<rigid_tool>& tools() const { return tools_; }
  const std::vector<segment_grid>& grids() const { return grid_; }
  const std::vector<body_pair>& body_pairs() const { return bodies_.pairs(); }
  // Two-pass tool contact: the tools' vertices also checked as slaves against the bodies'
  // surfaces (tool_vertex_contact.hpp), so that a sharp corner cannot slip between two surface
  // particles. Set before the solver is built.
  void set_tool_vertex_slaves(bool on) { tool_vertex_slaves_ = on; }
  bool tool_vertex_slaves() const { return tool_vertex_slaves_; }
  // Contacts between bodies in the last step.
  const body_contact& bodies() const { return bodies_; }
  // Reaction on each tool in the last step (minus the contact forces it applied).
  const std::vector<vec2>& reactions() const { return reaction_; }
  // The contacts of the last step.
  std::span<const contact_pair> active_pairs() const { return {pair_.data(), static_cast<std::size_t>(pairs_)}; }
  // m_eff of each slave, 1 / sum_I N_I(X_J)^2 / m_I.
  const std::vector<double>& effective_masses() const { return m_eff_; }
  const Friction& friction() const { return friction_; }
  const Enforcement& enforcement() const { return enforcement_; }

  // Checkpoint (io/checkpoint.hpp): what the next enforce() reads from the last one (held
  // segments, slave and tool positions for the crossing test) and the last step's report.
  void save(io::checkpoint_writer& w) const {
    sections(w, *this);
    w.array("contact.pairs", std::span<const contact_pair>(pair_.data(), static_cast<std::size_t>(pairs_)));
  }
  void load(io::checkpoint_reader& r) {
    sections(r, *this);
    pairs_ = static_cast<index_t>(r.array("contact.pairs", std::span<contact_pair>(pair_)));
  }

  // Checks the body and the slaves and copies the slave list and table; the body itself is
  // passed again on every enforce().
  void setup(const contact_body& body, const contact_slaves& slaves) {
    check_contact_inputs(body, slaves);
    const index_t np = static_cast<index_t>(body.reference_position.size());
    slave_ = slaves.particle;
    table_ = slaves.table;
    reached_ = compact_columns(table_, np);
    const index_t ns = static_cast<index_t>(slave_.size());

    m_eff_.assign(ns, 0.0);
    for (index_t j = 0; j < ns; ++j) {
      double s = 0.0;
      for (index_t e = table_.offset[j]; e < table_.offset[j + 1]; ++e)
        s += table_.N[e] * table_.N[e] / body.mass[reached_[table_.neighbor[e]]];
      if (!(s > 0.0))
        fail("contact setup: slave {} (particle {}) has no shape function support; check the slave table", j,
             slave_[j]);
      m_eff_[j] = 1.0 / s;
    }

    check_tools_outside(tools_, grid_, body.reference_position);

    const index_t nt = static_cast<index_t>(tools_.size());
    x_.assign(ns, vec2::Zero());
    v_.assign(ns, vec2::Zero());
    x_prev_.resize(ns);
    for (index_t j = 0; j < ns; ++j) x_prev_[j] = body.reference_position[slave_[j]];
    u_prev_.resize(nt);
    u_now_.resize(nt);
    v_tool_.resize(nt);
    for (index_t k = 0; k < nt; ++k) u_prev_[k] = tools_[k].displacement(0.0);
    held_.assign(ns * nt, -1);
    pair_.assign(ns * nt, contact_pair{});
    pairs_ = 0;
    in_contact_.assign(ns, 0);
    m_shared_.assign(ns * nt, 0.0);
    const auto reached = static_cast<index_t>(reached_.size());
    reached_mass_.resize(reached);
    for (index_t r = 0; r < reached; ++r) reached_mass_[r] = body.mass[reached_[r]];
    shared_mass_.setup(reached);
    increments_.resize(reached);
    reaction_.assign(nt, vec2::Zero());
    bodies_.setup(body, slave_);
    if (tool_vertex_slaves_) {
      std::size_t vertices = 0;
      for (const rigid_tool& tool : tools_) vertices += tool.reference_vertices().size();
      tool_vertices_.setup(body, vertices);
    }
    ready_ = true;
  }

  contact_result enforce(const contact_body& body, double t, double dt, std::vector<vec2>& d, std::vector<vec2>& v) {
    if (!ready_) fail("contact: enforce() called before setup(); the solver must call setup(body, slaves) once");
    const std::size_t np = body.reference_position.size();
    if (d.size() != np || v.size() != np)
      fail("contact: {} displacements and {} velocities for {} particles", d.size(), v.size(), np);
    if (!(dt > 0.0)) fail("contact: time step {} must be positive", dt);
    contact_result result;
    const index_t ns = static_cast<index_t>(slave_.size());
    const index_t nt = static_cast<index_t>(tools_.size());
    const std::span<const double> m = body.mass;
    const std::span<const vec2> X = body.reference_position;

    // (i) physical slave positions and velocities on the predicted configuration.
#pragma omp parallel for schedule(static) if (ns > parallel_slaves)
    for (index_t j = 0; j < ns; ++j) slave_state(X, j, d, v);
    for (index_t k = 0; k < nt; ++k) {
      u_now_[k] = tools_[k].displacement(t);
      v_tool_[k] = (u_now_[k] - tools_[k].displacement(t - dt)) / dt;
      reaction_[k].setZero();
    }
    pairs_ = 0;
    for (index_t k = 0; k < nt; ++k) {
      const rigid_tool& tool = tools_[k];
      for (index_t j = 0; j < ns; ++j) {
        index_t& held = held_[k * ns + j];
        const vec2 y = x_[j] - u_now_[k];
        const auto candidates = grid_[k].candidates(y);
        if (candidates.empty()) {
          held = -1;
          continue;
        }
        const segment_hit hit = choose_segment(tool, candidates, y, vec2(x_prev_[j] - u_prev_[k]), held);
        held = hit.segment;
        if (hit.segment < 0) continue;
        contact_pair& p = pair_[pairs_++];
        p = contact_pair{j, k, hit.segment, hit.gap, tool.normal(hit.segment), 0.0, vec2::Zero()};
        result.max_penetration = std::max(result.max_penetration, hit.gap);
        if (!in_contact_[j]) {
          in_contact_[j] = 1;
          ++result.active;
        }
      }
    }

    // (ii)-(iv), repeated for effective-mass sweeps: each sweep computes every pair's force
    // increment on the same configuration (Jacobi), then applies them together.
    shared_mass_.compute(active_pairs(), table_, reached_mass_, std::span<double>(m_shared_.data(), pairs_));
    for (int sweep = 0; sweep < enforcement_.sweeps && pairs_ > 0; ++sweep) {
      const double omega = sweep == 0 ? 1.0 : enforcement_.relaxation;
      if (sweep > 0)
        for (index_t q = 0; q < pairs_; ++q) slave_state(X, pair_[q].slave, d, v);
      for (index_t q = 0; q < pairs_; ++q) {
        contact_pair& p = pair_[q];
        const index_t j = p.slave;
        const rigid_tool& tool = tools_[p.tool];
        const double g =
            sweep == 0 ? p.gap : -tool.project(p.segment, vec2(x_[j] - u_now_[p.tool])).distance;
        const double m_s = m[slave_[j]];
        const vec2 rel = v_[j] - v_tool_[p.tool];
        const vec2 v_t = rel - rel.dot(p.normal) * p.normal;
        const double fn = std::max(0.0, p.normal_force + omega * enforcement_.normal_force(g, dt, m_s, m_shared_[q]));
        const vec2 trial = p.tangential_force - omega * enforcement_.stick_mass(m_s, m_shared_[q]) * v_t / dt;
        const vec2 ft = friction_.limit(trial, fn);
        const vec2 df = (fn - p.normal_force) * p.normal + (ft - p.tangential_force);
        p.normal_force = fn;
        p.tangential_force = ft;
        increments_.spread(table_, j, 1.0, df);  // (P7)
      }
      increments_.apply(m, dt, d, v, reached_);
    }

    for (index_t q = 0; q < pairs_; ++q) {
      reaction_[pair_[q].tool] -= pair_[q].force();
      in_contact_[pair_[q].slave] = 0;
    }
    // Then the pairs of deformable bodies (body_contact.hpp).
    bodies_.enforce(body, dt, enforcement_, friction_, d, v, result);
    tool_vertices_.enforce(body, tools_, u_now_, v_tool_, dt, enforcement_, friction_, d, v, result, reaction_);
    // Remember where the slaves ended up, for the crossing test of the next call.
    if (pairs_ > 0 || !bodies_.empty() || tool_vertices_.enabled())
#pragma omp parallel for schedule(static) if (ns > parallel_slaves)
      for (index_t j = 0; j < ns; ++j) {
        vec2 u = vec2::Zero();
        for (index_t e = table_.offset[j]; e < table_.offset[j + 1]; ++e) u += table_.N[e] * d[reached_[table_.neighbor[e]]];
        x_[j] = X[slave_[j]] + u;
      }
    std::swap(x_prev_, x_);
    for (index_t k = 0; k < nt; ++k) u_prev_[k] = u_now_[k];
    return result;
  }

 private:
  template <class Archive, class Self>
  static void sections(Archive& a, Self& s) {
    a.array("contact.held", s.held_);
    a.array("contact.x_prev", s.x_prev_);
    a.array("contact.u_prev", s.u_prev_);
    a.array("contact.reaction", s.reaction_);
  }

  void slave_state(std::span<const vec2> X, index_t j, const std::vector<vec2>& d, const std::vector<vec2>& v) {
    vec2 u = vec2::Zero(), w = vec2::Zero();
    for (index_t e = table_.offset[j]; e < table_.offset[j + 1]; ++e) {
      const index_t I = reached_[table_.neighbor[e]];
      u += table_.N[e] * d[I];
      w += table_.N[e] * v[I];
    }
    x_[j] = X[slave_[j]] + u;
    v_[j] = w;
  }

  // Below this many slaves the per-slave loops run on one thread (a parallel region costs more).
  static constexpr index_t parallel_slaves = 2048;

  std::vector<rigid_tool> tools_;
  std::vector<segment_grid> grid_;
  body_contact bodies_;
  bool tool_vertex_slaves_ = false;
  tool_vertex_contact tool_vertices_;
  Friction friction_;
  Enforcement enforcement_;

  std::vector<index_t> slave_;
  // Rows: slaves; columns: the particles the rows reach (reached_[c] is the particle of column
  // c), so the per-coefficient scratch is as long as the slaves' neighbourhood, not the body.
  shape_table<2> table_;
  std::vector<stored_index> reached_;
  std::vector<double> m_eff_;
  bool ready_ = false;

  // Scratch, sized in setup().
  std::vector<vec2> x_, v_, x_prev_;          // #slaves
  std::vector<vec2> u_prev_, u_now_, v_tool_;  // #tools
  std::vector<index_t> held_;                  // #tools x #slaves: segment of the previous call
  std::vector<contact_pair> pair_;             // capacity #tools x #slaves
  index_t pairs_ = 0;
  std::vector<char> in_contact_;               // #slaves
  std::vector<double> m_shared_;               // m_sh (61a) of each active pair, capacity #tools x #slaves
  std::vector<double> reached_mass_;           // the masses of reached_ (constant), for shared_mass_
  shared_effective_mass shared_mass_;          // #columns
  coefficient_increments increments_;          // #columns
  std::vector<vec2> reaction_;                 // #tools
};

}  // namespace rkpm::contact
