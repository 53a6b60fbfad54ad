#pragma once
// run_file_case<Geometry, Material>: a case file of one geometry, run with the runner's solver
// type of that geometry and case-file material (dispatch.hpp).

#include "dispatch.hpp"
#include "file_case.hpp"
#include "run_case_file.hpp"

namespace rkpm::runner {

template <class Geometry, class Material>
run_outcome run_file_case(const run_request& r, const case_file::case_description& c,
                          const std::optional<restart_point>& restart) {
  return run_with<file_case<Geometry, Material>>(r, c, restart);
}

}  // namespace rkpm::runner
