#pragma once
// model_bodies: the bodies of a discrete model (docs/method.md section 3.1), found once when the
// model is built and read by everything that asks which body a particle or point is in: the
// materials per body, the contact between bodies, the slave selection, the solver's bodies()
// and the case files' measures.
//   of_particle, of_point   a particle's and a quadrature point's body (the partition of
//                  discretization/body_partition.hpp; no table is kept for one body)
//   nodes_are_particles     whether the particles are the mesh nodes
//   first_particle(b)       the smallest index of body b's particles in the whole model (a
//                  part keeps the whole model's: a mesh body's node i is particle first + i)
//   surface()      each body's boundary chains (discretization/boundary_chains.hpp) without the
//                  axis of an axisymmetric section: the master surfaces of contact between bodies
//                  and the surfaces tool vertices are checked against. Their vertices are
//                  particles only when the particles are the mesh nodes; otherwise, or when the
//                  cells' boundary is not a set of chains, surface() refuses with the reason.

#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <rkpm/core/error.hpp>
#include <rkpm/discretization/body_partition.hpp>
#include <rkpm/discretization/boundary_chains.hpp>
#include <rkpm/discretization/quadrature_points.hpp>

namespace rkpm {

class model_bodies {
 public:
  model_bodies() = default;

  // The bodies of particles in cells; `axisymmetric`: the axis (r below 1e-9 of the bodies'
  // size) is no surface.
  model_bodies(std::span<const vec2> positions, const background_mesh& mesh, bool axisymmetric)
      : partition_((mesh.validate(), partition_bodies(positions, mesh))) {
    positions_count_ = positions.size();
    first_.assign(partition_.bodies, static_cast<index_t>(positions.size()));
    for (index_t I = static_cast<index_t>(positions.size()) - 1; I >= 0; --I) first_[of_particle(I)] = I;
    if (partition_.bodies == 1) {  // nothing to look up: keep no table per particle and cell
      // Swapped out, not assigned {}: that would clear them and keep their capacity, a table
      // per particle and one per cell held for nothing.
      std::vector<index_t>().swap(partition_.particle_body);
      std::vector<index_t>().swap(partition_.cell_body);
    }
    if (!partition_.nodes_are_particles) {
      surface_error_ = fmt::format("the mesh has {} nodes for {} particles at other positions; give the particles "
                                   "at the mesh nodes",
                                   mesh.node.size(), positions.size());
      return;
    }
    double size = 0.0;
    for (const vec2& x : positions) size = std::max(size, x.cwiseAbs().maxCoeff());
    const double axis = 1e-9 * size;
    try {
      surface_ = boundary_chains(mesh, [&](index_t i) { return axisymmetric && positions[i][0] <= axis; });
    } catch (const error& e) {
      surface_error_ = e.what();
    }
  }

  // Each point's body: its cell's.
  void find_point_bodies(const quadrature_points& points) {
    point_body_.clear();
    if (count() < 2) return;
    point_body_.resize(points.size());
    for (index_t q = 0; q < points.size(); ++q)
      point_body_[q] = static_cast<stored_index>(partition_.cell_body[points.cell[q]]);
  }

  // The bodies of a rank's part of a model (parallel/local_model.hpp): its particles' and points'
  // bodies, given by their indices in the whole model. It has no cells. Its surfaces are the
  // whole model's chains in local particle ids (`local_id`: each particle's local id, -1 where
  // the part does not hold it) when the part holds every chain's particles (the shared region
  // of parallel/distributed_solver.hpp holds them when the contact reads the surfaces);
  // otherwise surface() refuses.
  static model_bodies part(const model_bodies& whole, std::span<const stored_index> particles,
                           std::span<const stored_index> points, std::span<const stored_index> local_id = {}) {
    model_bodies b;
    b.partition_.bodies = whole.partition_.bodies;
    b.partition_.nodes_are_particles = false;
    b.positions_count_ = particles.size();
    b.first_ = whole.first_;
    if (whole.count() > 1)
      for (const stored_index I : particles) b.partition_.particle_body.push_back(whole.partition_.particle_body[I]);
    if (!whole.point_body_.empty())
      for (const stored_index q : points) b.point_body_.push_back(whole.point_body_[q]);
    b.surface_error_ = whole.surface_error_;
    if (!b.surface_error_.empty()) return b;
    b.surface_ = whole.surface_;
    for (boundary_chain& c : b.surface_)
      for (index_t& node : c.node) {
        const stored_index i = local_id.empty() ? -1 : local_id[node];
        if (i < 0) {
          b.surface_.clear();
          b.surface_error_ = "this rank's part of the model does not hold the whole surface (it holds the surfaces "
                             "only when the contact policy reads them: contact between bodies, tool vertices)";
          return b;
        }
        node = i;
      }
    return b;
  }

  // Whether the bodies were found (a model assembled by hand may not have them).
  bool found() const { return partition_.bodies > 0; }
  index_t count() const { return partition_.bodies; }
  index_t of_particle(index_t I) const { return count() < 2 ? 0 : partition_.particle_body[I]; }
  index_t of_cell(index_t c) const { return count() < 2 ? 0 : partition_.cell_body[c]; }
  index_t of_point(index_t q) const { return point_body_.empty() ? 0 : point_body_[q]; }
  // Each particle's and point's body; empty with one body.
  const std::vector<index_t>& particle_body() const { return partition_.particle_body; }
  const std::vector<stored_index>& point_body() const { return point_body_; }
  bool nodes_are_particles() const { return partition_.nodes_are_particles; }
  index_t first_particle(index_t b) const { return first_.empty() ? 0 : first_[b]; }
  // The particles of body b, ascending.
  std::vector<index_t> particles_of(index_t b) const {
    std::vector<index_t> out;
    for (index_t I = 0; I < static_cast<index_t>(positions_count_); ++I)
      if (of_particle(I) == b) out.push_back(I);
    return out;
  }

  // The bodies' surfaces as chains of particles; `who` names the caller in the refusal.
  const std::vector<boundary_chain>& surface(std::string_view who) const {
    if (!surface_error_.empty()) fail("{}: the bodies' surfaces are not chains of particles: {}", who, surface_error_);
    return surface_;
  }

 private:
  body_partition partition_;
  std::size_t positions_count_ = 0;
  std::vector<stored_index> point_body_;
  std::vector<index_t> first_;  // each body's smallest particle index in the whole model
  std::vector<boundary_chain> surface_;
  std::string surface_error_;  // why there is no surface, if there is none
};

}  // namespace rkpm
