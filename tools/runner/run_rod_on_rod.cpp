// The dispatch table of the rod_on_rod case, compiled on its own so the cases build in parallel.
#include "cases/rod_on_rod.hpp"
#include "dispatch.hpp"

namespace rkpm::runner {
template run_outcome run_case<cases::rod_on_rod>(const run_request& r);
}  // namespace rkpm::runner
