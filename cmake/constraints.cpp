// The velocity constraints' projector (Eigen's sparse assembly, factorization and solve),
// compiled once for the project's own programs (target rkpm_instances,
// cmake/rkpm_instances.cmake; include/rkpm/solver/constraints.hpp).
#include <rkpm/solver/constraints.hpp>

namespace rkpm {
template class basic_constraint_projector<constraint_factor>;
}  // namespace rkpm
