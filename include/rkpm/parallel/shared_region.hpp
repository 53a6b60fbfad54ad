#pragma once
// The shared region of a run on several processes (parallel/distributed_solver.hpp; docs/method.md
// section 9.8): the particles every rank holds and corrects alike, so that the constraints'
// projection and the contact corrections of the whole model are computed on every rank as one
// process computes them; and which parts of the model the contact policy reads there.

#include <algorithm>
#include <vector>

#include <rkpm/concepts/contact.hpp>
#include <rkpm/discretization/boundary_chains.hpp>
#include <rkpm/discretization/crack_face_rows.hpp>
#include <rkpm/discretization/shape_table.hpp>
#include <rkpm/solver/constraints.hpp>

namespace rkpm::parallel {

// The particles every rank holds (sorted global ids): the constrained and slave particles, the
// surfaces' particles when the contact reads them, and the columns of their rows at the
// particles; with `faces` (the crack faces, when the contact reads them) the columns of the face
// points' rows, whose coefficients give the points' positions and take their corrections.
inline std::vector<stored_index> shared_particles(const shape_table<2>& at_particles,
                                                  const std::vector<velocity_constraint>& constraints,
                                                  const std::vector<index_t>& slaves,
                                                  const std::vector<boundary_chain>& surfaces = {},
                                                  const crack_face_rows* faces = nullptr) {
  std::vector<stored_index> out;
  const auto add_row = [&](index_t I) {
    out.push_back(static_cast<stored_index>(I));
    for (index_t e = at_particles.offset[I]; e < at_particles.offset[I + 1]; ++e) out.push_back(at_particles.neighbor[e]);
  };
  for (const velocity_constraint& c : constraints) add_row(c.particle);
  for (const index_t I : slaves) add_row(I);
  for (const boundary_chain& c : surfaces)
    for (const index_t I : c.node) add_row(I);
  if (faces) out.insert(out.end(), faces->rows.neighbor.begin(), faces->rows.neighbor.end());
  std::ranges::sort(out);
  out.erase(std::ranges::unique(out).begin(), out.end());
  return out;
}

// Whether a contact policy reads the bodies' surfaces (contact/particle_to_segment.hpp's pairs
// of bodies and tool vertices).
template <class Contact>
bool reads_surfaces(const Contact& c) {
  if constexpr (ContactsOnSurfaces<Contact>)
    return !c.body_pairs().empty() || c.all_body_pairs() || c.tool_vertex_slaves();
  else
    return false;
}

// Whether it reads the faces of cracks (all body pairs: contact/crack_face_points.hpp).
template <class Contact>
bool reads_crack_faces(const Contact& c) {
  if constexpr (ContactsOnSurfaces<Contact>)
    return c.all_body_pairs();
  else
    return false;
}

}  // namespace rkpm::parallel
