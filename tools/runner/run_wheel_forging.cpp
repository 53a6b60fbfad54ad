// The dispatch table of the wheel_forging case, compiled on its own so the cases build in parallel.
#include "cases/wheel_forging.hpp"
#include "dispatch.hpp"

namespace rkpm::runner {
run_outcome run_wheel_forging(const run_request& r) { return run_case<cases::wheel_forging>(r); }
}  // namespace rkpm::runner
