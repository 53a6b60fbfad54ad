#pragma once
// particle_to_segment<Enforcement, Friction>: the paper's contact (docs/method.md section 6) as
// the solver's Contact policy, in up to three passes per step, each on the configuration the
// previous one left:
//   1. the body's slave particles against the moving rigid tools (tool_slave_contact.hpp);
//   2. the pairs of deformable bodies, a body's slaves against another's surface or its own
//      (body_contact.hpp), when the problem names body pairs or asks for all of them;
//   3. the tools' vertices against the bodies' surfaces (tool_vertex_contact.hpp), when asked for.
// Every pass has the same skeleton (detect, shared effective masses, sweeps, apply:
// contact_sweeps.hpp) and the same force kernel (contact_kernel.hpp), with the enforcement
// policy's masses and sweeps and the friction law given here.
// Reported per step: the reaction on each tool (minus the sum of the contact forces its segments
// and vertices applied), the largest penetration before correction and the number of slave
// contacts. The work of the contact forces is booked by the solver's energy ledger
// (solver/energy.hpp, impulse_work_at), the same formula as for the constraints.
// enforce() does not allocate: setup() sizes every buffer.

#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include <rkpm/concepts/contact.hpp>
#include <rkpm/core/error.hpp>
#include <rkpm/core/joined_name.hpp>
#include <rkpm/contact/body_contact.hpp>
#include <rkpm/contact/contact_pair.hpp>
#include <rkpm/contact/enforcement.hpp>
#include <rkpm/contact/friction.hpp>
#include <rkpm/contact/rigid_tool.hpp>
#include <rkpm/contact/segment_grid.hpp>
#include <rkpm/contact/tool_slave_contact.hpp>
#include <rkpm/contact/tool_vertex_contact.hpp>
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
      : tool_slaves_(std::move(tools)), friction_(friction), enforcement_(enforcement) {
    friction_.validate();
    enforcement_.validate();
  }
  // Rigid tools and pairs of deformable bodies in contact (body_contact.hpp); either may be empty.
  particle_to_segment(std::vector<rigid_tool> tools, std::vector<body_pair> body_pairs, Friction friction = {},
                      Enforcement enforcement = {})
      : particle_to_segment(std::move(tools), friction, enforcement) {
    bodies_ = body_contact(std::move(body_pairs));
  }
  // Rigid tools and every body against every body, itself included (all_body_pairs; docs/method.md
  // section 6.11).
  particle_to_segment(std::vector<rigid_tool> tools, all_body_pairs_t all, Friction friction = {},
                      Enforcement enforcement = {})
      : particle_to_segment(std::move(tools), friction, enforcement) {
    bodies_ = body_contact(all);
  }

  const std::vector<rigid_tool>& tools() const { return tool_slaves_.tools(); }
  const std::vector<segment_grid>& grids() const { return tool_slaves_.grids(); }
  // The declared pairs, or in all-pairs mode those made at set-up.
  const std::vector<body_pair>& body_pairs() const { return bodies_.pairs(); }
  bool all_body_pairs() const { return bodies_.all_pairs(); }
  // Two-pass tool contact: the tools' vertices also checked as slaves against the bodies'
  // surfaces (tool_vertex_contact.hpp), so that a sharp corner cannot slip between two surface
  // particles. Set before the solver is built.
  void set_tool_vertex_slaves(bool on) { tool_vertex_slaves_ = on; }
  bool tool_vertex_slaves() const { return tool_vertex_slaves_; }
  // Contacts between bodies in the last step.
  const body_contact& bodies() const { return bodies_; }
  // Reaction on each tool in the last step (minus the contact forces it applied).
  const std::vector<vec2>& reactions() const { return tool_slaves_.reactions(); }
  // The slaves' contacts with the tools in the last step.
  std::span<const contact_pair> active_pairs() const { return tool_slaves_.active_pairs(); }
  const Friction& friction() const { return friction_; }
  const Enforcement& enforcement() const { return enforcement_; }
  // Replaces the enforcement (e.g. enforcement::chosen's choice); before the solver is built.
  void set_enforcement(Enforcement enforcement) {
    enforcement.validate();
    enforcement_ = enforcement;
  }

  // Checkpoint (io/checkpoint.hpp): the tools' pass is the only one that reads the last step
  // (tool_slave_contact.hpp); the other passes start afresh every step.
  void save(io::checkpoint_writer& w) const { tool_slaves_.save(w); }
  void load(io::checkpoint_reader& r) { tool_slaves_.load(r); }

  // Checks the body and the slaves and sets up each pass; the body itself is passed again on
  // every enforce().
  void setup(const contact_body& body, const contact_slaves& slaves) {
    tool_slaves_.setup(body, slaves);
    setup_surfaces(body);
    ready_ = true;
  }

  // The same slaves on a model rebuilt in the current configuration (the solver's re-reference):
  // the tools' pass keeps what the last step left, the others are set up on the new surfaces.
  void rebind(const contact_body& body, const contact_slaves& slaves) {
    tool_slaves_.rebind(body, slaves);
    setup_surfaces(body);
  }

  contact_result enforce(const contact_body& body, double t, double dt, std::vector<vec2>& d, std::vector<vec2>& v) {
    if (!ready_) fail("contact: enforce() called before setup(); the solver must call setup(body, slaves) once");
    const std::size_t np = body.reference_position.size();
    if (d.size() != np || v.size() != np)
      fail("contact: {} displacements and {} velocities for {} particles", d.size(), v.size(), np);
    if (!(dt > 0.0)) fail("contact: time step {} must be positive", dt);
    contact_result result;
    tool_slaves_.enforce(body, t, dt, enforcement_, friction_, d, v, result);
    bodies_.enforce(body, dt, enforcement_, friction_, d, v, result);
    tool_vertices_.enforce(body, tools(), tool_slaves_.displacements(), tool_slaves_.velocities(), dt, enforcement_,
                           friction_, d, v, result, tool_slaves_.mutable_reactions());
    // The bodies' pass moved d only if it found contacts (all pairs or a self pair with nothing
    // touching then costs the slaves' positions nothing more).
    tool_slaves_.end_step(body, d, !bodies_.active_pairs().empty() || tool_vertices_.enabled());
    return result;
  }

 private:
  // The passes that start afresh every step: bodies against bodies, tool vertices against the body.
  void setup_surfaces(const contact_body& body) {
    bodies_.setup(body, tool_slaves_.slaves());
    if (tool_vertex_slaves_) {
      std::size_t vertices = 0;
      for (const rigid_tool& tool : tools()) vertices += tool.reference_vertices().size();
      tool_vertices_.setup(body, vertices);
    }
  }

  tool_slave_contact tool_slaves_;
  body_contact bodies_;
  bool tool_vertex_slaves_ = false;
  tool_vertex_contact tool_vertices_;
  Friction friction_;
  Enforcement enforcement_;
  bool ready_ = false;
};

}  // namespace rkpm::contact
