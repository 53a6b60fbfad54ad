// The dispatch table of the taylor_bar case, compiled on its own so the cases build in parallel.
#include "cases/taylor_bar.hpp"
#include "dispatch.hpp"

namespace rkpm::runner {
template run_outcome run_case<cases::taylor_bar>(const run_request& r);
}  // namespace rkpm::runner
