#pragma once
// `rkpm_run FILE.json`: a problem from a case file (file_case.hpp), run with the same dispatch
// table and simulate() as the typed cases. run_case_file (run_case_file.cpp) reads the file, or
// the document a checkpoint kept, and hands it to run_file_case<Geometry, Material>, which is
// compiled once per geometry and case-file material (case_file/case_material.hpp) in
// run_file_GEOMETRY[_johnson_cook].cpp (table: file_case_dispatch.hpp), so that they build in
// parallel.

#include <optional>

#include "case_file/case_description.hpp"
#include "outcome.hpp"
#include "request.hpp"
#include "run_record.hpp"

namespace rkpm::runner {

run_outcome run_case_file(const run_request& r);

template <class Geometry, class Material>
run_outcome run_file_case(const run_request& r, const case_file::case_description& c,
                          const std::optional<restart_point>& restart);

}  // namespace rkpm::runner
