#pragma once
// A rank's part of the model built without the model of the whole (docs/method.md section 9.8,
// "Set-up in parts"). Every rank holds the layout of the whole: the particles, the cells, the
// quadrature points and the bodies (model_layout, about 200 bytes a particle), never a shape
// table of the whole (1.6 KB a particle). From it:
//   - the plans and the traversal read the whole model's rows through a neighbour search,
//     one row at a time (discretization/search_rows.hpp), never stored;
//   - the rank evaluates the shape functions at its own points (the plan's: those whose
//     support holds an owned particle) and at the particles whose rows the plan reads (its own,
//     those whose rows hold one of its own, the shared region's, its ghosts);
//   - its owned particles' lumped volumes are summed over its points, in the whole model's
//     point order; the ghosts' come from their owners (distributed_solver forwards them).
// Each value is evaluated at the same position with the same search as the whole model's
// builder does, so the rank's model equals local_model(whole, plan) entry by entry, and its
// plan make_halo_plan(whole...)'s (tests/mpi/rank_setup.cpp).
// The layout is the set-up's replicated part; the rank drops it once its part is built.
// Several bodies as build_model_of_bodies (solver/body_models.hpp) builds them: the points body
// by body, each row within its position's body (body_searches: one search per body over its
// particles, which finds what the body's own search finds, ascending, so the same bits).
// Cell rules only: VCI's corrected gradients and SCNI's smoothed ones need each particle's cells
// whole, and cracks make the rows depend on the values; both are refused.

#include <cmath>
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include <rkpm/concepts/correction.hpp>
#include <rkpm/concepts/geometry.hpp>
#include <rkpm/concepts/kernel.hpp>
#include <rkpm/concepts/quadrature.hpp>
#include <rkpm/discretization/search_rows.hpp>
#include <rkpm/parallel/global_blocks.hpp>
#include <rkpm/parallel/halo.hpp>
#include <rkpm/parallel/local_model.hpp>
#include <rkpm/solver/discrete_model.hpp>

namespace rkpm::parallel {

// The whole model without its tables (`whole`: particles, mesh, points, bodies), and the shape
// functions of its kernel and correction at chosen positions (of one body, from its search).
struct model_layout {
  discrete_model whole;
  std::function<shape_table<2>(const neighbor_search<2>&, const std::vector<vec2>&, shape_table_contents)> evaluate;
};

namespace detail {

// Each body's particles and cells must describe the same body (check_body per body, as
// build_model_of_bodies checks each body's part).
inline void check_bodies(const particle_set<2>& particles, const background_mesh& mesh, const model_bodies& bodies) {
  std::vector<double> volume(bodies.count(), 0.0), area(bodies.count(), 0.0);
  for (index_t I = 0; I < particles.size(); ++I) volume[bodies.of_particle(I)] += particles.volume[I];
  for (index_t c = 0; c < mesh.cells(); ++c) area[bodies.of_cell(c)] += mesh.cell_area(c);
  for (index_t b = 0; b < bodies.count(); ++b)
    if (std::abs(volume[b] - area[b]) > 1e-2 * area[b])
      fail("body {}: particle volumes add up to {:.6g} but its background cells cover {:.6g}: the particle set and "
           "the cells must describe the same body (check units and extents)",
           b, volume[b], area[b]);
}

// The points of body 0's cells, then body 1's, ...: build_model_of_bodies's order. A cell's points
// depend on its nodes only, so they are the body's own points, bit for bit.
inline quadrature_points points_body_by_body(const quadrature_points& all, const model_bodies& bodies) {
  std::vector<index_t> start(bodies.count() + 1, 0);  // a stable counting sort by body
  for (index_t q = 0; q < all.size(); ++q) ++start[bodies.of_cell(all.cell[q]) + 1];
  for (index_t b = 0; b < bodies.count(); ++b) start[b + 1] += start[b];
  quadrature_points p;
  p.position.resize(all.size());
  p.weight.resize(all.size());
  p.cell.resize(all.size());
  for (index_t q = 0; q < all.size(); ++q) {
    const index_t k = start[bodies.of_cell(all.cell[q])]++;
    p.position[k] = all.position[q];
    p.weight[k] = all.weight[q];
    p.cell[k] = all.cell[q];
  }
  return p;
}

// The layout's rows at positions `at`, each within its body (`body(k)`: position k's), in
// their order. Runs of consecutive positions of one body are evaluated a chunk at a time and
// appended, into a table reserved to its size when nothing is dropped (a row holds what its
// search finds), so that the rank holds its table once and a chunk's besides.
template <class BodyOf>
shape_table<2> rows_by_body(const model_layout& l, const body_searches<2>& searches, const std::vector<vec2>& at,
                            BodyOf body, shape_table_contents contents) {
  if (searches.count() == 1) return l.evaluate(searches.of(0), at, contents);
  const auto n = static_cast<index_t>(at.size());
  shape_table<2> t;
  if (!(contents.drop_below > 0.0)) {
    std::size_t entries = 0;
    std::vector<index_t> found;
    for (index_t k = 0; k < n; ++k) {
      searches.of(body(k)).query(at[k], found);
      entries += found.size();
    }
    t.offset.reserve(n + 1);
    t.neighbor.reserve(entries);
    t.N.reserve(entries);
    if (contents.gradients) t.grad.reserve(entries);
  }
  constexpr index_t chunk = 4096;
  std::vector<vec2> some;
  for (index_t k = 0; k < n;) {
    const index_t b = body(k);
    some.clear();
    for (; k < n && body(k) == b && static_cast<index_t>(some.size()) < chunk; ++k) some.push_back(at[k]);
    const shape_table<2> rows = l.evaluate(searches.of(b), some, contents);
    t.neighbor.insert(t.neighbor.end(), rows.neighbor.begin(), rows.neighbor.end());
    t.N.insert(t.N.end(), rows.N.begin(), rows.N.end());
    t.grad.insert(t.grad.end(), rows.grad.begin(), rows.grad.end());
    const stored_index before = t.offset.back();
    for (index_t r = 1; r <= rows.points(); ++r) t.offset.push_back(before + rows.offset[r]);
  }
  return t;
}

}  // namespace detail

// The layout of build_model_of_bodies<K, C, Q, G>(particles, mesh, max_condition)'s model
// (build_discrete_model's with one body). `evaluate` gives the rows at positions of one body
// from that body's search.
template <Kernel K, Correction C, Quadrature Q, Geometry G>
model_layout make_model_layout(particle_set<2> particles, background_mesh mesh,
                               double max_condition = default_max_moment_condition) {
  if constexpr (NodalRule<Q> || CorrectedRule<Q>)
    fail("set-up in parts with the rule {}: its gradients need each particle's cells whole; set up a VCI or SCNI "
         "model whole (distributed_solver from a discrete_model)",
         Q::name);
  if (!mesh.cracks.empty())
    fail("set-up in parts with cracks in the cells: the rows near a crack depend on the shape functions; set up a "
         "cracked model whole");
  particles.validate();
  model_bodies bodies(particles.position, mesh, G::is_axisymmetric);
  model_layout l;
  if constexpr (!NodalRule<Q>) l.whole.points = make_quadrature_points<Q, G>(mesh);
  if (bodies.count() == 1) {
    check_body(particles, mesh);
  } else {
    detail::check_bodies(particles, mesh, bodies);
    l.whole.points = detail::points_body_by_body(l.whole.points, bodies);
  }
  l.whole.particles = std::move(particles);
  l.whole.mesh = std::move(mesh);
  l.whole.set_bodies(std::move(bodies));
  l.evaluate = [max_condition](const neighbor_search<2>& search, const std::vector<vec2>& at,
                               shape_table_contents contents) {
    const rk_shape_functions<K, C, 2> rk(max_condition);
    return build_shape_table<K, C, 2>(search, at, rk, contents);
  };
  return l;
}

namespace detail {

// The rows of the layout's table at the particles (values_only) of the particles marked in
// `wanted`, the others' rows empty: the whole table's rows where they are wanted.
inline shape_table<2> rows_at_particles(const model_layout& l, const body_searches<2>& searches,
                                        const std::vector<char>& wanted) {
  const std::vector<vec2>& X = l.whole.particles.position;
  std::vector<vec2> at;
  std::vector<index_t> body;
  for (index_t I = 0; I < static_cast<index_t>(X.size()); ++I)
    if (wanted[I]) {
      at.push_back(X[I]);
      body.push_back(l.whole.bodies.of_particle(I));
    }
  const shape_table<2> some = rows_by_body(l, searches, at, [&](index_t k) { return body[k]; }, values_only);
  shape_table<2> t;
  t.offset.assign(1, 0);
  index_t k = 0;
  for (index_t I = 0; I < static_cast<index_t>(X.size()); ++I) {
    if (wanted[I]) {
      const std::span<const particle_index> row = some.columns(k);
      t.neighbor.insert(t.neighbor.end(), row.begin(), row.end());
      t.N.insert(t.N.end(), some.N.begin() + some.offset[k], some.N.begin() + some.offset[k + 1]);
      ++k;
    }
    t.offset.push_back(static_cast<stored_index>(t.neighbor.size()));
  }
  return t;
}

// Row I of `a` where `a` has it, else of `b` (tables from rows_at_particles of disjoint sets).
inline shape_table<2> merged_rows(const shape_table<2>& a, const shape_table<2>& b) {
  shape_table<2> t;
  for (index_t I = 0; I < a.points(); ++I) {
    const shape_table<2>& from = a.offset[I + 1] > a.offset[I] ? a : b;
    const std::span<const particle_index> row = from.columns(I);
    t.neighbor.insert(t.neighbor.end(), row.begin(), row.end());
    t.N.insert(t.N.end(), from.N.begin() + from.offset[I], from.N.begin() + from.offset[I + 1]);
    t.offset.push_back(static_cast<stored_index>(t.neighbor.size()));
  }
  return t;
}

}  // namespace detail

// A rank's plan and model, as from the whole model (shared_particles and local_model, with
// `rows` the whole table at the particles), but from the layout. `shared_region(rows)` gives the
// particles every rank holds from the rows at the particles it reads (the constrained, slave and
// surface particles' rows, which the caller marks in `region`).
struct rank_model {
  halo_plan plan;
  discrete_model local;
  index_t shared = 0;
  particle_partition point_owner;  // every point's owner (global_blocks.hpp), from the same search
};

template <class SharedRegion>
rank_model rank_model_of(const model_layout& l, const particle_partition& partition, int rank,
                         const std::vector<index_t>& region, SharedRegion&& shared_region) {
  const discrete_model& w = l.whole;
  const index_t n = w.particle_count();
  if (partition.particles() != n)
    fail("set-up in parts: the partition has {} particles but the model {}; partition this model's particles",
         partition.particles(), n);
  const std::vector<stored_index>& part = partition.part;
  const body_searches<2> search(w.particles, w.bodies.particle_body(), w.bodies.count());
  const search_rows<2> point_rows(search, w.points.position, [&](index_t q) { return w.bodies.of_point(q); });
  const search_rows<2> particle_rows(search, w.particles.position, [&](index_t I) { return w.bodies.of_particle(I); });
  // The rows at the particles the plan reads: the owned ones, those that hold an owned one, the
  // shared region's.
  std::vector<char> wanted(n, 0);
  for (index_t I = 0; I < n; ++I)
    wanted[I] = part[I] == rank ||
                std::ranges::any_of(particle_rows.columns(I), [&](particle_index J) { return part[J] == rank; });
  for (const index_t I : region) wanted[I] = 1;
  shape_table<2> rows = detail::rows_at_particles(l, search, wanted);
  rank_model r;
  const std::vector<stored_index> shared = shared_region(rows);
  r.shared = static_cast<index_t>(shared.size());
  r.plan = make_halo_plan(partition, point_rows, rank, &rows, shared);
  // The ghosts' rows too (local_model keeps those whose columns the rank holds).
  std::vector<char> added(n, 0);
  bool more = false;
  for (const stored_index I : r.plan.ghosts) more |= (added[I] = !wanted[I]) != 0;
  if (more) rows = detail::merged_rows(rows, detail::rows_at_particles(l, search, added));

  const halo_plan& h = r.plan;
  discrete_model& m = r.local;
  // The particles and points of local_force_model and local_model, from the layout.
  for (index_t i = 0; i < h.local_particles(); ++i) {
    const index_t I = h.global_particle(i);
    m.particles.position.push_back(w.particles.position[I]);
    m.particles.volume.push_back(w.particles.volume[I]);
    m.particles.support.push_back(w.particles.support[I]);
  }
  std::vector<vec2> at;
  for (const stored_index q : h.points) {
    at.push_back(w.points.position[q]);
    m.points.position.push_back(w.points.position[q]);
    m.points.weight.push_back(w.points.weight[q]);
    if (!w.points.cell.empty()) m.points.cell.push_back(w.points.cell[q]);
  }
  // The rows at the particles as local_model keeps them; the rank's rows at its points,
  // evaluated here, in local columns.
  const std::vector<stored_index> local = keep_held_rows(rows, h, m);
  m.at_points = detail::rows_by_body(l, search, at, [&](index_t k) { return w.bodies.of_point(h.points[k]); }, {});
  for (particle_index& I : m.at_points.neighbor) I = local[I];
  m.traversal = local_traversal(h, make_point_traversal(point_rows, n));
  r.point_owner = point_owners(partition, point_rows);
  // V_I = sum_q N_I(X_q) w_q (lumped_volumes) over the rank's points in the whole model's order:
  // every point of an owned particle is here, so its sum is the whole model's.
  m.lumped_volume.assign(h.local_particles(), 0.0);
  for (index_t k = 0; k < m.point_count(); ++k)
    for (index_t e = m.at_points.offset[k]; e < m.at_points.offset[k + 1]; ++e)
      m.lumped_volume[m.at_points.neighbor[e]] += m.at_points.N[e] * m.points.weight[k];
  for (index_t i = 0; i < static_cast<index_t>(h.owned.size()); ++i)
    if (!(m.lumped_volume[i] > 0.0))
      fail("particle {} at ({:.6g}, {:.6g}) gets a lumped mass of {:.3g} x density: it is covered by no quadrature "
           "point or by negative shape-function lobes; refine the background cells, enlarge the support or use "
           "the linear correction",
           h.owned[i], m.particles.position[i][0], m.particles.position[i][1], m.lumped_volume[i]);
  m.own = h.own();
  m.global_mean_support = w.mean_support();
  m.point_id = h.points;
  m.whole_points = h.global_points;
  m.bodies = model_bodies::part(w.bodies, m.particle_id, h.points, local);
  return r;
}

}  // namespace rkpm::parallel
