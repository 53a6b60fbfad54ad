#pragma once
// Whether the loops of the execution layer (core/execution.hpp, core/block_sums.hpp) run on one
// thread: then they run as plain loops, in the order one OpenMP thread would take, without
// entering a parallel region (a one-thread step otherwise spends a few per cent of its time in
// libgomp's scheduling and barriers: docs/performance.md).

#ifdef _OPENMP
#include <omp.h>
#endif

namespace rkpm::exec {

inline bool single_thread() {
#ifdef _OPENMP
  return omp_get_max_threads() == 1 || omp_in_parallel();
#else
  return true;
#endif
}

}  // namespace rkpm::exec
