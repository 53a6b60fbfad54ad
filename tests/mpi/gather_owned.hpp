#pragma once
// The owned values of every rank, in global particle order, on rank 0 (empty elsewhere): what
// the decomposition tests compare with one process's result.

#include <mpi.h>

#include <cstring>
#include <limits>
#include <vector>

#include <rkpm/core/types.hpp>
#include <rkpm/parallel/communicator.hpp>
#include <rkpm/parallel/halo.hpp>

namespace rkpm::test {

inline std::vector<vec2> gather_owned(parallel::communicator& world, const parallel::halo_plan& plan,
                                      const std::vector<vec2>& f) {
  const int owned = static_cast<int>(plan.owned.size());
  std::vector<double> values(2 * owned);
  for (int i = 0; i < owned; ++i) std::memcpy(values.data() + 2 * i, f[i].data(), 2 * sizeof(double));
  std::vector<int> counts(world.size()), displacements(world.size(), 0);
  MPI_Gather(&owned, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, world.get());
  for (int r = 1; r < world.size(); ++r) displacements[r] = displacements[r - 1] + counts[r - 1];
  std::vector<stored_index> ids(world.rank() == 0 ? plan.global_particles : 0);
  MPI_Gatherv(plan.owned.data(), owned, MPI_INT, ids.data(), counts.data(), displacements.data(), MPI_INT, 0, world.get());
  for (int r = 0; r < world.size(); ++r) {
    counts[r] *= 2;
    displacements[r] *= 2;
  }
  std::vector<double> all(world.rank() == 0 ? 2 * plan.global_particles : 0);
  MPI_Gatherv(values.data(), 2 * owned, MPI_DOUBLE, all.data(), counts.data(), displacements.data(), MPI_DOUBLE, 0,
              world.get());
  std::vector<vec2> out(world.rank() == 0 ? plan.global_particles : 0,
                        vec2::Constant(std::numeric_limits<double>::quiet_NaN()));
  for (std::size_t k = 0; k < ids.size(); ++k) std::memcpy(out[ids[k]].data(), all.data() + 2 * k, 2 * sizeof(double));
  return out;
}

}  // namespace rkpm::test
