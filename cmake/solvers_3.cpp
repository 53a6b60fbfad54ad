// Part 3 of the solvers the project's programs share, compiled once (include/rkpm/solver/solver_instances.hpp).
#define RKPM_INSTANTIATE_SOLVERS 3
#include <rkpm/solver/solver_instances.hpp>
