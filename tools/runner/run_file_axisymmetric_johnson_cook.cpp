// The case files in axisymmetric geometry with a Johnson-Cook body (file_case_dispatch.hpp): their
// solver, with the state Johnson-Cook needs, instantiated once (CMakeLists.txt).
#include "file_case_dispatch.hpp"

namespace rkpm::runner {
template run_outcome run_file_case<geometry::axisymmetric, case_file::material_type>(
    const run_request&, const case_file::case_description&, const std::optional<restart_point>&);
}  // namespace rkpm::runner
