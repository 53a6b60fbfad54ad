#pragma once
// measure(solver, case, mean_tool_force): the case file's histories evaluated on a solver at
// its current time, in the file's order, as (name, value) pairs like the typed cases'
// measure(). The arithmetic is theirs (a maximum over the same particles, a gap as reference
// gap plus relative displacement, a force as the runner's mean over the last output
// interval), so that the paper case files give the typed cases' numbers bit for bit. With
// several bodies each measure that names a body looks at that body's particles or points only.
//   mean_tool_force  #tools list of the tools' reactions averaged over the last interval (N
//                    or N/m, as the runner passes them to every case's measure)
// measure() is measure_from() of the maxima, sums and nearest values measure_parts.hpp takes
// over the solver's own particles and points, which on several processes combine over the
// ranks first.

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include <rkpm/core/exact_sum.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/io/solver_output.hpp>

#include "build_problem.hpp"
#include "case_description.hpp"
#include "measure_parts.hpp"

namespace rkpm::runner::case_file {

namespace detail {

// Index of the tool called `name` among the solver's tools (the file's order).
template <class Solver>
std::size_t tool_index(const Solver& s, const std::string& name) {
  const auto& tools = s.contact().tools();
  for (std::size_t k = 0; k < tools.size(); ++k)
    if (tools[k].name() == name) return k;
  fail("case file: the solver has no tool '{}' (was it built from this case file?)", name);
}

// The particles [first, last) of the body called `name`: build_problem adds the bodies in the
// file's order, each one's particles after the previous ones'.
struct particle_range {
  index_t first = 0, last = 0;
};
template <class Solver>
particle_range body_particles(const Solver& s, const case_description& c, const std::string& name) {
  const auto n = s.model().particle_count();
  if (c.bodies.size() == 1) return {0, n};
  index_t k = 0;
  while (static_cast<std::size_t>(k) < c.bodies.size() && c.bodies[k].name != name) ++k;
  particle_range r{n, n};
  for (index_t I = 0; I < n; ++I)
    if (s.body_of_particle(I) == k) {
      r.first = std::min(r.first, I);
      r.last = I + 1;
    }
  return r;
}

// Largest, smallest or spread of the current x or y of the particles selected; 0 if none is
// (as the typed wheel's rim height before material reaches the recess).
template <class Solver>
double extent_of(const Solver& s, const body_description& b, particle_range body, const extent_history& h,
                 const std::vector<vec2>& x) {
  const auto& X = s.initial_positions();
  std::vector<index_t> chosen;
  if (h.on_edge.empty()) {
    for (index_t I = body.first; I < body.last; ++I) chosen.push_back(I);
  } else {  // the body's own particles: edges are named per body
    const std::vector<vec2> own(X.begin() + body.first, X.begin() + body.last);
    for (index_t I : particles_on_edge(b, own, h.on_edge)) chosen.push_back(body.first + I);
  }
  const int k = h.of.back() == 'x' ? 0 : 1;
  bool any = false;
  double lo = 0.0, hi = 0.0;
  for (index_t I : chosen) {
    const vec2& p = x[I];
    // NaN bounds compare false, so an absent bound keeps every particle.
    if (p.x() >= h.x_below || p.x() <= h.x_above || p.y() >= h.y_below || p.y() <= h.y_above) continue;
    lo = any ? std::min(lo, p[k]) : p[k];
    hi = any ? std::max(hi, p[k]) : p[k];
    any = true;
  }
  if (!any) return 0.0;
  if (h.of.starts_with("max")) return hi;
  if (h.of.starts_with("min")) return lo;
  return hi - lo;
}

// Whether quadrature point q belongs to the body called `name` (kernels never reach across
// bodies, so a point's body is that of any particle in its row).
template <class Solver>
auto of_body(const Solver& s, const case_description& c, const std::string& name) {
  const auto body = body_particles(s, c, name);
  const auto& rows = s.model().at_points;
  return [body, &rows](std::size_t q) {
    const index_t I = rows.neighbor[rows.offset[q]];
    return I >= body.first && I < body.last;
  };
}

template <class Solver>
double evaluate(const Solver& s, const case_description& c, const history_kind& kind,
                const std::vector<vec2>& mean_tool_force, const std::vector<vec2>& x) {
  return std::visit(
      [&](const auto& h) -> double {
        using H = std::decay_t<decltype(h)>;
        if constexpr (std::is_same_v<H, extent_history>) {
          const auto body = body_particles(s, c, h.body);
          for (const auto& b : c.bodies)
            if (b.name == h.body) return extent_of(s, b, body, h, x);
          fail("case file: no body '{}'", h.body);
        } else if constexpr (std::is_same_v<H, tool_gap_history>) {
          const auto& from = s.contact().tools()[tool_index(s, h.from)];
          const auto& to = s.contact().tools()[tool_index(s, h.to)];
          double top = to.reference_vertices().front()[h.component];
          double bottom = from.reference_vertices().front()[h.component];
          for (const vec2& v : to.reference_vertices()) top = std::min(top, v[h.component]);
          for (const vec2& v : from.reference_vertices()) bottom = std::max(bottom, v[h.component]);
          const double t = s.time();
          return (top - bottom) + (to.displacement(t)[h.component] - from.displacement(t)[h.component]);
        } else if constexpr (std::is_same_v<H, tool_force_history>) {
          const std::size_t k = tool_index(s, h.tool);
          const double f = k < mean_tool_force.size() ? mean_tool_force[k][h.component] : 0.0;
          return h.absolute ? std::abs(f) : f;
        } else if constexpr (std::is_same_v<H, tool_displacement_history>) {
          return s.contact().tools()[tool_index(s, h.tool)].displacement(s.time())[h.component];
        } else if constexpr (std::is_same_v<H, probe_history>) {
          fail("case file: a probe is measured by measure_nearest (measure_parts.hpp)");
        } else if constexpr (std::is_same_v<H, max_plastic_strain_history>) {
          const auto in_body = of_body(s, c, h.body);
          double eps_p = 0.0;
          for (std::size_t q = 0; q < s.point_states().size(); ++q)
            if (in_body(q)) eps_p = std::max(eps_p, s.point_states()[q].equivalent_plastic_strain);
          return eps_p;
        } else if constexpr (std::is_same_v<H, max_temperature_history>) {
          return io::largest_state_field(s, "temperature_K", of_body(s, c, h.body));
        } else if constexpr (std::is_same_v<H, failed_fraction_history>) {
          return io::failed_fraction(s, of_body(s, c, h.body));
        } else if constexpr (std::is_same_v<H, max_penetration_history>) {
          return s.max_penetration();
        } else if constexpr (std::is_same_v<H, momentum_history>) {
          const auto body = body_particles(s, c, h.body);
          exact_sum P;  // exact sums, as the typed cases' (a row's sums then reduce over processes)
          for (index_t I = body.first; I < body.last; ++I) P.add(s.mass()[I] * s.coefficient_velocities()[I][h.component]);
          return P.value();
        } else {
          const auto in_body = of_body(s, c, h.body);
          exact_sum v0, v;
          const auto& w = s.model().points.weight;
          for (std::size_t q = 0; q < w.size(); ++q) {
            if (!in_body(q)) continue;
            v0.add(w[q]);
            v.add(w[q] * s.point_det_F(q));
          }
          return v.value() / v0.value() - 1.0;
        }
      },
      kind);
}

}  // namespace detail

// The row from the maxima, sums and nearest values of measure_parts.hpp (over the whole model,
// or combined over the ranks' parts) and the totals `s` holds; a history that cannot be reduced
// is evaluated on `s`, which is then the whole model.
template <class Solver>
std::vector<std::pair<std::string, double>> measure_from(const std::vector<double>& maxima,
                                                         const std::vector<exact_sum>& sums,
                                                         const std::vector<nearest_value>& nearest, const Solver& s,
                                                         const case_description& c,
                                                         const std::vector<vec2>& mean_tool_force) {
  std::vector<std::pair<std::string, double>> out;
  out.reserve(c.histories.size());
  std::vector<vec2> x;  // the whole model's positions, for the histories that are not reduced
  std::size_t m = 0, k = 0, n = 0;
  for (const auto& h : c.histories) {
    double value = 0.0;
    if (!detail::reducible(c, h.kind)) {
      if (x.empty()) x = s.particle_positions();
      value = detail::evaluate(s, c, h.kind, mean_tool_force, x);
    } else if (const auto* e = std::get_if<extent_history>(&h.kind)) {
      const double hi = maxima[m], lo = -maxima[m + 1];
      value = maxima[m + 2] == 0.0 ? 0.0 : e->of.starts_with("max") ? hi : e->of.starts_with("min") ? lo : hi - lo;
      m += 3;
    } else if (std::holds_alternative<probe_history>(h.kind)) {
      value = nearest[n++].value;
    } else if (std::holds_alternative<max_plastic_strain_history>(h.kind)) {
      value = maxima[m++];
    } else if (std::holds_alternative<max_temperature_history>(h.kind)) {
      value = maxima[m] == detail::none ? std::numeric_limits<double>::quiet_NaN() : maxima[m];
      ++m;
    } else if (std::holds_alternative<momentum_history>(h.kind)) {
      value = sums[k++].value();
    } else if (std::holds_alternative<volume_change_history>(h.kind)) {
      value = sums[k + 1].value() / sums[k].value() - 1.0;
      k += 2;
    } else if (std::holds_alternative<failed_fraction_history>(h.kind)) {
      const double chosen = sums[k].value(), failed = sums[k + 1].value();
      value = chosen > 0.0 ? failed / chosen : 0.0;
      k += 2;
    } else {  // the tools' and the contact's: totals every rank holds
      value = detail::evaluate(s, c, h.kind, mean_tool_force, x);
    }
    out.emplace_back(h.name, value * h.scale);
  }
  return out;
}

template <class Solver>
std::vector<std::pair<std::string, double>> measure(const Solver& s, const case_description& c,
                                                    const std::vector<vec2>& mean_tool_force) {
  return measure_from(measure_maxima(s, c), measure_sums(s, c), measure_nearest(s, c), s, c, mean_tool_force);
}

}  // namespace rkpm::runner::case_file
