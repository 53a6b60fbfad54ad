// The run of the wheel_forging case, compiled on its own so the cases build in parallel.
#include "cases/wheel_forging.hpp"
#include "dispatch.hpp"

namespace rkpm::runner {
template run_outcome run_case<cases::wheel_forging>(const run_request& r);
}  // namespace rkpm::runner
