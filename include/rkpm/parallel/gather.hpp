#pragma once
// gather_owned: every rank's owned values of a per-particle field, in the whole model's particle
// order, on rank 0 (empty on the others): what a program on P processes writes or measures as
// one process would (tutorials/11_many_processes, the decomposition tests). Collective.

#include <cstring>
#include <limits>
#include <vector>

#include <mpi.h>

#include <rkpm/core/types.hpp>
#include <rkpm/parallel/communicator.hpp>
#include <rkpm/parallel/halo.hpp>

namespace rkpm::parallel {

inline std::vector<vec2> gather_owned(communicator& comm, const halo_plan& plan, const std::vector<vec2>& field) {
  comm.agree();
  const int owned = static_cast<int>(plan.owned.size());
  std::vector<double> values(2 * static_cast<std::size_t>(owned));
  for (int i = 0; i < owned; ++i) std::memcpy(values.data() + 2 * i, field[i].data(), 2 * sizeof(double));
  std::vector<int> counts(comm.size()), displacements(comm.size(), 0);
  MPI_Gather(&owned, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm.get());
  for (int r = 1; r < comm.size(); ++r) displacements[r] = displacements[r - 1] + counts[r - 1];
  const bool root = comm.rank() == 0;
  std::vector<stored_index> ids(root ? plan.global_particles : 0);
  MPI_Gatherv(plan.owned.data(), owned, MPI_INT, ids.data(), counts.data(), displacements.data(), MPI_INT, 0,
              comm.get());
  for (int r = 0; r < comm.size(); ++r) {
    counts[r] *= 2;
    displacements[r] *= 2;
  }
  std::vector<double> all(root ? 2 * plan.global_particles : 0);
  MPI_Gatherv(values.data(), 2 * owned, MPI_DOUBLE, all.data(), counts.data(), displacements.data(), MPI_DOUBLE, 0,
              comm.get());
  std::vector<vec2> out(root ? plan.global_particles : 0, vec2::Constant(std::numeric_limits<double>::quiet_NaN()));
  for (std::size_t k = 0; k < ids.size(); ++k) std::memcpy(out[ids[k]].data(), all.data() + 2 * k, 2 * sizeof(double));
  return out;
}

}  // namespace rkpm::parallel
