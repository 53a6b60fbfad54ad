// The case files in axisymmetric geometry (run_file_case.hpp), compiled on their own so that the
// dispatch tables build in parallel.
#include "run_file_case.hpp"

namespace rkpm::runner {
template run_outcome run_file_case<geometry::axisymmetric>(const run_request&, const case_file::case_description&,
                                                 const std::optional<restart_point>&);
}  // namespace rkpm::runner
