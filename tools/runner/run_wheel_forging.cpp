// The run of the wheel_forging case: its solver instantiated once (grouped with the other axisymmetric
// units at build time, CMakeLists.txt).
#include "cases/wheel_forging.hpp"
#include "dispatch.hpp"

namespace rkpm::runner {
template run_outcome run_case<cases::wheel_forging>(const run_request& r);
}  // namespace rkpm::runner
