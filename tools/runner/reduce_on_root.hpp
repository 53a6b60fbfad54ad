#pragma once
// reduce_on_root(comm, reduction): a history row's reduction (row_reduction.hpp) combined over
// the ranks on rank 0 (ranks.hpp): the maxima by MPI_MAX, the exact sums by an MPI_SUM of their
// limbs (exact, in any order), the nearest values by the smallest (distance, global index), a
// choice (MPI_Op_create, commutative: the smallest of a set does not depend on the order it is
// taken in). So the row has one process's bits. Collective; rank 0's result is the combined one.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include <mpi.h>

#include <rkpm/core/exact_sum.hpp>
#include <rkpm/parallel/communicator.hpp>

#include "row_reduction.hpp"

namespace rkpm::runner {

namespace detail {

static_assert(sizeof(nearest_value) == 3 * sizeof(double), "nearest_value is sent as three doubles");

// The MPI_Op of the nearest values: each of `in` that comes before the one of `inout` replaces it.
inline void keep_nearest(void* in, void* inout, int* length, MPI_Datatype*) {
  const auto* a = static_cast<const nearest_value*>(in);
  auto* b = static_cast<nearest_value*>(inout);
  for (int k = 0; k < *length; ++k)
    if (a[k].before(b[k])) b[k] = a[k];
}

}  // namespace detail

inline row_reduction reduce_on_root(parallel::communicator& comm, row_reduction r) {
  const bool root = comm.rank() == 0;
  MPI_Reduce(root ? MPI_IN_PLACE : r.maxima.data(), r.maxima.data(), static_cast<int>(r.maxima.size()), MPI_DOUBLE,
             MPI_MAX, 0, comm.get());
  if (!r.nearest.empty()) {
    MPI_Datatype triple = MPI_DATATYPE_NULL;
    MPI_Type_contiguous(3, MPI_DOUBLE, &triple);
    MPI_Type_commit(&triple);
    MPI_Op nearest = MPI_OP_NULL;
    MPI_Op_create(&detail::keep_nearest, 1, &nearest);
    MPI_Reduce(root ? MPI_IN_PLACE : r.nearest.data(), r.nearest.data(), static_cast<int>(r.nearest.size()), triple,
               nearest, 0, comm.get());
    MPI_Op_free(&nearest);
    MPI_Type_free(&triple);
  }
  if (r.sums.empty()) return r;
  constexpr int L = exact_sum::limb_count;
  std::vector<std::int64_t> limbs(r.sums.size() * L);
  std::vector<double> special(r.sums.size());
  for (std::size_t k = 0; k < r.sums.size(); ++k) {
    r.sums[k].normalize();
    std::copy_n(r.sums[k].limbs().begin(), L, limbs.begin() + static_cast<std::ptrdiff_t>(k * L));
    special[k] = r.sums[k].special();
  }
  MPI_Reduce(root ? MPI_IN_PLACE : limbs.data(), limbs.data(), static_cast<int>(limbs.size()), MPI_INT64_T, MPI_SUM, 0,
             comm.get());
  MPI_Reduce(root ? MPI_IN_PLACE : special.data(), special.data(), static_cast<int>(special.size()), MPI_DOUBLE,
             MPI_SUM, 0, comm.get());
  for (std::size_t k = 0; k < r.sums.size(); ++k) {
    std::copy_n(limbs.begin() + static_cast<std::ptrdiff_t>(k * L), L, r.sums[k].limbs().begin());
    r.sums[k].special() = special[k];
    r.sums[k].normalize();
  }
  return r;
}

}  // namespace rkpm::runner
