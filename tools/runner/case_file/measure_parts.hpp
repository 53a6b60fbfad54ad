#pragma once
// A case file's histories from what each process takes over its part (tools/runner/
// row_reduction.hpp, docs/method.md section 9.8), so that a row on several processes gathers
// nothing:
//   measure_maxima(solver, case)        per history, in the file's order: an extent's largest
//                                       and negated smallest coordinate and whether any particle
//                                       was chosen; a largest plastic strain or temperature (-inf
//                                       where none), over the solver's own particles and points
//   measure_sums(solver, case)          per history: a momentum's sum of m v, a volume change's
//                                       sums of w and w det F, a failed fraction's counts; exact
//                                       sums (core/exact_sum.hpp), so in no particular order
//   measure_nearest(solver, case)       per probe: the solver's own particle of the body nearest
//                                       the point in the reference configuration (X, fixed for
//                                       the run), its global index and the quantity there
//                                       (nearest_value: over the ranks the nearest of all, ties
//                                       to the smallest index, one process's choice)
//   measure_from(maxima, sums, nearest, solver, case, mean_tool_force)
//                                       the row from them (combined over the ranks) and the
//                                       totals every rank holds (time, tools, penetration)
// On one process the same functions give case_file::measure its values, so that a row has the
// same bits on any number of processes.

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include <rkpm/core/exact_sum.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/io/solver_output.hpp>
#include <rkpm/solver/fields.hpp>

#include "../row_reduction.hpp"
#include "body_edges.hpp"
#include "case_description.hpp"

namespace rkpm::runner::case_file {

namespace detail {

// The index of the body called `name` in the file; with one body, every particle is its own.
inline index_t body_index(const case_description& c, const std::string& name) {
  for (std::size_t k = 0; k < c.bodies.size(); ++k)
    if (c.bodies[k].name == name) return static_cast<index_t>(k);
  fail("case file: no body '{}'", name);
}
template <class Solver>
bool in_body(const Solver& s, const case_description& c, index_t body, index_t I) {
  return c.bodies.size() == 1 || s.body_of_particle(I) == body;
}

// Whether a particle (of the solver's model) started on the edge, as particles_on_edge decides:
// by its reference position on the edge's segment, or for a Gmsh body by its node group (node i
// of body b is the whole model's particle first_particle(b) + i: build_problem adds the bodies in
// the file's order). The segment, its tolerance and the group are found once, not per particle.
template <class Solver>
auto edge_test(const Solver& s, const body_description& b, index_t body, const std::string& edge) {
  const std::vector<index_t>* group = nullptr;  // a Gmsh body's
  const index_t first = s.model().bodies.first_particle(body);
  std::optional<std::pair<vec2, vec2>> segment;
  double tol = 0.0;
  if (const auto* m = std::get_if<mesh_shape>(&b.shape)) {
    const auto it = m->body.node_groups.find(edge);
    if (it != m->body.node_groups.end()) group = &it->second;
  } else if ((segment = edge_segment(b, edge))) {
    tol = 1e-9 * extent(body_outline(b));
  }
  const bool mesh = std::holds_alternative<mesh_shape>(b.shape);
  return [&s, group, first, segment, tol, mesh](index_t I) {
    if (mesh) return group && std::ranges::binary_search(*group, s.model().global_particle(I) - first);
    return segment && distance_to_segment(s.initial_positions()[I], segment->first, segment->second) <= tol;
  };
}

constexpr double none = -std::numeric_limits<double>::infinity();

// Quadrature point q's body: that of the first particle in its row (kernels never reach across
// bodies).
template <class Solver>
bool point_in_body(const Solver& s, const case_description& c, index_t body, index_t q) {
  const auto& rows = s.model().at_points;
  return in_body(s, c, body, rows.neighbor[rows.offset[q]]);
}

}  // namespace detail

template <class Solver>
std::vector<double> measure_maxima(const Solver& s, const case_description& c) {
  std::vector<double> out;
  for (const history_description& h : c.histories) {
    if (const auto* e = std::get_if<extent_history>(&h.kind)) {
      const index_t body = detail::body_index(c, e->body);
      const int k = e->of.back() == 'x' ? 0 : 1;
      double hi = detail::none, minus_lo = detail::none, any = 0.0;
      const auto on_edge = detail::edge_test(s, c.bodies[body], body, e->on_edge);
      for (index_t I = s.model().own.particles.begin; I < s.model().own.particles.end; ++I) {
        if (!detail::in_body(s, c, body, I)) continue;
        if (!e->on_edge.empty() && !on_edge(I)) continue;
        const vec2 p = position_at_particle(s.model(), s.coefficients(), I);
        // NaN bounds compare false, so an absent bound keeps every particle.
        if (p.x() >= e->x_below || p.x() <= e->x_above || p.y() >= e->y_below || p.y() <= e->y_above) continue;
        hi = std::max(hi, p[k]);
        minus_lo = std::max(minus_lo, -p[k]);
        any = 1.0;
      }
      out.insert(out.end(), {hi, minus_lo, any});
    } else if (const auto* m = std::get_if<max_plastic_strain_history>(&h.kind)) {
      const index_t body = detail::body_index(c, m->body);
      double eps_p = 0.0;
      for_each_owned_point(s.model(), [&](index_t q) {
        if (detail::point_in_body(s, c, body, q)) eps_p = std::max(eps_p, s.point_states()[q].equivalent_plastic_strain);
      });
      out.push_back(eps_p);
    } else if (const auto* t = std::get_if<max_temperature_history>(&h.kind)) {
      const index_t body = detail::body_index(c, t->body);
      std::vector<char> owned(s.point_states().size(), 0);
      for_each_owned_point(s.model(), [&](index_t q) { owned[q] = 1; });
      const double largest = io::largest_state_field(s, "temperature_K", [&](std::size_t q) {
        return owned[q] && detail::point_in_body(s, c, body, static_cast<index_t>(q));
      });
      out.push_back(std::isnan(largest) ? detail::none : largest);
    }
  }
  return out;
}

template <class Solver>
std::vector<nearest_value> measure_nearest(const Solver& s, const case_description& c) {
  std::vector<nearest_value> out;
  const discrete_model& m = s.model();
  const std::vector<vec2>& X = s.initial_positions();
  for (const history_description& h : c.histories) {
    const auto* p = std::get_if<probe_history>(&h.kind);
    if (!p) continue;
    const index_t body = detail::body_index(c, p->body);
    nearest_value best;
    index_t chosen = -1;
    for (index_t I = m.own.particles.begin; I < m.own.particles.end; ++I) {
      if (!detail::in_body(s, c, body, I)) continue;
      const nearest_value here{(X[I] - p->point).squaredNorm(), static_cast<double>(m.global_particle(I))};
      if (here.before(best)) {
        best = here;
        chosen = I;
      }
    }
    if (chosen >= 0) {
      // As the solver's particle_positions(), particle_velocities() and particle_displacements()
      // give it: the displacement since the initial reference once the model was re-referenced.
      vec2 value;
      if (p->quantity == "position") {
        value = position_at_particle(m, s.coefficients(), chosen);
      } else if (p->quantity == "velocity") {
        value = m.at_particles.interpolate(chosen, s.coefficient_velocities());
      } else {
        value = m.at_particles.interpolate(chosen, s.coefficients());
        if (&X != &m.particles.position) value += m.particles.position[chosen] - X[chosen];
      }
      best.value = value[p->component];
    }
    out.push_back(best);
  }
  return out;
}

template <class Solver>
std::vector<exact_sum> measure_sums(const Solver& s, const case_description& c) {
  std::vector<exact_sum> out;
  for (const history_description& h : c.histories) {
    if (const auto* m = std::get_if<momentum_history>(&h.kind)) {
      const index_t body = detail::body_index(c, m->body);
      exact_sum P;
      for (index_t I = s.model().own.particles.begin; I < s.model().own.particles.end; ++I)
        if (detail::in_body(s, c, body, I)) P.add(s.mass()[I] * s.coefficient_velocities()[I][m->component]);
      out.push_back(P);
    } else if (const auto* v = std::get_if<volume_change_history>(&h.kind)) {
      const index_t body = detail::body_index(c, v->body);
      exact_sum w0, w;
      const auto& weight = s.model().points.weight;
      for_each_owned_point(s.model(), [&](index_t q) {
        if (!detail::point_in_body(s, c, body, q)) return;
        w0.add(weight[q]);
        w.add(weight[q] * s.point_det_F(q));
      });
      out.insert(out.end(), {w0, w});
    } else if (const auto* f = std::get_if<failed_fraction_history>(&h.kind)) {
      const index_t body = detail::body_index(c, f->body);
      exact_sum chosen, failed;
      for_each_owned_point(s.model(), [&](index_t q) {
        if (!detail::point_in_body(s, c, body, q)) return;
        chosen.add(1.0);
        if constexpr (FailingState<typename Solver::state_type>) failed.add(s.point_states()[q].failed() ? 1.0 : 0.0);
      });
      out.insert(out.end(), {chosen, failed});
    }
  }
  return out;
}

}  // namespace rkpm::runner::case_file
