#pragma once
// The owned values of every rank, in global particle order, on rank 0 (empty elsewhere): what
// the decomposition tests compare with one process's result (parallel/gather.hpp).

#include <rkpm/parallel/gather.hpp>

namespace rkpm::test {

using parallel::gather_owned;

}  // namespace rkpm::test
