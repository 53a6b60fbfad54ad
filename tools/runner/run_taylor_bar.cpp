// The runs of the taylor_bar and rod_on_rod cases (grouped with the other axisymmetric units at
// build time, CMakeLists.txt); the two share this file because they share their solver type
// (axisymmetric, J2 with linear hardening, the runner's contact), which is then instantiated once.
#include "cases/rod_on_rod.hpp"
#include "cases/taylor_bar.hpp"
#include "dispatch.hpp"

namespace rkpm::runner {
template run_outcome run_case<cases::taylor_bar>(const run_request& r);
template run_outcome run_case<cases::rod_on_rod>(const run_request& r);
}  // namespace rkpm::runner
