// The case files' run-time material in axisymmetry, compiled once for the tests
// (support/case_file_solver_instance.hpp).
#define RKPM_INSTANTIATE_CASE_FILE_SOLVER
#include "support/case_file_solver_instance.hpp"
