// The case files in plane_strain geometry with J2 and elastic bodies (file_case_dispatch.hpp):
// their solver instantiated once (grouped with the other plane-strain units at build time, CMakeLists.txt).
#include "file_case_dispatch.hpp"

namespace rkpm::runner {
template run_outcome run_file_case<geometry::plane_strain, case_file::j2_material>(
    const run_request&, const case_file::case_description&, const std::optional<restart_point>&);
}  // namespace rkpm::runner
