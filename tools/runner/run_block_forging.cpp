// The run of the block_forging case: its solver instantiated once (grouped with the other plane-strain
// units at build time, CMakeLists.txt).
#include "cases/block_forging.hpp"
#include "dispatch.hpp"

namespace rkpm::runner {
template run_outcome run_case<cases::block_forging>(const run_request& r);
}  // namespace rkpm::runner
