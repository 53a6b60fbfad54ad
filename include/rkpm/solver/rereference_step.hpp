#pragma once
// explicit_solver::rereference(): the kernels rebuilt in the current configuration
// (docs/method.md section 5.8), between two steps:
//   1. the particles' current positions x_I become their reference; the cells are the deformed
//      cells (their corners are the particles), the supports follow the stretch (82), and the
//      model's builder (model_builder()) builds the tables, VCI gradients and surfaces;
//   2. the quadrature points are the material points themselves, carried: point q at its current
//      position x_q, with its weight times det F_rel (the volume it stands for now), so the
//      deformed cells need not stay convex, nor even the right way round, where the material is
//      squeezed flat against a tool; each keeps its material state, and F_r takes its total F
//      (79), so the material goes on from the same F. (A nodal rule's points are made again on
//      the deformed cells, its smoothing cells: they must stay the right way round.)
//   3. the coefficients: d = 0 (the displacement since the new reference); the velocity
//      coefficients stay (83): the masses and v, so the linear momentum and the kinetic energy,
//      are kept exactly, and a linear velocity field (a rigid motion among them) is the same
//      field on the new kernels (solving for each particle's velocity instead blows up, 5.8).
//      The constraints' projection then books its change of kinetic energy as energy().remap;
//   4. the constraint rows, the contact slaves' rows and surfaces, the stable step (a short
//      warm-started power iteration) and f_int, a at the new reference; then the companions'.
// Included at the end of solver/explicit_solver.hpp.

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

#include <rkpm/solver/explicit_solver.hpp>
#include <rkpm/solver/fields.hpp>
#include <rkpm/solver/part_cracks.hpp>
#include <rkpm/solver/rereference.hpp>

namespace rkpm {

template <Geometry G, Material M, Contact Ct>
bool explicit_solver<G, M, Ct>::rereference_due() const {
  const rereference_policy& when = options_.rereference;
  if (!when.enabled()) return false;
  if (when.every_steps > 0 && timeline_.steps - last_rereference_step_ >= when.every_steps) return true;
  // The distortion (81) every time_step_update_interval steps, with the stable step's update: a
  // pass over the points each step would cost a tenth of the step.
  // On a rank's part, over every rank's points (MPI_MAX), so that every rank decides alike.
  if (!(when.max_stretch > 0.0 && timeline_.steps % options_.time_step_update_interval == 0)) return false;
  const double distortion = points_.max_distortion(model_);
  return (model_.own.group ? model_.own.group->max(distortion) : distortion) > when.max_stretch;
}

template <Geometry G, Material M, Contact Ct>
std::vector<vec2> explicit_solver<G, M, Ct>::particle_displacements() const {
  std::vector<vec2> u = values_at_particles(model_, d_);
  if (!initial_position_.empty())
    for (index_t I = 0; I < model_.particle_count(); ++I) u[I] += model_.particles.position[I] - initial_position_[I];
  return u;
}

// The cells of points failed since the last call are cut (section 5.12), each once, through its
// centroid normal to the first failed point's crack normal. A rank's part only says, alike on
// every rank, whether the whole model would cut one (solver/part_cracks.hpp).
template <Geometry G, Material M, Contact Ct>
bool explicit_solver<G, M, Ct>::grow_cracks() {
  if constexpr (!BreakingState<state_type>) return false;
  else {
    if (!cracks_can_grow()) return false;  // no pass over the points (Johnson-Cook without opens_cracks)
    const bool look = points_.failures_to_scan();  // else no cell can be cut (failures_to_scan)
    bool left_uncut = false, cut = false;
    if (model_.is_part()) {
      cut = part_cuts_a_cell(model_, points_.states(), cracks_, d_, look, left_uncut);
    } else if (look) {
      const std::vector<std::pair<index_t, vec2>> failed = failed_uncut_cells(model_, points_.states(), cracks_);
      cut = !failed.empty() && insert_cuts(failed, true);
      left_uncut = std::ranges::any_of(failed, [&](const auto& f) { return !is_cut(cracks_, f.first); });
    }
    if (look) points_.scanned(left_uncut);
    return cut;
  }
}

template <Geometry G, Material M, Contact Ct>
void explicit_solver<G, M, Ct>::cut_cells(const std::vector<std::pair<index_t, vec2>>& cells_and_normals) {
  if (!timeline_.between_steps()) fail("cut_cells() between steps only");
  for (const auto& [c, n] : cells_and_normals)
    if (c < 0 || c >= model_.mesh.cells() || !(n.norm() > 0.0))
      fail("cut_cells: cell {} with normal ({}, {}): give a cell of the mesh (0 to {}) and a nonzero normal", c, n[0],
           n[1], model_.mesh.cells() - 1);
  if (insert_cuts(cells_and_normals, false)) rereference();
}

// Adds the cut of each cell not cut yet, on the current configuration (cracks_ stays in cell
// order), none beside a cut when `not_beside_cuts` (failed points, beside_a_cut); whether it added
// any. The model is rebuilt by the caller.
template <Geometry G, Material M, Contact Ct>
bool explicit_solver<G, M, Ct>::insert_cuts(const std::vector<std::pair<index_t, vec2>>& cells_and_normals,
                                            bool not_beside_cuts) {
  std::optional<background_mesh> current;  // the cells at the current positions, when needed
  std::vector<std::array<index_t, 4>> neighbours;
  bool cut = false;
  for (const auto& [c, n] : cells_and_normals) {
    if (is_cut(cracks_, c) || !(n.norm() > 0.0)) continue;
    if (!current) current.emplace(background_mesh{positions_at_particles(model_, d_), model_.mesh.cell});
    if (not_beside_cuts && neighbours.empty()) neighbours = cell_neighbours(model_.mesh);
    if (const std::optional<cell_crack> k = cut_cell(*current, c, n.normalized())) {
      if (not_beside_cuts && beside_a_cut(neighbours, cracks_, *k)) continue;
      cracks_.insert(cracks_.begin() + static_cast<std::ptrdiff_t>(cut_position(cracks_, c)), *k);
      cut = true;
    }
  }
  if (cut && (!factory_ || !model_.bodies.nodes_are_particles() || model_.is_part()))
    fail("t = {:.6g} s: cutting a cell rebuilds the model: {}", timeline_.time,
         model_.is_part() ? "a rank's part cuts no cell (cut a notch on one process and read its checkpoint)"
                          : "build the solver with make_solver and give the particles at the mesh nodes");
  return cut;
}

template <Geometry G, Material M, Contact Ct>
void explicit_solver<G, M, Ct>::rereference() {
  if (model_.is_part())
    fail("re-referencing a rank's part: the run on several processes re-references every part at once "
         "(parallel::distributed_solver::rereference)");
  if (!factory_)
    fail("re-referencing needs the solver's model builder: build the solver with make_solver (or pass the "
         "model_factory to its constructor)");
  if (!model_.bodies.nodes_are_particles())
    fail("re-referencing moves the cells with the particles at their corners: give the particles at the mesh "
         "nodes (make_grid_particles with make_grid_mesh, or particles from the mesh)");
  if (!timeline_.between_steps()) fail("rereference() between steps only");
  if (initial_position_.empty() && !model_.mesh.cracks.empty())
    fail("re-referencing a model with cracks given in its cells (background_mesh::cracks): they would not move "
         "with the body; cut the notch out of the cells instead");
  if (initial_position_.empty()) initial_position_ = model_.particles.position;

  // 1. The model in the current configuration.
  const std::vector<vec2> x = positions_at_particles(model_, d_);
  if constexpr (G::is_axisymmetric) refuse_across_axis(x, model_.particles.position, false, timeline_.time);
  const std::vector<mat2> stretch = project_to_particles<mat2>(
      [&](index_t q) { return mat2(points_.relative_deformation_gradient(q).template topLeftCorner<2, 2>()); });
  auto [particles, cells] = deformed_particles(model_.particles, model_.mesh, x, stretch, !model_.nodal);
  cells.cracks = cracks_on(cells, cracks_);
  // The points carried (rereference.hpp); a nodal rule's are made again on the deformed cells.
  quadrature_points carried;
  if (!model_.nodal)
    carried = carried_points(
        model_.points, model_.at_points, d_,
        [&](index_t q) { return points_.relative_deformation_gradient(q).determinant(); }, G::is_axisymmetric,
        timeline_.time);
  discrete_model next = with_bodies<G>(factory_(std::move(particles), std::move(cells), options_.max_moment_condition,
                                                model_.nodal ? nullptr : &carried));
  next.deformed_reference = true;

  // 2. The points: the same material points, F_r their total F.
  points_.rereference(model_, next);
  const double kinetic_before = kinetic_energy();
  model_ = std::move(next);

  // 3. The coefficients: d = 0 (no displacement since the new reference); v kept (83).
  std::fill(d_.begin(), d_.end(), vec2::Zero());
  derive_from_model(constraints_.constraints());
  if (constraints_.size() > 0) constraints_.apply(timeline_.time, v_);

  // 4. The step's other ingredients at the new reference.
  compute_internal_force();
  for (index_t I = 0; I < model_.particle_count(); ++I) a_[I] = (f_ext_.at(I, physical_mass()) - f_int_[I]) / mass_[I];
  timeline_.dt = clock_.rereference(model_, materials_.moduli(), mass_, points_.deformation_gradients(), options_,
                                    timeline_.time, timeline_.steps);
  energy_.kinetic = kinetic_energy();
  energy_.remap += energy_.kinetic - kinetic_before;
  energy_.record();
  rereference_times_.push_back(timeline_.time);
  last_rereference_step_ = timeline_.steps;
  for (const auto& c : companions_) c->after_rebuild(*this, {});  // e.g. heat conduction, rebound
}

// The re-referenced model in a checkpoint: the particles' current reference (positions,
// supports, volumes), their initial positions and the re-references so far; a Lagrangian run's
// sections are empty. Read back, the model is rebuilt through the builder before the state is.
template <Geometry G, Material M, Contact Ct>
template <class Archive, class Self>
void explicit_solver<G, M, Ct>::reference_sections(Archive& a, Self& s) {
  constexpr bool reading = !std::is_const_v<Self>;
  std::uint64_t count = s.rereference_times_.size();
  a.value("reference.count", count);
  a.value("reference.last_step", s.last_rereference_step_);
  if constexpr (reading) {
    s.rereference_times_.resize(count);
    if (count > 0) s.initial_position_.resize(s.model_.particle_count());
  }
  a.array("reference.times", s.rereference_times_);
  a.array("reference.initial_position", s.initial_position_);
  std::uint64_t cuts = s.cracks_.size();
  a.value("reference.crack_count", cuts);
  [[maybe_unused]] const std::vector<cell_crack> cracks_before = reading ? s.cracks_ : std::vector<cell_crack>{};
  if constexpr (reading) s.cracks_.resize(cuts);
  a.array("reference.cracks", s.cracks_);
  if constexpr (reading) {
    if (count == 0) return;
    particle_set<2> particles = s.model_.particles;
    background_mesh cells = s.model_.mesh;
    a.array("reference.position", particles.position);
    a.array("reference.support", particles.support);
    a.array("reference.volume", particles.volume);
    cells.node = particles.position;
    cells.tangled = !s.model_.nodal;
    if (!s.model_.is_part()) cells.cracks = cracks_on(cells, s.cracks_);  // a part holds no cells
    quadrature_points carried;  // the carried points (none for a nodal rule)
    if (!s.model_.nodal) {
      carried.position.resize(s.model_.point_count());
      carried.weight.resize(s.model_.point_count());
      carried.cell = s.model_.points.cell;
    }
    a.array("reference.point_position", carried.position);
    a.array("reference.point_weight", carried.weight);
    // A rank's part: built on the re-referenced model by parallel::distributed_solver, whose
    // read_checkpoint reads the file into a whole solver first.
    if (s.model_.is_part()) {
      if (particles.position != s.model_.particles.position)
        fail("a re-referenced checkpoint read into a rank's part of another reference: read it with "
             "parallel::read_checkpoint of a distributed_solver given its whole solver (rereference_through)");
      return;
    }
    // A whole solver that mirrors a run on several processes reads the same reference at every
    // mirror (parallel::mirror_state): its model was built from it, so it stays.
    const auto same = [](const auto& x, const auto& y) {  // bit for bit (an empty vector's data() may be null)
      return x.size() == y.size() && (x.empty() || std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0);
    };
    if (s.model_.deformed_reference && same(particles.position, s.model_.particles.position) &&
        same(particles.support, s.model_.particles.support) && same(particles.volume, s.model_.particles.volume) &&
        (s.model_.nodal || (same(carried.position, s.model_.points.position) &&
                            same(carried.weight, s.model_.points.weight))) &&
        same(cracks_before, s.cracks_))
      return;
    if (!s.factory_) fail("reading a re-referenced checkpoint needs the solver's model builder: build it with make_solver");
    s.model_ = with_bodies<G>(s.factory_(std::move(particles), std::move(cells), s.options_.max_moment_condition,
                                         s.model_.nodal ? nullptr : &carried));
    s.model_.deformed_reference = true;
    s.points_.bind(s.model_);
    s.derive_from_model(s.constraints_.constraints());
    for (const auto& c : s.companions_) c->after_rebuild(s, {.restart = true});  // their state is read next
  } else if (count > 0) {
    a.array("reference.position", s.model_.particles.position);
    a.array("reference.support", s.model_.particles.support);
    a.array("reference.volume", s.model_.particles.volume);
    static const std::vector<vec2> no_positions;
    static const std::vector<double> no_weights;
    a.array("reference.point_position", s.model_.nodal ? no_positions : s.model_.points.position);
    a.array("reference.point_weight", s.model_.nodal ? no_weights : s.model_.points.weight);
  }
}

}  // namespace rkpm
