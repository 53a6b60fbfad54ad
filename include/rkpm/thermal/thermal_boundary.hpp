#pragma once
// Thermal boundary conditions on sets of boundary particles (docs/method.md section 5.9, (91)-(92)):
//   fixed_temperature  T^h(x_J) = T_b(t)          (imposed by projection, (92))
//   heat_flux          q(t), W/m^2 into the body   (Q_J = q A_J)
//   convection         h, T_inf(t)                 (Q_J = -h A_J (T^h(x_J) - T_inf))
// A set lists particles J and the tributary boundary length L_J of each (m); the area of J is
// A_J = L_J omega(x_J), with omega = 1 per metre of depth in plane strain and 2 pi r_J in
// axisymmetry (16). The lengths of an ordered chain of particles (a body's boundary_chain,
// discretization/boundary_chains.hpp, or a case file's named edge put in order along it, tools/
// runner/case_file/body_edges.hpp) come from tributary_lengths(): half of each segment to each of
// its ends. A set made by on_chain() keeps its chain, so that heat_conduction::
// update_boundary_geometry(x) measures the lengths again on the current positions.
//   particle  #J particle indices
//   length    #J tributary lengths, m

#include <algorithm>
#include <cmath>
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/discretization/boundary_chains.hpp>

namespace rkpm::thermal {

enum class boundary_kind { fixed_temperature, heat_flux, convection };

// A value that is constant or a function of time (s).
struct time_value {
  double value = 0.0;
  std::function<double(double)> of_time;
  time_value() = default;
  time_value(double v) : value(v) {}  // NOLINT: a constant converts implicitly
  time_value(std::function<double(double)> f) : of_time(std::move(f)) {}  // NOLINT
  double operator()(double t) const { return of_time ? of_time(t) : value; }
};

// Tributary lengths of the particles of an ordered chain at positions x (#particles): each
// particle gets half of each segment it ends. `closed`: the last particle joins the first.
inline std::vector<double> tributary_lengths(std::span<const index_t> chain, std::span<const vec2> x, bool closed) {
  const std::size_t n = chain.size();
  std::vector<double> length(n, 0.0);
  if (n < 2) return length;
  const std::size_t segments = closed ? n : n - 1;
  for (std::size_t s = 0; s < segments; ++s) {
    const std::size_t a = s, b = (s + 1) % n;
    const double half = 0.5 * (x[chain[b]] - x[chain[a]]).norm();
    length[a] += half;
    length[b] += half;
  }
  return length;
}

// The parts of a body's boundary chain (model_bodies::surface(), whose nodes are the particles)
// that a set of particles covers, each as an ordered run of consecutive chain nodes: a named edge
// of a case file (its particles by index, tools/runner/case_file/body_edges.hpp) becomes runs for
// on_chain(). A run covers whole segments only (a lone particle is a run of one, no length); a
// closed chain all of whose nodes are in the set is one closed run.
struct chain_run {
  std::vector<index_t> particle;
  bool closed = false;
};
inline std::vector<chain_run> chain_runs(const boundary_chain& chain, std::span<const index_t> particles) {
  const auto n = static_cast<index_t>(chain.node.size());
  std::vector<char> in(n, 0);
  for (index_t k = 0; k < n; ++k) in[k] = std::find(particles.begin(), particles.end(), chain.node[k]) != particles.end();
  if (chain.closed && std::all_of(in.begin(), in.end(), [](char c) { return c != 0; })) return {{chain.node, true}};
  // A closed chain is read from a node outside the set, so that no run is cut at the chain's start.
  index_t first = 0;
  if (chain.closed)
    while (in[first]) ++first;
  std::vector<chain_run> runs;
  for (index_t j = 0; j < n; ++j) {
    const index_t k = (first + j) % n;
    if (!in[k]) continue;
    if (j == 0 || !in[(k + n - 1) % n]) runs.emplace_back();
    runs.back().particle.push_back(chain.node[k]);
  }
  return runs;
}

struct thermal_boundary {
  boundary_kind kind = boundary_kind::heat_flux;
  std::vector<index_t> particle;
  std::vector<double> length;
  time_value value;            // T_b (K), q (W/m^2) or T_inf (K)
  double film_coefficient = 0.0;  // h, W/(m^2 K), convection only
  bool closed_chain = false;
  bool from_chain = false;  // particle is an ordered chain: lengths follow the positions

  static thermal_boundary fixed_temperature(std::vector<index_t> particles, std::vector<double> lengths, time_value T) {
    return {boundary_kind::fixed_temperature, std::move(particles), std::move(lengths), std::move(T)};
  }
  static thermal_boundary heat_flux(std::vector<index_t> particles, std::vector<double> lengths, time_value q) {
    return {boundary_kind::heat_flux, std::move(particles), std::move(lengths), std::move(q)};
  }
  static thermal_boundary convection(std::vector<index_t> particles, std::vector<double> lengths, double h,
                                     time_value T_inf) {
    return {boundary_kind::convection, std::move(particles), std::move(lengths), std::move(T_inf), h};
  }
  // The set on an ordered chain of particles at positions x, its lengths from tributary_lengths.
  static thermal_boundary on_chain(boundary_kind kind, std::vector<index_t> chain, std::span<const vec2> x,
                                   bool closed, time_value value, double h = 0.0) {
    thermal_boundary b{kind, std::move(chain), {}, std::move(value), h, closed, true};
    b.length = tributary_lengths(b.particle, x, closed);
    return b;
  }

  // One line naming the problem and the fix; `particles`: the model's count.
  void validate(index_t particles) const {
    if (length.size() != particle.size())
      fail("thermal boundary: {} particles but {} lengths: give one tributary length (m) per particle",
           particle.size(), length.size());
    for (std::size_t k = 0; k < particle.size(); ++k) {
      if (particle[k] < 0 || particle[k] >= particles)
        fail("thermal boundary: particle {} does not exist (the model has {} particles)", particle[k], particles);
      if (!(std::isfinite(length[k]) && length[k] >= 0.0))
        fail("thermal boundary: particle {} has the tributary length {:.6g} m: give a length >= 0", particle[k],
             length[k]);
    }
    if (kind == boundary_kind::convection && !(std::isfinite(film_coefficient) && film_coefficient >= 0.0))
      fail("thermal boundary: the film coefficient h = {:.6g} W/(m^2 K) must be finite and not negative (still air "
           "about 10, forced air about 100, water quench about 1e3-1e4)",
           film_coefficient);
  }
};

}  // namespace rkpm::thermal
