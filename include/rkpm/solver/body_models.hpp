#pragma once
// The discrete model of a problem with several bodies (docs/method.md section 3.1): each body,
// the particles and cells of one connected part of the mesh (found once: discretization/model_bodies.hpp),
// gets its own model (neighbours searched within the body only, so kernels never reach across
// bodies; VCI and SCNI corrections per body), and the models are joined into one: particles and
// cells keep the problem's numbering, the points follow body by body. The time loop then steps
// all bodies together with one stable step. A problem with one body gets exactly the model of
// build_discrete_model. The faces of cracks cut through the cells get their rows here, each
// within its body (discretization/crack_face_rows.hpp).

#include <optional>
#include <utility>
#include <vector>

#include <rkpm/discretization/model_bodies.hpp>
#include <rkpm/solver/discrete_model.hpp>

namespace rkpm {

namespace detail {

// The particles and cells of body b, with the maps back to the problem's numbering.
struct body_part {
  particle_set<2> particles;
  background_mesh mesh;
  std::vector<index_t> particle;  // local -> problem particle
  std::vector<index_t> cell;      // local -> problem cell
};

inline body_part extract_body(const particle_set<2>& particles, const background_mesh& mesh,
                              const model_bodies& bodies, index_t b) {
  body_part out;
  out.particle = bodies.particles_of(b);
  out.mesh.cracks = mesh.cracks;  // in the same coordinates; those away from the body block nothing
  for (index_t I : out.particle) {
    out.particles.position.push_back(particles.position[I]);
    out.particles.volume.push_back(particles.volume[I]);
    out.particles.support.push_back(particles.support[I]);
  }
  std::vector<index_t> local_node(mesh.node.size(), -1);
  for (index_t c = 0; c < mesh.cells(); ++c) {
    if (bodies.of_cell(c) != b) continue;
    std::array<stored_index, 4> cell{};
    for (int k = 0; k < 4; ++k) {
      index_t& n = local_node[mesh.cell[c][k]];
      if (n < 0) {
        n = static_cast<index_t>(out.mesh.node.size());
        out.mesh.node.push_back(mesh.node[mesh.cell[c][k]]);
      }
      cell[k] = n;
    }
    out.mesh.cell.push_back(cell);
    out.cell.push_back(c);
  }
  return out;
}

// Appends row `row` of `from` to `to`, its neighbours renumbered by `global`.
inline void append_row(const shape_table<2>& from, index_t row, const std::vector<index_t>& global,
                       shape_table<2>& to) {
  for (index_t e = from.offset[row]; e < from.offset[row + 1]; ++e) {
    to.neighbor.push_back(global[from.neighbor[e]]);
    to.N.push_back(from.N[e]);
    if (!from.grad.empty()) to.grad.push_back(from.grad[e]);
  }
  to.offset.push_back(static_cast<index_t>(to.neighbor.size()));
}

}  // namespace detail

template <Kernel K, Correction C, Quadrature Q, Geometry G>
discrete_model build_model_of_bodies(particle_set<2> particles, background_mesh mesh,
                                     double max_condition = default_max_moment_condition,
                                     const quadrature_points* carried = nullptr) {
  particles.validate();
  model_bodies bodies(particles.position, mesh, G::is_axisymmetric);
  if (bodies.count() == 1) {
    discrete_model m =
        detail::build_one_model<K, C, Q, G>(std::move(particles), std::move(mesh), max_condition, carried);
    m.set_bodies(std::move(bodies));
    m.crack_faces = build_crack_face_rows<K, C>(m.particles, m.mesh.cracks, m.bodies, max_condition);
    return m;
  }

  const index_t n = particles.size();
  discrete_model joined;
  joined.lumped_volume.assign(n, 0.0);
  std::vector<detail::body_part> parts;
  std::vector<discrete_model> models;
  for (index_t b = 0; b < bodies.count(); ++b) {
    parts.push_back(detail::extract_body(particles, mesh, bodies, b));
    // Carried points of body b, in their order, their cells numbered as the body's.
    std::optional<quadrature_points> own;
    if (carried) {
      std::vector<index_t> local_cell(mesh.cell.size(), -1);
      for (index_t c = 0; c < static_cast<index_t>(parts[b].cell.size()); ++c) local_cell[parts[b].cell[c]] = c;
      own.emplace();
      for (index_t q = 0; q < carried->size(); ++q)
        if (const index_t c = local_cell[carried->cell[q]]; c >= 0) {
          own->position.push_back(carried->position[q]);
          own->weight.push_back(carried->weight[q]);
          own->cell.push_back(static_cast<stored_index>(c));
        }
    }
    models.push_back(detail::build_one_model<K, C, Q, G>(parts[b].particles, parts[b].mesh, max_condition,
                                                         own ? &*own : nullptr));
  }
  for (index_t b = 0; b < bodies.count(); ++b) {
    const discrete_model& m = models[b];
    for (index_t q = 0; q < m.point_count(); ++q) {
      joined.points.position.push_back(m.points.position[q]);
      joined.points.weight.push_back(m.points.weight[q]);
      joined.points.cell.push_back(parts[b].cell[m.points.cell[q]]);
      detail::append_row(m.at_points, q, parts[b].particle, joined.at_points);
    }
    joined.test_gradient.insert(joined.test_gradient.end(), m.test_gradient.begin(), m.test_gradient.end());
    for (index_t i = 0; i < m.particle_count(); ++i) joined.lumped_volume[parts[b].particle[i]] = m.lumped_volume[i];
  }
  // Rows at the particles in the problem's order.
  std::vector<index_t> local(n);
  for (index_t b = 0; b < bodies.count(); ++b)
    for (index_t i = 0; i < static_cast<index_t>(parts[b].particle.size()); ++i) local[parts[b].particle[i]] = i;
  for (index_t I = 0; I < n; ++I) {
    const index_t b = bodies.of_particle(I);
    detail::append_row(models[b].at_particles, local[I], parts[b].particle, joined.at_particles);
  }
  joined.traversal = make_point_traversal(joined.at_points, n);
  joined.own = ownership::single_process(n, joined.point_count());
  joined.particles = std::move(particles);
  joined.mesh = std::move(mesh);
  joined.set_bodies(std::move(bodies));
  joined.crack_faces = build_crack_face_rows<K, C>(joined.particles, joined.mesh.cracks, joined.bodies, max_condition);
  return joined;
}

}  // namespace rkpm
