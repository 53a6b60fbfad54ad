#pragma once
// tool_slave_contact: the body's slave particles against moving rigid tools, the paper's contact
// subroutine (docs/method.md section 6, (P4)-(P7) = (56)-(59)); the first pass of
// particle_to_segment.hpp. enforce(body, t_next, dt, ..., d, v), with d = d_{n+1} predicted and
// v = v_{n+1/2}, tools at t_next:
//   (i)   slave positions x_J = X_J + sum_I N_I(X_J) d_I and velocities v_J = sum_I N_I(X_J) v_I;
//         per tool, the master segment each penetrating slave crossed (segment_search.hpp),
//         found through a grid in the tool frame (segment_grid.hpp);
//   (ii)  normal force (P4) along the segment normal n (out of the tool, toward the body), and the
//         tangential force from the sticking force (P6) limited by the friction law (P5), with
//         v_T the tangential velocity of J relative to the tool (contact_kernel.hpp);
//         redistribution (P7) f_I = sum_J N_I(X_J) f_J. The enforcement policy gets the slave's
//         own mass m_J and its effective mass among the slaves in contact this step, m_sh (61a,
//         shared_effective_mass.hpp), which is (61) for an isolated slave;
//   (iii) da_I = f_I / m_I;   (iv) v_I += dt da_I, d_I += dt^2 da_I;
// (ii)-(iv) in the enforcement's sweeps (contact_sweeps.hpp).
// The tool velocity used for v_T is its mean over the step, (u(t) - u(t - dt)) / dt, the one
// consistent with d_{n+1} = d_n + dt v_{n+1/2}; it equals the tool velocity for fixed and
// constant-velocity tools. end_step() remembers where the slaves and tools ended up, for the
// crossing test of the next step. Neither allocates: setup() sizes every buffer.

#include <algorithm>
#include <span>
#include <utility>
#include <vector>

#include <rkpm/concepts/contact.hpp>
#include <rkpm/contact/contact_checks.hpp>
#include <rkpm/contact/contact_pair.hpp>
#include <rkpm/contact/contact_sweeps.hpp>
#include <rkpm/contact/rigid_tool.hpp>
#include <rkpm/contact/segment_grid.hpp>
#include <rkpm/contact/segment_search.hpp>
#include <rkpm/contact/shared_effective_mass.hpp>
#include <rkpm/contact/surface_scratch.hpp>
#include <rkpm/io/checkpoint.hpp>

namespace rkpm::contact {

class tool_slave_contact {
 public:
  tool_slave_contact() = default;
  explicit tool_slave_contact(std::vector<rigid_tool> tools) : tools_(std::move(tools)) {
    for (const rigid_tool& tool : tools_) grid_.emplace_back(tool);
    reaction_.assign(tools_.size(), vec2::Zero());
  }

  const std::vector<rigid_tool>& tools() const { return tools_; }
  const std::vector<segment_grid>& grids() const { return grid_; }
  const std::vector<index_t>& slaves() const { return slave_; }
  // Reaction on each tool in the last step (minus the contact forces it applied); the tools'
  // vertices' pass (tool_vertex_contact.hpp) adds its own through mutable_reactions().
  const std::vector<vec2>& reactions() const { return reaction_; }
  std::span<vec2> mutable_reactions() { return reaction_; }
  // Each tool's displacement at t_n+1 and its mean velocity over the last step.
  std::span<const vec2> displacements() const { return u_now_; }
  std::span<const vec2> velocities() const { return v_tool_; }
  // The contacts of the last step.
  std::span<const contact_pair> active_pairs() const { return {pair_.data(), static_cast<std::size_t>(pairs_)}; }

  // Checkpoint (io/checkpoint.hpp): what the next enforce() reads from the last one (held
  // segments, slave and tool positions for the crossing test) and the last step's report.
  void save(io::checkpoint_writer& w) const {
    sections(w, *this);
    w.array("contact.pairs", active_pairs());
  }
  void load(io::checkpoint_reader& r) {
    sections(r, *this);
    pairs_ = static_cast<index_t>(r.array("contact.pairs", std::span<contact_pair>(pair_)));
  }

  // Checks the body and the slaves and copies the slave list and table.
  void setup(const contact_body& body, const contact_slaves& slaves) {
    check_contact_inputs(body, slaves);
    const index_t np = static_cast<index_t>(body.reference_position.size());
    slave_ = slaves.particle;
    table_ = slaves.table;
    reached_ = compact_columns(table_, np);
    const index_t ns = static_cast<index_t>(slave_.size());
    if (!body.deformed_reference) check_tools_outside(tools_, grid_, body.reference_position);

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
  }

  // After the solver re-referenced its model (the same slaves, new shape-function rows): the rows
  // and what is derived from them are taken again; what the last step left (the slaves' and the
  // tools' positions, the held segments) stays, so the next step continues as it would have.
  void rebind(const contact_body& body, const contact_slaves& slaves) {
    if (slaves.particle != slave_) fail("contact: rebind() with other slave particles than setup() had");
    const index_t np = static_cast<index_t>(body.reference_position.size());
    table_ = slaves.table;
    reached_ = compact_columns(table_, np);
    const auto reached = static_cast<index_t>(reached_.size());
    reached_mass_.resize(reached);
    for (index_t r = 0; r < reached; ++r) reached_mass_[r] = body.mass[reached_[r]];
    shared_mass_.setup(reached);
    increments_.resize(reached);
  }

  template <ContactEnforcement Enforcement, FrictionLaw Friction>
  void enforce(const contact_body& body, double t, double dt, const Enforcement& enforcement, const Friction& friction,
               std::vector<vec2>& d, std::vector<vec2>& v, contact_result& result) {
    const index_t ns = static_cast<index_t>(slave_.size());
    const index_t nt = static_cast<index_t>(tools_.size());
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
        p = contact_pair{j, k, hit.segment, hit.gap, tool.normal(hit.segment), 0.0, 0.0, vec2::Zero()};
        result.max_penetration = std::max(result.max_penetration, hit.gap);
        if (!in_contact_[j]) {
          in_contact_[j] = 1;
          ++result.active;
        }
      }
    }

    // (ii)-(iv), repeated for effective-mass sweeps (contact_sweeps.hpp).
    contact_sweeps(pass{*this, X, body.mass, dt, d, v}, 0, pairs_, dt, enforcement, friction);

    for (index_t q = 0; q < pairs_; ++q) {
      reaction_[pair_[q].tool] -= pair_[q].force();
      in_contact_[pair_[q].slave] = 0;
    }
  }

  // After every pass of the step: the slaves' positions on the final d (recomputed only if a
  // pass moved them: `moved` says whether a later pass may have), and the tools' at t_n+1.
  void end_step(const contact_body& body, const std::vector<vec2>& d, bool moved) {
    const index_t ns = static_cast<index_t>(slave_.size());
    const std::span<const vec2> X = body.reference_position;
    if (pairs_ > 0 || moved)
#pragma omp parallel for schedule(static) if (ns > parallel_slaves)
      for (index_t j = 0; j < ns; ++j) {
        vec2 u = vec2::Zero();
        for (index_t e = table_.offset[j]; e < table_.offset[j + 1]; ++e)
          u += table_.N[e] * d[reached_[table_.neighbor[e]]];
        x_[j] = X[slave_[j]] + u;
      }
    std::swap(x_prev_, x_);
    for (std::size_t k = 0; k < tools_.size(); ++k) u_prev_[k] = u_now_[k];
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

  // The slaves' contacts for contact_sweeps (contact_sweeps.hpp).
  struct pass {
    tool_slave_contact& self;
    std::span<const vec2> X;
    std::span<const double> m;
    double dt;
    std::vector<vec2>& d;
    std::vector<vec2>& v;

    void refresh() {
      for (index_t q = 0; q < self.pairs_; ++q) self.slave_state(X, self.pair_[q].slave, d, v);
    }
    void shared_masses(index_t, index_t end) {
      self.shared_mass_.compute(self.active_pairs(), self.table_, self.reached_mass_,
                                std::span<double>(self.m_shared_.data(), end));
    }
    contact_pair& contact(index_t q) { return self.pair_[q]; }
    contact_state state(index_t q, int sweep) const {
      const contact_pair& p = self.pair_[q];
      const index_t j = p.slave;
      const vec2 y = self.x_[j] - self.u_now_[p.tool];  // in the tool frame
      const double g = sweep == 0 ? p.gap : -self.tools_[p.tool].project(p.segment, y).distance;
      return {g, vec2(self.v_[j] - self.v_tool_[p.tool]), p.normal, m[self.slave_[j]], self.m_shared_[q]};
    }
    void spread(index_t q, const vec2& df) { self.increments_.spread(self.table_, self.pair_[q].slave, 1.0, df); }
    void apply() { self.increments_.apply(m, dt, d, v, self.reached_); }
  };

  // Below this many slaves the per-slave loops run on one thread (a parallel region costs more).
  static constexpr index_t parallel_slaves = 2048;

  std::vector<rigid_tool> tools_;
  std::vector<segment_grid> grid_;
  std::vector<index_t> slave_;
  // Rows: slaves; columns: the particles the rows reach (reached_[c] is the particle of column
  // c), so the per-coefficient scratch is as long as the slaves' neighbourhood, not the body.
  shape_table<2> table_;
  std::vector<stored_index> reached_;

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
