#pragma once
// What a run's output shows, taken from the solver in one place, so that every consumer (the
// runner's history.csv, summary.json and VTK snapshots, the tutorials, the tests) writes the
// same thing and a new term or field reaches all of them with no edit of theirs:
//   energy_terms(e)      the ledger's terms (docs/method.md section 7) by output name; with
//                        them the printed numbers close the balance to the printed error;
//   snapshot_fields(s)   the particle fields of a snapshot: displacement, velocity, Cauchy
//                        stress, equivalent plastic strain, det F, and every extra double a
//                        material state lists in `output_fields()` (temperature, damage, ...)
//                        that is not NaN at every point (a state a material leaves unused; on
//                        a part of a run on several processes, at every point of the run);
//                        with field_arrays::deferred, each computed only when a writer asks,
//                        and the vectors and the stress made piecewise as they are written;
//   snapshot_cells(s)    (or of a model) the cells of a snapshot: the model's background cells as quads when the
//                        particles are their nodes (grids, Gmsh bodies), else a vertex per
//                        particle (io/vtu_cells.hpp); the same for every snapshot of a run;
//                        snapshot_cell_layout(s) the same entry by entry, snapshot_points(s)
//                        the current positions piecewise (a snapshot that holds neither);
//   snapshot_tools(s)    the rigid tools' vertices at the solver's time, one <FieldData> array
//                        "tool:NAME" each, for a viewer to draw them with the body;
//   largest_state_field(s, name, in), failed_fraction(s, in)
//                        the largest value of such a field over the points `in` selects, and
//                        the fraction of them that have failed (a state with `failed()`);
//   state_summary(s)     both over every point, by output name ("max_temperature_K",
//                        "max_damage", "failed_fraction"), for a run's summary.
//   fragment_terms(s)    the pieces cracks have made, "fragments" and "largest_fragment_mass_kg"
//                        (solver/crack_growth.hpp), when the solver's cracks can grow; none
//                        otherwise (a history's columns stay as they were).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <memory>
#include <limits>
#include <string>
#include <utility>
#include <string_view>
#include <type_traits>
#include <vector>

#include <Eigen/Core>

#include <rkpm/concepts/material.hpp>
#include <rkpm/core/process_group.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/discretization/body_partition.hpp>
#include <rkpm/io/vtk.hpp>
#include <rkpm/solver/energy.hpp>
#include <rkpm/solver/fields.hpp>

namespace rkpm::io {

struct named_value {
  std::string_view name;
  double value;
};

// The ledger by output name (J per unit thickness in plane strain, J per radian in
// axisymmetric geometry): kinetic + internal - initial_kinetic - external - contact - constraint
// is the imbalance, and balance_error times largest_term_J bounds its largest value over the run.
// `remap`: with the remap term of a re-referenced run (docs/method.md section 5.8) after the constraints'.
inline std::vector<named_value> energy_terms(const energy_balance& e, bool remap = false) {
  std::vector<named_value> terms{{"kinetic_J", e.kinetic},
                                 {"internal_J", e.internal},
                                 {"plastic_J", e.plastic},
                                 {"contact_J", e.contact},
                                 {"external_J", e.external},
                                 {"constraint_J", e.constraint}};
  if (remap) terms.push_back({"remap_J", e.remap});
  terms.insert(terms.end(), {{"initial_kinetic_J", e.initial_kinetic},
                             {"largest_term_J", e.largest_term},
                             {"balance_error", e.balance_error()}});
  return terms;
}

// When a snapshot's arrays are computed: now (a point_data the caller reads), or deferred to
// the writer (io/vtk.hpp), one at a time, for a snapshot written at once from a solver that
// outlives the write.
enum class field_arrays { now, deferred };

// The RK coefficients of displacement and velocity that a snapshot's particle values
// interpolate: the solver's (null), or copies (a part of a run on several processes, its
// ghosts' values refreshed from their owners: parallel/snapshot_pieces.hpp).
struct snapshot_coefficients {
  const std::vector<vec2>* d = nullptr;
  const std::vector<vec2>* v = nullptr;
};

namespace detail {

// Particle values of the RK coefficients c, u(X_I) = sum_J N_J(X_I) c_J (plus X_I: the current
// positions; `initial`, a re-referenced run's initial positions: plus X_I - X_I^0, the displacement
// since the start), as rows (x, y, 0) made piecewise: the arithmetic of values_at_particles and
// positions_at_particles (solver/fields.hpp) and point_data::flat, particle by particle.
inline std::function<point_data::filler()> particle_vectors(const discrete_model& m, const std::vector<vec2>& c,
                                                           bool plus_position,
                                                           const std::vector<vec2>* initial = nullptr) {
  return [&m, &c, plus_position, initial] {
    return point_data::filler([&m, &c, plus_position, initial](std::size_t first, std::size_t n, double* out) {
      index_t particle = -1;
      vec2 u = vec2::Zero();
      for (std::size_t k = 0; k < n; ++k) {
        const auto I = static_cast<index_t>((first + k) / 3);
        if (I != particle) {
          u = m.at_particles.interpolate(I, c);
          if (plus_position) u += m.particles.position[I];
          if (initial) u += m.particles.position[I] - (*initial)[I];
          particle = I;
        }
        const std::size_t component = (first + k) % 3;
        out[k] = component < 2 ? u[static_cast<index_t>(component)] : 0.0;
      }
    });
  };
}

// The Cauchy stress at the particles (the lumped projection of solver/fields.hpp) as row-major
// 3 x 3 rows, made piecewise. A 2D body's stress has no out-of-plane shear, so only xx, xy, yx,
// yy and zz are projected and held (41 MB at 10^6 particles instead of 74); the others are the
// projection of zeros, 0 / V_I, as the 9-component projection gives them. A material that
// gives an out-of-plane shear anyway gets the 9-component projection.
template <class Solver>
point_data::filler stress_rows(const Solver& s) {
  static constexpr std::array<int, 9> compact{0, 1, -1, 2, 3, -1, -1, -1, 4};  // row-major entry -> held column
  using tensor = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;
  const discrete_model& m = s.model();
  bool in_plane = true;
  auto held = std::make_shared<std::vector<double>>(project_to_particles_flat<5>(m, [&](index_t q) {
    const tensor sigma = s.point_cauchy_stress(q);
    in_plane = in_plane && sigma(0, 2) == 0.0 && sigma(1, 2) == 0.0 && sigma(2, 0) == 0.0 && sigma(2, 1) == 0.0;
    return Eigen::Matrix<double, 5, 1>(sigma(0, 0), sigma(0, 1), sigma(1, 0), sigma(1, 1), sigma(2, 2));
  }));
  if (!in_plane) {
    held = std::make_shared<std::vector<double>>(project_to_particles_flat<9>(m, [&](index_t q) {
      const tensor sigma = s.point_cauchy_stress(q);
      return Eigen::Matrix<double, 9, 1>(Eigen::Map<const Eigen::Matrix<double, 9, 1>>(sigma.data()));
    }));
    return [held](std::size_t first, std::size_t n, double* out) { std::copy_n(held->data() + first, n, out); };
  }
  return [held, &m](std::size_t first, std::size_t n, double* out) {
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t I = (first + k) / 9;
      const int column = compact[(first + k) % 9];
      out[k] = column >= 0 ? (*held)[5 * I + static_cast<std::size_t>(column)] : 0.0 / m.lumped_volume[I];
    }
  };
}

}  // namespace detail

template <class Solver>
point_data snapshot_fields(const Solver& s, field_arrays when = field_arrays::now,
                           snapshot_coefficients coefficients = {}) {
  using state_type = typename Solver::state_type;
  point_data data;
  const auto add = [&](std::string name, int components, point_data::producer produce) {
    if (when == field_arrays::deferred) data.add_deferred(std::move(name), components, std::move(produce));
    else data.add_values(std::move(name), components, produce());
  };
  const std::vector<vec2>& d = coefficients.d ? *coefficients.d : s.coefficients();
  const std::vector<vec2>& v = coefficients.v ? *coefficients.v : s.coefficient_velocities();
  const auto add_filled = [&](std::string name, int components, std::function<point_data::filler()> prepare) {
    const auto count = static_cast<std::size_t>(components) * static_cast<std::size_t>(s.model().particle_count());
    if (when == field_arrays::deferred) data.add_filled(std::move(name), components, count, std::move(prepare));
    else data.add_values(std::move(name), components, filled_values(count, prepare));
  };
  const std::vector<vec2>* initial = nullptr;  // a re-referenced run's: displacements since the start
  if constexpr (requires { s.rereferences(); })
    if (s.rereferences() > 0) initial = &s.initial_positions();
  add_filled("displacement", 3, detail::particle_vectors(s.model(), d, false, initial));
  add_filled("velocity", 3, detail::particle_vectors(s.model(), v, false));
  add_filled("stress", 9, [&s] { return detail::stress_rows(s); });
  add("equivalent_plastic_strain", 1, [&s] {
    return s.template project_to_particles<double>([&](index_t q) {
      return static_cast<double>(s.point_states()[q].equivalent_plastic_strain);
    });
  });
  add("det_F", 1, [&s] {
    return s.template project_to_particles<double>([&](index_t q) { return s.point_det_F(q); });
  });
  if constexpr (ListsOutputFields<state_type>)
    for (const auto& [name, member] : state_type::output_fields()) {
      const auto& states = s.point_states();
      const bool unused =
          std::all_of(states.begin(), states.end(), [m = member](const state_type& st) { return std::isnan(st.*m); });
      // A part of a run on several processes lists what the whole lists (parallel/snapshot_pieces.hpp).
      process_group* const group = s.model().own.group;
      if (group ? group->max(unused ? 0.0 : 1.0) == 0.0 : unused) continue;
      add(std::string(name), 1, [&s, m = member] {
        return s.template project_to_particles<double>(
            [&](index_t q) { return static_cast<double>(s.point_states()[q].*m); });
      });
    }
  return data;
}

// The snapshot's cells entry by entry (io/vtu_cells.hpp), and as arrays: the model's background
// cells as quads when the particles are their nodes, else a vertex per particle.
inline cell_layout snapshot_cell_layout(const discrete_model& m) {
  const auto n = static_cast<std::size_t>(m.particle_count());
  const bool nodes = m.bodies.found() ? m.bodies.nodes_are_particles()
                                      : rkpm::nodes_are_particles(m.particles.position, m.mesh);
  return nodes ? cell_layout::quads(m.mesh, n) : cell_layout::vertices(n);
}
template <class Solver>
cell_layout snapshot_cell_layout(const Solver& s) {
  return snapshot_cell_layout(s.model());
}
inline vtu_cells snapshot_cells(const discrete_model& m) { return cells_of(snapshot_cell_layout(m)); }
template <class Solver>
vtu_cells snapshot_cells(const Solver& s) {
  return snapshot_cells(s.model());
}
// The current positions as the rows (x, y, 0) of the snapshot's points, made piecewise
// (write_vtu's form that holds neither them nor the cells).
template <class Solver>
std::function<point_data::filler()> snapshot_points(const Solver& s) {
  return detail::particle_vectors(s.model(), s.coefficients(), true);
}

template <class Solver>
point_data snapshot_tools(const Solver& s) {
  point_data tools;
  if constexpr (requires { s.contact().tools(); })
    for (const auto& tool : s.contact().tools()) tools.add("tool:" + tool.name(), tool.vertices(s.time()));
  return tools;
}

// The largest value of the output field `name` over the points q with in(q) (NaN values left
// out); NaN when there is none (no such field, or NaN at every point chosen).
template <class Solver, class Select>
double largest_state_field(const Solver& s, std::string_view name, Select in) {
  using state_type = typename Solver::state_type;
  double largest = std::numeric_limits<double>::quiet_NaN();
  if constexpr (ListsOutputFields<state_type>)
    for (const auto& [field, member] : state_type::output_fields()) {
      if (field != name) continue;
      const auto& states = s.point_states();
      for (std::size_t q = 0; q < states.size(); ++q) {
        const double v = states[q].*member;
        if (in(q) && !std::isnan(v) && !(v <= largest)) largest = v;
      }
    }
  return largest;
}

// The fraction of the points q with in(q) whose state has failed (0 for a state that cannot).
template <class Solver, class Select>
double failed_fraction(const Solver& s, Select in) {
  std::size_t chosen = 0, failed = 0;
  const auto& states = s.point_states();
  for (std::size_t q = 0; q < states.size(); ++q) {
    if (!in(q)) continue;
    ++chosen;
    if constexpr (FailingState<std::remove_cvref_t<decltype(states[q])>>) failed += states[q].failed() ? 1 : 0;
  }
  return chosen > 0 ? static_cast<double>(failed) / static_cast<double>(chosen) : 0.0;
}

// Over every point: "max_" + each output field not NaN everywhere, and "failed_fraction" when the
// state can fail.
template <class Solver>
std::vector<std::pair<std::string, double>> state_summary(const Solver& s) {
  using state_type = typename Solver::state_type;
  std::vector<std::pair<std::string, double>> out;
  const auto every = [](std::size_t) { return true; };
  if constexpr (ListsOutputFields<state_type>)
    for (const auto& [name, member] : state_type::output_fields()) {
      const double v = largest_state_field(s, name, every);
      if (!std::isnan(v)) out.emplace_back("max_" + std::string(name), v);
    }
  if constexpr (FailingState<state_type>)
    if (!out.empty()) out.emplace_back("failed_fraction", failed_fraction(s, every));
  return out;
}

// The pieces and the largest one's mass (kg per metre of depth in plane strain, kg per radian in
// axisymmetric geometry, as the masses) when s.cracks_can_grow(), else nothing.
template <class Solver>
std::vector<named_value> fragment_terms(const Solver& s) {
  if constexpr (requires { s.cracks_can_grow(); }) {
    if (!s.cracks_can_grow()) return {};
    const auto pieces = s.fragments();
    return {{"fragments", static_cast<double>(pieces.pieces)}, {"largest_fragment_mass_kg", pieces.largest_mass}};
  } else {
    return {};
  }
}

}  // namespace rkpm::io
