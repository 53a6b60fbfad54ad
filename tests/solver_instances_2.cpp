// Part 2 of the solvers the tests share, compiled once (include/rkpm/solver/solver_instances.hpp),
// and the case files' run-time material in axisymmetry (support/case_file_solver_instance.hpp).
#define RKPM_INSTANTIATE_SOLVERS 2
#include <rkpm/solver/solver_instances.hpp>

#include "support/case_file_solver_instance.hpp"
