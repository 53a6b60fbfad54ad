#pragma once
// What a run's output shows, taken from the solver in one place, so that every consumer (the
// runner's history.csv, summary.json and VTK snapshots, the tutorials, the tests) writes the
// same thing and a new term or field reaches all of them with no edit of theirs:
//   energy_terms(e)      the ledger's terms (docs/method.md section 7) by output name; with
//                        them the printed numbers close the balance to the printed error;
//   snapshot_fields(s)   the particle fields of a snapshot: displacement, velocity, Cauchy
//                        stress, equivalent plastic strain, det F, and every extra double a
//                        material state lists in `output_fields()` (temperature, damage, ...).

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include <rkpm/core/types.hpp>
#include <rkpm/io/vtk.hpp>
#include <rkpm/solver/energy.hpp>

namespace rkpm::io {

struct named_value {
  std::string_view name;
  double value;
};

// The ledger by output name (J per unit thickness in plane strain, J per radian in
// axisymmetric geometry): kinetic + internal - initial_kinetic - external - contact - constraint
// is the imbalance, and balance_error times largest_term_J bounds its largest value over the run.
inline std::array<named_value, 9> energy_terms(const energy_balance& e) {
  return {{{"kinetic_J", e.kinetic},
           {"internal_J", e.internal},
           {"plastic_J", e.plastic},
           {"contact_J", e.contact},
           {"external_J", e.external},
           {"constraint_J", e.constraint},
           {"initial_kinetic_J", e.initial_kinetic},
           {"largest_term_J", e.largest_term},
           {"balance_error", e.balance_error()}}};
}

// Extra per-point scalars a material state lists for output: `static constexpr auto
// output_fields()` returning pairs {name, &state::member}, e.g. {"temperature_K", &s::temperature}.
template <class State>
concept has_output_fields = requires { State::output_fields(); };

template <class Solver>
point_data snapshot_fields(const Solver& s) {
  using state_type = typename Solver::state_type;
  point_data data;
  data.add("displacement", s.particle_displacements());
  data.add("velocity", s.particle_velocities());
  data.add("stress", s.template project_to_particles<mat3>([&](index_t q) { return s.point_cauchy_stress(q); }));
  data.add("equivalent_plastic_strain", s.template project_to_particles<double>([&](index_t q) {
    return static_cast<double>(s.point_states()[q].equivalent_plastic_strain);
  }));
  data.add("det_F", s.template project_to_particles<double>([&](index_t q) { return s.point_det_F(q); }));
  if constexpr (has_output_fields<state_type>)
    for (const auto& [name, member] : state_type::output_fields())
      data.add(std::string(name), s.template project_to_particles<double>([&, m = member](index_t q) {
        return static_cast<double>(s.point_states()[q].*m);
      }));
  return data;
}

}  // namespace rkpm::io
