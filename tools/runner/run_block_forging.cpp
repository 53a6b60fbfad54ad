// The run of the block_forging case, compiled on its own so the cases build in parallel.
#include "cases/block_forging.hpp"
#include "dispatch.hpp"

namespace rkpm::runner {
template run_outcome run_case<cases::block_forging>(const run_request& r);
}  // namespace rkpm::runner
