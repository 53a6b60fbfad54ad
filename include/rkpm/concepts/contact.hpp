#pragma once
// Contact: what the explicit solver calls on a contact policy (docs/method.md section 6):
//   setup(body, slaves)                once, before the first step;
//   enforce(body, t_next, dt, d, v)    every step, correcting the predicted d_{n+1} and
//                                      v_{n+1/2} in place, with no heap allocation;
//   tools(), reactions()               the rigid tools and the force on each in the last step;
//   body_pairs()                       the pairs of deformable bodies in contact (empty if
//                                      none): with the tools, whether there is contact at all;
//   save(writer), load(reader)         its state between steps, for checkpoints
//                                      (solver/checkpoint.hpp; empty for a stateless policy).
// The body is passed on every call (a view of the solver's own arrays), so a policy holds no
// pointer into the solver and the solver can be moved.
// ContactEnforcement and FrictionLaw are the building blocks of contact::particle_to_segment.
// Concept headers depend only on core/ and discretization/, never on the policies they describe.

#include <concepts>
#include <ranges>
#include <span>
#include <string_view>
#include <vector>

#include <rkpm/core/types.hpp>
#include <rkpm/discretization/crack_face_rows.hpp>
#include <rkpm/discretization/model_bodies.hpp>
#include <rkpm/discretization/shape_table.hpp>

namespace rkpm {

namespace io {
class checkpoint_writer;
class checkpoint_reader;
}  // namespace io

// The body a contact policy acts on, valid for the duration of one call.
struct contact_body {
  std::span<const vec2> reference_position;  // X_I, #particles
  std::span<const double> mass;              // lumped m_I (axisymmetric: 2 pi r included)
  // For contact on deformable surfaces (contact/body_contact.hpp, tool_vertex_contact.hpp): the
  // model's bodies with their surfaces (discrete_model::bodies), and the rows N_J(X_I) that give
  // physical positions.
  const model_bodies* bodies = nullptr;
  const shape_table<2>* at_particles = nullptr;
  // The reference is a deformed configuration (discrete_model::deformed_reference): setup() does
  // not check that the tools start outside it (a rank's part built again on several processes).
  bool deformed_reference = false;
  // The faces of the cracks cut through the cells, with their rows (discrete_model::crack_faces):
  // masters and slaves in all-pairs mode (contact/crack_face_points.hpp). Null or empty: none.
  const crack_face_rows* crack_faces = nullptr;
  // A rank's part (parallel/local_model.hpp): each particle's index in the whole model, the order
  // in which all-pairs contact takes the surface slaves (body_pair_surfaces.hpp). Empty: its own.
  std::span<const stored_index> particle_id = {};
};

// The particles checked against the tools, given once at set-up: slave j is particle
// particle[j], and row j of table holds N_I(X_particle[j]) for its neighbours I.
struct contact_slaves {
  std::vector<index_t> particle;
  shape_table<2> table;
};

// What a contact policy reports after each step.
struct contact_result {
  double max_penetration = 0;  // largest gap found on the predicted configuration
  index_t active = 0;          // slave particles in contact with a tool, plus slave contacts between bodies
};

template <class C>
concept Contact = std::movable<C> && requires(C& c, const C& cc, const contact_body& b, const contact_slaves& s,
                                              double t, double dt, std::vector<vec2>& d, std::vector<vec2>& v,
                                              io::checkpoint_writer& w, io::checkpoint_reader& r) {
  { C::name } -> std::convertible_to<std::string_view>;
  c.setup(b, s);
  { c.enforce(b, t, dt, d, v) } -> std::same_as<contact_result>;
  { cc.tools() } -> std::ranges::sized_range;
  { cc.body_pairs() } -> std::ranges::sized_range;
  { cc.reactions() } -> std::convertible_to<std::span<const vec2>>;
  cc.save(w);
  c.load(r);
};

// Whether a policy has anything to enforce: rigid tools or pairs of deformable bodies (declared,
// or all of them: particle_to_segment's all_body_pairs(), whose pairs are made at set-up).
template <Contact C>
bool has_contact(const C& c) {
  if constexpr (requires { { c.all_body_pairs() } -> std::convertible_to<bool>; })
    if (c.all_body_pairs()) return true;
  return !std::ranges::empty(c.tools()) || !std::ranges::empty(c.body_pairs());
}

// Optional protocols of a contact policy (contact::particle_to_segment offers them all):
// RebindsSlaves: `rebind(body, slaves)`, the same slaves' rows on a model rebuilt in the current
// configuration, its state kept (re-referencing, solver/contact_stage.hpp).
template <class C>
concept RebindsSlaves = requires(C& c, const contact_body& b, const contact_slaves& s) { c.rebind(b, s); };
// ContactsOnSurfaces: `all_body_pairs()` and `tool_vertex_slaves()` besides body_pairs(): contact
// on the bodies' surfaces, which a distributed run then keeps (parallel/distributed_solver.hpp).
template <class C>
concept ContactsOnSurfaces = requires(const C& c) {
  { c.body_pairs() } -> std::ranges::sized_range;
  { c.all_body_pairs() } -> std::convertible_to<bool>;
  { c.tool_vertex_slaves() } -> std::convertible_to<bool>;
};
// ReportsToolPairs, ReportsBodyPairs: `active_pairs()` and `bodies().active_pairs()`, the
// slave-tool and body-body contacts of the last step, which a heat coupling heats by friction
// (thermal/heat_coupling.hpp).
template <class C>
concept ReportsToolPairs = requires(const C& c) {
  { c.active_pairs() } -> std::ranges::sized_range;
};
template <class C>
concept ReportsBodyPairs = requires(const C& c) {
  { c.bodies().active_pairs() } -> std::ranges::sized_range;
};

template <class E>
concept ContactEnforcement = requires(const E& e, double g, double dt, double m) {
  { E::name } -> std::convertible_to<std::string_view>;
  { e.sweeps } -> std::convertible_to<int>;
  { e.relaxation } -> std::convertible_to<double>;
  { e.normal_force(g, dt, m, m) } -> std::same_as<double>;
  { e.stick_mass(m, m) } -> std::same_as<double>;
  e.validate();
};

template <class F>
concept FrictionLaw = requires(const F& f, const vec2& trial, double normal) {
  { F::name } -> std::convertible_to<std::string_view>;
  { f.limit(trial, normal) } -> std::same_as<vec2>;
  f.validate();
};

}  // namespace rkpm
