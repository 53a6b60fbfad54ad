#pragma once
// discrete_model: everything the time-stepping loop reads, computed once in the reference
// configuration (docs/method.md sections 2.7 and 9.3). Only this builder depends on the kernel, the
// correction and the quadrature rule; the loop (solver/explicit_solver.hpp) does not, so those
// policies cost a small instantiation each instead of a copy of the whole solver.
//   points               quadrature points X_q and weights w_q (2 pi R included)
//   at_points            N_I(X_q), grad N_I(X_q)
//   traversal            the tiles and colours the force loop visits the points in (gather,
//                        point rule and scatter in one pass, discretization/point_traversal.hpp)
//   at_particles         N_J(X_I): physical values at the particles (values only, entries with
//                        |N_J| < 1e-30 left out: shape_table_contents values_only)
//   lumped_volume        V_I = sum_q N_I(X_q) w_q (mass = rho0 V_I, docs/method.md (38))
//   test_gradient        corrected test-function gradients g_I(X_q), parallel to at_points.grad,
//                        for a rule with variationally consistent integration (vci<Rule>,
//                        docs/method.md section 3.5); empty: the test gradients are the trial
//                        gradients. The deformation gradient always uses at_points.grad.
//   own                  the particles and points this process owns, and its ghosts (one process: all)
//   bodies               the bodies: each particle's, cell's and point's, their surfaces
//                        (discretization/model_bodies.hpp), found once by the builder
//   crack_faces          the faces of the cracks cut through the cells, with their rows for
//                        contact (discretization/crack_face_rows.hpp); empty without cuts
// For a nodal rule (scni, docs/method.md section 3.6) the points are those of the smoothing
// cells and at_points.grad holds the smoothed gradients, trial and test alike (test_gradient
// stays empty); at_points.N stays the shape functions at the points, for the hoop term, the
// lumped volumes and the projections.

#include <cmath>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include <rkpm/concepts/geometry.hpp>
#include <rkpm/concepts/quadrature.hpp>
#include <rkpm/core/execution.hpp>
#include <rkpm/discretization/background_mesh.hpp>
#include <rkpm/discretization/crack_face_rows.hpp>
#include <rkpm/discretization/integration_constraint.hpp>
#include <rkpm/discretization/model_bodies.hpp>
#include <rkpm/discretization/point_traversal.hpp>
#include <rkpm/discretization/vci_gradients.hpp>
#include <rkpm/discretization/quadrature_points.hpp>
#include <rkpm/discretization/shape_table.hpp>
#include <rkpm/discretization/smoothing_cells.hpp>

namespace rkpm {

struct discrete_model {
  particle_set<2> particles;
  background_mesh mesh;
  quadrature_points points;
  shape_table<2> at_points;
  point_traversal traversal;
  shape_table<2> at_particles;
  std::vector<double> lumped_volume;
  std::vector<vec2> test_gradient;
  ownership own;
  model_bodies bodies;
  crack_face_rows crack_faces;
  // A rank's model (parallel/local_model.hpp): the whole model's mean support, which
  // mean_support() gives instead of its own particles' mean, each point's index in the whole
  // model, which errors name, and each particle's, which orders what every rank computes over
  // the same particles (the constraints, the contact, the stable step's start vector). Empty on
  // one process.
  std::optional<vec2> global_mean_support;
  // Whether the points are a nodal rule's (scni): on smoothing cells, not carried as material
  // points when the model is rebuilt in the current configuration (section 5.8).
  bool nodal = false;
  // Whether the particles' reference is a deformed configuration: a model rebuilt by a re-reference
  // (section 5.8), which the tools may already press into (contact_body::deformed_reference).
  bool deformed_reference = false;
  std::vector<stored_index> point_id;
  std::vector<stored_index> particle_id;
  index_t whole_points = 0;  // a rank's model: the whole model's point count
  // A rank's model of a material that breaks: each point's cell (crack_growth.hpp, cells_around_points).
  std::vector<cell_around> cells_around;

  // Takes the bodies found for these particles and cells, and finds each point's.
  void set_bodies(model_bodies b) {
    bodies = std::move(b);
    bodies.find_point_bodies(points);
  }

  index_t particle_count() const { return particles.size(); }
  // The particles' mean support per direction (the support stretch of the stable step,
  // solver/point_materials.hpp), summed in particle order.
  vec2 mean_support() const {
    if (global_mean_support) return *global_mean_support;
    vec2 sum = vec2::Zero();
    for (const vec2& a : particles.support) sum += a;
    return sum / static_cast<double>(particle_count());
  }
  index_t point_count() const { return points.size(); }
  index_t whole_point_count() const { return is_part() || whole_points > 0 ? whole_points : point_count(); }
  // Point q's and particle I's index in the whole model (q and I themselves on one process).
  index_t global_point(index_t q) const { return point_id.empty() ? q : point_id[q]; }
  index_t global_particle(index_t I) const { return particle_id.empty() ? I : particle_id[I]; }
  // Whether this is one rank's part of a model on several processes (parallel/local_model.hpp).
  bool is_part() const { return own.group != nullptr; }
  // The gradients the internal force is scattered with (#entries of at_points).
  const std::vector<vec2>& test_gradients() const { return test_gradient.empty() ? at_points.grad : test_gradient; }
};

// The particles and the cells must describe the same body.
inline void check_body(const particle_set<2>& particles, const background_mesh& mesh) {
  particles.validate();
  mesh.validate();
  double particle_volume = 0.0;
  for (double v : particles.volume) particle_volume += v;
  const double cell_area = mesh.area();
  if (std::abs(particle_volume - cell_area) > 1e-2 * cell_area)
    fail("particle volumes add up to {:.6g} but the background cells cover {:.6g}: the particle "
         "set and the cells must describe the same body (check units and extents)",
         particle_volume, cell_area);
}

// Lumped volumes V_I = sum_q N_I(X_q) w_q; each must be positive. `tolerant` (cracks, or a model
// rebuilt, whose masses are kept and whose V_I only the projections read): a particle no point's
// row holds (a free particle, section 3.7), or only negative lobes (near a crack's tip, in a
// layer squeezed thinner than the supports, section 5.8), takes its own volume.
inline std::vector<double> lumped_volumes(const particle_set<2>& particles, const quadrature_points& points,
                                          const shape_table<2>& at_points, bool tolerant = false) {
  std::vector<double> volume(particles.size(), 0.0);
  for (index_t q = 0; q < points.size(); ++q)
    for (index_t e = at_points.offset[q]; e < at_points.offset[q + 1]; ++e)
      volume[at_points.neighbor[e]] += at_points.N[e] * points.weight[q];
  for (index_t I = 0; I < particles.size(); ++I)
    if (tolerant && !(volume[I] > 0.0)) volume[I] = particles.volume[I];
  for (index_t I = 0; I < particles.size(); ++I)
    if (!(volume[I] > 0.0))
      fail("particle {} at ({:.6g}, {:.6g}) gets a lumped mass of {:.3g} x density: it is covered by "
           "no quadrature point or by negative shape-function lobes; refine the background cells, "
           "enlarge the support or use the linear correction",
           I, particles.position[I][0], particles.position[I][1], volume[I]);
  return volume;
}

// The model on given quadrature points (`rebuilt`: carried, section 5.8): only this depends on the
// kernel and the correction, so a program compiles it once per (kernel, correction).
template <Kernel K, Correction C>
discrete_model build_discrete_model_on(particle_set<2> particles, background_mesh mesh, quadrature_points points,
                                       double max_condition = default_max_moment_condition, bool rebuilt = false) {
  discrete_model m;
  m.points = std::move(points);
  const neighbor_search<2> search(particles, &mesh.cracks);
  const rk_shape_functions<K, C, 2> rk(max_condition);
  m.at_points = build_shape_table<K, C, 2>(search, m.points.position, rk);
  m.at_particles = build_shape_table<K, C, 2>(search, particles.position, rk, values_only);
  if (!mesh.cracks.empty()) m.at_particles = with_free_particles(std::move(m.at_particles));
  m.traversal = make_point_traversal(m.at_points, particles.size());
  m.lumped_volume = lumped_volumes(particles, m.points, m.at_points, rebuilt || !mesh.cracks.empty());
  m.own = ownership::single_process(particles.size(), m.point_count());
  m.particles = std::move(particles);
  m.mesh = std::move(mesh);
  return m;
}

// The model of a nodal rule (scni<Beta, EdgePoints>, docs/method.md section 3.6) with the
// stabilization beta given at run time (tests sweep it): smoothing cells, their points (one per
// node for beta = 0, one per part otherwise) and the smoothed gradients.
template <Kernel K, Correction C, Geometry G>
discrete_model build_nodal_model(particle_set<2> particles, background_mesh mesh, double beta, int edge_points,
                                 double max_condition = default_max_moment_condition) {
  if (!(beta >= 0.0 && beta <= 1.0)) fail("nodal integration: the stabilization {} must lie in [0, 1]", beta);
  if (!mesh.cracks.empty())
    fail("nodal integration with cracks: the smoothing cells do not follow a crack; use a cell rule (q4, q2, "
         "with or without vci) for a body that cracks");
  const smoothing_cells cells = make_smoothing_cells(mesh);
  const nodal_points np = make_nodal_points<G>(cells, beta > 0.0);
  discrete_model m = build_discrete_model_on<K, C>(std::move(particles), std::move(mesh), np.points, max_condition);
  smooth_point_gradients<K, C, G>(m.particles, cells, np, beta, edge_points, m.at_points, max_condition);
  m.traversal = make_point_traversal(m.at_points, m.particle_count());
  m.nodal = true;
  return m;
}

namespace detail {

// One model over all the particles and cells, without its bodies. `carried`: the points of a
// model rebuilt in the current configuration (section 5.8), the material points of the one before
// with their current weights, in place of the rule's points on the cells (a nodal rule ignores
// them and smooths on the cells).
template <Kernel K, Correction C, Quadrature Q, Geometry G>
discrete_model build_one_model(particle_set<2> particles, background_mesh mesh, double max_condition,
                               const quadrature_points* carried = nullptr) {
  if (!carried || NodalRule<Q>) check_body(particles, mesh);
  if constexpr (NodalRule<Q>) {
    return build_nodal_model<K, C, G>(std::move(particles), std::move(mesh), Q::stabilization, Q::edge_points,
                                      max_condition);
  } else {
    quadrature_points points = carried ? *carried : make_quadrature_points<Q, G>(mesh);
    discrete_model m = build_discrete_model_on<K, C>(std::move(particles), std::move(mesh), std::move(points),
                                                     max_condition, carried != nullptr);
    if constexpr (CorrectedRule<Q>)
      m.test_gradient = vci_test_gradients(
          m.points, m.at_points, boundary_integrals<K, C, G>(m.particles, m.mesh, Q::edge_points, max_condition),
          G::is_axisymmetric);
    return m;
  }
}

}  // namespace detail

// The model with one set of shape functions over all the cells (with several bodies the kernels
// reach across them; build_model_of_bodies in solver/body_models.hpp keeps them apart).
template <Kernel K, Correction C, Quadrature Q, Geometry G>
discrete_model build_discrete_model(particle_set<2> particles, background_mesh mesh,
                                    double max_condition = default_max_moment_condition) {
  particles.validate();
  model_bodies bodies(particles.position, mesh, G::is_axisymmetric);
  discrete_model m = detail::build_one_model<K, C, Q, G>(std::move(particles), std::move(mesh), max_condition);
  m.set_bodies(std::move(bodies));
  return m;
}

// A model builder with its method fixed (make_solver's): the model of particles in cells, with
// the moment-matrix conditioning limit. A solver keeps the one it was built with, so that its
// tables can be built again on another particle set (model_factory()).
// `carried`: the points of a re-referenced model (build_one_model), or null.
using model_factory = std::function<discrete_model(particle_set<2> particles, background_mesh mesh,
                                                   double max_condition, const quadrature_points* carried)>;

// The model with its bodies found, if it was assembled without a builder that finds them.
template <Geometry G>
discrete_model with_bodies(discrete_model m) {
  if (!m.bodies.found()) m.set_bodies(model_bodies(m.particles.position, m.mesh, G::is_axisymmetric));
  return m;
}

// Lumped masses m_I = rho0 V_I (docs/method.md section 5).
inline std::vector<double> lumped_masses(const discrete_model& m, double density) {
  std::vector<double> mass(m.lumped_volume.size());
  for (std::size_t I = 0; I < mass.size(); ++I) mass[I] = density * m.lumped_volume[I];
  return mass;
}

}  // namespace rkpm

// A program that compiles the shipped policies' models once (see the header).
#ifdef RKPM_EXTERN_MODELS
#include <rkpm/solver/model_instances.hpp>
#endif
