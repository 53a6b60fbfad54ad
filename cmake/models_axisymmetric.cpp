// The discrete models of every shipped kernel, correction and rule in the axisymmetric geometry, and
// the run-time builder make_model of that geometry, compiled once for the project's own
// programs (target rkpm_instances, cmake/rkpm_instances.cmake; include/rkpm/solver/model_instances.hpp).
#define RKPM_INSTANTIATE_MODELS 2
#include <rkpm/solver/model_instances.hpp>
#include <rkpm/solver/make_model.hpp>

namespace rkpm {
template discrete_model make_model<geometry::axisymmetric>(const method_names&, particle_set<2>, background_mesh, double,
                                                           const quadrature_points*);
}  // namespace rkpm
