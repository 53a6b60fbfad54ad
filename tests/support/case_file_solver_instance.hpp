#pragma once
// explicit_solver for the case files' run-time material (runner::case_file::material_type: J2,
// Johnson-Cook or Zerilli-Armstrong chosen per body) in axisymmetry with the paper's contact,
// compiled once in rkpm_test_solvers (tests/case_file_solver_instance.cpp includes this header
// after defining RKPM_INSTANTIATE_CASE_FILE_SOLVER) and declared extern in the test files that run it
// (unit/case_file/measures.cpp, cases/taylor_cylinders.cpp): two programs use it, and the
// solver's set-up and step are about 20 s of compile each time. The library's own list
// (include/rkpm/solver/solver_instances.hpp) cannot name a type of the runner.

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/geometry/axisymmetric.hpp>
#include <rkpm/solver/explicit_solver.hpp>

#include "tools/runner/case_file/case_material.hpp"

namespace rkpm::test {
using axisymmetric_file_contact =
    contact::particle_to_segment<contact::enforcement::paper, contact::friction::coulomb>;
}  // namespace rkpm::test

#if defined(RKPM_INSTANTIATE_CASE_FILE_SOLVER)
template class rkpm::explicit_solver<rkpm::geometry::axisymmetric, rkpm::runner::case_file::material_type,
                                     rkpm::test::axisymmetric_file_contact>;
#elif defined(RKPM_EXTERN_SOLVERS)
extern template class rkpm::explicit_solver<rkpm::geometry::axisymmetric, rkpm::runner::case_file::material_type,
                                            rkpm::test::axisymmetric_file_contact>;
#endif
