#pragma once
// run_file_case<Geometry>: the dispatch table of case files of one geometry, from the policies'
// names to the compiled configurations (dispatch.hpp), with case_file::material_type.

#include "dispatch.hpp"
#include "file_case.hpp"
#include "run_case_file.hpp"

namespace rkpm::runner {

template <class Geometry>
run_outcome run_file_case(const run_request& r, const case_file::case_description& c,
                          const std::optional<restart_point>& restart) {
  const auto table = dispatch_table<file_case<Geometry>>();
  const auto it = table.find(r.method_key());
  if (it == table.end()) fail("no compiled configuration for '{}'", r.method_key());
  return it->second(r, c, restart);
}

}  // namespace rkpm::runner
