#pragma once
// local_force_model: the part of the discrete model that one rank's force loop reads
// (solver/point_forces.hpp, solver/point_materials.hpp), from the whole model and the rank's
// halo plan (parallel/halo.hpp; docs/method.md section 9.8):
//   particles       the plan's local particles, owned first, then the ghosts
//   points          the plan's points (redundant ghost points included), in global order
//   at_points       their rows, columns renamed to local particles (local_shape_table)
//   traversal       the global tiles and colours restricted to them (local_traversal, below)
//   test_gradient   the corrected gradients of those rows, for a VCI rule
//   own             owned, ghost and point ranges (halo_plan::own)
//   global_mean_support  the whole model's mean support (the stable step's support stretch)
//   point_id        each point's global index, which an error names
// Over it the force loop gives every owned particle the force it has on one process, bit for
// bit (tests/mpi/local_force.cpp), and every point the same stress and material state.
// local_model (below) adds what the rest of the step reads.

#include <vector>

#include <rkpm/discretization/point_traversal.hpp>
#include <rkpm/parallel/halo.hpp>
#include <rkpm/solver/discrete_model.hpp>

namespace rkpm::parallel {

// The global traversal restricted to the plan's points, in local point ids: each tile keeps the
// points of the plan it holds (a tile with none is left out), each colour its tiles in the same
// order. An owned particle's points are all in the plan, and the force loop sums a particle's
// force colour by colour, tile by tile, point by point: over the local traversal it adds the
// same terms in the same order as over the global one, on any partition.
inline point_traversal local_traversal(const halo_plan& plan, const point_traversal& global) {
  if (global.tile_start.back() != plan.global_points)
    fail("local traversal: the plan was made for {} points but the traversal covers {}; make both from one model",
         plan.global_points, global.tile_start.back());
  const auto points = static_cast<index_t>(plan.points.size());
  point_traversal t;
  std::vector<index_t> local_tile(global.tiles(), -1);
  index_t k = 0;
  for (index_t g = 0; g < global.tiles(); ++g) {
    const index_t first = k;
    while (k < points && plan.points[k] < global.tile_start[g + 1]) ++k;
    if (k == first) continue;
    local_tile[g] = t.tiles();
    t.tile_start.push_back(k);
  }
  for (index_t c = 0; c < global.colours(); ++c) {
    if (c == global.serial_from) t.serial_from = t.colours();
    for (index_t j = global.colour_start[c]; j < global.colour_start[c + 1]; ++j)
      if (const index_t lt = local_tile[global.tile[j]]; lt >= 0) t.tile.push_back(lt);
    if (static_cast<index_t>(t.tile.size()) > t.colour_start.back())
      t.colour_start.push_back(static_cast<index_t>(t.tile.size()));
  }
  if (global.serial_from >= global.colours()) t.serial_from = t.colours();
  return t;
}

inline discrete_model local_force_model(const discrete_model& global, const halo_plan& plan) {
  if (global.particle_count() != plan.global_particles || global.point_count() != plan.global_points)
    fail("local force model: the plan was made for {} particles and {} points but the model has {} and {}; make "
         "the plan from this model's table",
         plan.global_particles, plan.global_points, global.particle_count(), global.point_count());
  discrete_model m;
  for (index_t i = 0; i < plan.local_particles(); ++i) {
    const index_t I = plan.global_particle(i);
    m.particles.position.push_back(global.particles.position[I]);
    m.particles.volume.push_back(global.particles.volume[I]);
    m.particles.support.push_back(global.particles.support[I]);
  }
  for (const stored_index q : plan.points) {
    m.points.position.push_back(global.points.position[q]);
    m.points.weight.push_back(global.points.weight[q]);
    if (!global.points.cell.empty()) m.points.cell.push_back(global.points.cell[q]);
  }
  m.at_points = local_shape_table(plan, global.at_points);
  m.traversal = local_traversal(plan, global.traversal);
  if (!global.test_gradient.empty()) {
    m.test_gradient.reserve(m.at_points.entries());
    for (const stored_index q : plan.points)
      for (index_t e = global.at_points.offset[q]; e < global.at_points.offset[q + 1]; ++e)
        m.test_gradient.push_back(global.test_gradient[e]);
  }
  m.own = plan.own();
  m.global_mean_support = global.mean_support();
  m.point_id = plan.points;
  m.whole_points = plan.global_points;
  return m;
}

// The rows at the particles a rank keeps (`rows`: the whole table at the particles): sets
// m.particle_id (each local particle's index in the whole model) and m.at_particles, the rows of
// the owned particles and of every ghost whose columns are all held here (the shared region's:
// parallel/halo.hpp), columns renamed; the other ghosts' rows are empty (no rank reads them).
// Returns each whole-model particle's local id (-1 where the rank does not hold it).
inline std::vector<stored_index> keep_held_rows(const shape_table<2>& rows, const halo_plan& plan, discrete_model& m) {
  const index_t n = plan.local_particles(), owned = static_cast<index_t>(plan.owned.size());
  std::vector<stored_index> local(plan.global_particles, -1);
  m.particle_id.clear();
  for (index_t i = 0; i < n; ++i) {
    const stored_index I = plan.global_particle(i);
    local[I] = static_cast<stored_index>(i);
    m.particle_id.push_back(I);
  }
  shape_table<2>& t = m.at_particles;
  t = {};
  for (index_t i = 0; i < n; ++i) {
    const stored_index I = m.particle_id[i];
    bool held = true;
    for (index_t e = rows.offset[I]; e < rows.offset[I + 1] && held; ++e) held = local[rows.neighbor[e]] >= 0;
    if (!held && i < owned)
      fail("local model: owned particle {}'s row at the particles names a particle rank {} does not hold; make the "
           "plan with the table at the particles",
           I, plan.rank);
    if (held)
      for (index_t e = rows.offset[I]; e < rows.offset[I + 1]; ++e) {
        t.neighbor.push_back(local[rows.neighbor[e]]);
        t.N.push_back(rows.N[e]);
        if (!rows.grad.empty()) t.grad.push_back(rows.grad[e]);
      }
    t.offset.push_back(static_cast<index_t>(t.neighbor.size()));
  }
  return local;
}

// The crack faces with their rows' columns renamed by `local` (each whole-model particle's local
// id, -1 where the part does not hold it), in the whole model's order; none if a column is not held.
inline crack_face_rows part_crack_faces(const crack_face_rows& whole, const std::vector<stored_index>& local) {
  crack_face_rows f = whole;
  for (particle_index& I : f.rows.neighbor) {
    if (local[I] < 0) return {};
    I = static_cast<particle_index>(local[I]);
  }
  return f;
}

// A rank's whole model for the time step (solver/explicit_solver.hpp): the force model above,
// and what the rest of the step reads:
//   lumped_volume  every local particle's (the masses: ghosts' too, for the shared region)
//   at_particles   keep_held_rows's
//   particle_id    each particle's index in the whole model
//   bodies         the particles' and points' bodies, and the surfaces if the part holds them
//                  (model_bodies::part)
//   crack_faces    the faces of the cracks, their rows' columns in local ids, if the part holds
//                  every column (the shared region holds them when the contact reads the faces:
//                  parallel/shared_region.hpp); none otherwise
// own.group is left to the caller (the process group the run lives in).
inline discrete_model local_model(const discrete_model& global, const halo_plan& plan) {
  discrete_model m = local_force_model(global, plan);
  for (index_t i = 0; i < plan.local_particles(); ++i) m.lumped_volume.push_back(global.lumped_volume[plan.global_particle(i)]);
  const std::vector<stored_index> local = keep_held_rows(global.at_particles, plan, m);
  m.bodies = model_bodies::part(global.bodies, m.particle_id, plan.points, local);
  m.crack_faces = part_crack_faces(global.crack_faces, local);
  m.nodal = global.nodal;
  m.deformed_reference = global.deformed_reference;
  return m;
}

}  // namespace rkpm::parallel
