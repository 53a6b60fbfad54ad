#pragma once
// The runner's set-up in parts on several processes (ranks.hpp; docs/method.md section 9.8,
// "The runner on P processes"): whether a run can do without any whole model, and the layout
// of its model (parallel/rank_setup.hpp) for the method named at run time; what rank 0 gathers
// or reduces of such a run in place of a whole solver (each rank's counts, the points' extremes,
// the positions of a figure shape, the end-state figures' fields).
//
// A run is set up in parts, with no whole solver on rank 0, when
//   - the library can set its model up in parts: a cell rule without VCI or SCNI, no cracks in
//     the cells (parallel::make_model_layout; several bodies each with its own shape functions,
//     their surfaces in the shared region when the contact reads them);
//   - its history rows reduce over the ranks (row_reduction.hpp), so that no row needs the state
//     gathered;
//   - nothing reads the whole state that the ranks do not reduce: no cracks that can grow (their
//     snapshots are written whole on rank 0, and a cut rebuilds the whole model), no re-referencing (each
//     re-reference builds the whole model on every rank, parallel/distributed_rereference.hpp,
//     and summary.json's re-reference times are the whole solver's), no mass scaling (the mass
//     added per body is a sum in particle order), no caller's hooks (particle_state_of).
// Every other run keeps the whole model on every rank, METIS's partition and rank 0's whole
// solver (set_up_in_parts_refusal names why).

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <mpi.h>

#include <rkpm/geometry/axisymmetric.hpp>
#include <rkpm/geometry/plane_strain.hpp>
#include <rkpm/io/solver_output.hpp>
#include <rkpm/parallel/communicator.hpp>
#include <rkpm/parallel/distributed_solver.hpp>
#include <rkpm/parallel/gather.hpp>
#include <rkpm/parallel/rank_setup.hpp>
#include <rkpm/solver/fields.hpp>
#include <rkpm/solver/method_names.hpp>

#include "final_figures.hpp"

namespace rkpm::runner {

// What the run asks for beyond its model.
struct part_setup_request {
  bool rows_reduce = false;  // the case's rows reduce over the ranks (row_reduction_of)
  bool rereference = false;
  bool cracks = false;       // a material opens cracks (its snapshots are written whole on rank 0)
  bool mass_scaling = false;
  bool hooks = false;        // a caller's observe or keep_final_state (run_hooks.hpp)
  bool plots = false;        // the end-state figures are drawn (their fields gathered on rank 0)
};

// Why the run cannot be set up in parts without a whole solver (empty: it can). Every rank
// answers alike: the problem and method are the same on each.
std::string set_up_in_parts_refusal(const method_names& m, const background_mesh& mesh, const part_setup_request& r);

// The layout of make_model<G>(m, particles, mesh, max_condition)'s model, for a method the
// refusal above accepts (part_setup.cpp: one instantiation per geometry for the whole runner).
template <Geometry G>
parallel::model_layout make_layout(const method_names& m, particle_set<2> particles, background_mesh mesh,
                                   double max_condition);

extern template parallel::model_layout make_layout<geometry::plane_strain>(const method_names&, particle_set<2>,
                                                                           background_mesh, double);
extern template parallel::model_layout make_layout<geometry::axisymmetric>(const method_names&, particle_set<2>,
                                                                           background_mesh, double);

// Collective: each rank's owned particles and ghosts, on rank 0 (summary.json's
// "local_particles"; empty elsewhere).
inline std::vector<std::pair<index_t, index_t>> gather_local_counts(parallel::communicator& comm,
                                                                    const parallel::halo_plan& plan) {
  const long long mine[2] = {static_cast<long long>(plan.owned.size()), static_cast<long long>(plan.ghosts.size())};
  std::vector<long long> all(2 * static_cast<std::size_t>(comm.size()));
  MPI_Gather(mine, 2, MPI_LONG_LONG, all.data(), 2, MPI_LONG_LONG, 0, comm.get());
  std::vector<std::pair<index_t, index_t>> out;
  if (comm.rank() == 0)
    for (int r = 0; r < comm.size(); ++r) out.emplace_back(all[2 * r], all[2 * r + 1]);
  return out;
}

// Collective: io::state_summary of the whole model from the ranks' parts, on rank 0: each
// output field's largest over a part's points (its redundant points hold their owners' states;
// a maximum in any order is the same), the failed fraction from the counts over the owned points
// (integers, exact), divided as one process divides them.
template <class Solver>
std::vector<std::pair<std::string, double>> reduced_state_summary(parallel::communicator& comm, const Solver& part) {
  using state_type = typename Solver::state_type;
  constexpr double none = -std::numeric_limits<double>::infinity();
  std::vector<std::string> names;
  std::vector<double> largest;
  if constexpr (ListsOutputFields<state_type>)
    for (const auto& [name, member] : state_type::output_fields()) {
      const double v = io::largest_state_field(part, name, [](std::size_t) { return true; });
      names.emplace_back(name);
      largest.push_back(std::isnan(v) ? none : v);
    }
  std::vector<double> all(largest.size(), none);
  MPI_Reduce(largest.data(), all.data(), static_cast<int>(largest.size()), MPI_DOUBLE, MPI_MAX, 0, comm.get());
  double counts[2] = {0.0, 0.0}, total[2] = {0.0, 0.0};  // the owned points, those failed
  if constexpr (FailingState<state_type>)
    for_each_owned_point(part.model(), [&](index_t q) {
      counts[0] += 1.0;
      counts[1] += part.point_states()[q].failed() ? 1.0 : 0.0;
    });
  MPI_Reduce(counts, total, 2, MPI_DOUBLE, MPI_SUM, 0, comm.get());
  std::vector<std::pair<std::string, double>> out;
  if (comm.rank() != 0) return out;
  for (std::size_t k = 0; k < names.size(); ++k)
    if (all[k] != none) out.emplace_back("max_" + names[k], all[k]);
  if constexpr (FailingState<state_type>)
    if (!out.empty()) out.emplace_back("failed_fraction", total[0] > 0.0 ? total[1] / total[0] : 0.0);
  return out;
}

// Collective: every owned particle's current position on rank 0, in the whole model's order
// (a figure shape's; empty elsewhere), from the ghosts' coefficients as their owners have them
// (as the snapshot pieces take them).
template <class Solver>
std::vector<vec2> gathered_positions(parallel::communicator& comm, parallel::distributed_solver<Solver>& run) {
  const Solver& part = run.solver();
  std::vector<vec2> d = part.coefficients();
  run.group().forward(d);
  return parallel::gather_owned(comm, run.plan(), positions_at_particles(part.model(), d));
}

// Collective: end_state_of(part) for every particle on rank 0 (none elsewhere): the positions,
// and the projections, right at each part's owned particles.
template <class Solver>
std::optional<end_state_fields> gathered_end_state(parallel::communicator& comm,
                                                   parallel::distributed_solver<Solver>& run) {
  end_state_fields f = end_state_of(run.solver());
  std::vector<vec2> pairs(f.plastic_strain.size());
  for (std::size_t i = 0; i < pairs.size(); ++i)
    pairs[i] = vec2(f.plastic_strain[i], f.temperature.empty() ? std::nan("") : f.temperature[i]);
  f.x = gathered_positions(comm, run);
  pairs = parallel::gather_owned(comm, run.plan(), pairs);
  if (comm.rank() != 0) return std::nullopt;
  f.plastic_strain.clear();
  for (const vec2& p : pairs) f.plastic_strain.push_back(p[0]);
  if (!f.temperature.empty()) {
    f.temperature.clear();
    for (const vec2& p : pairs) f.temperature.push_back(p[1]);
  }
  return f;
}

}  // namespace rkpm::runner
