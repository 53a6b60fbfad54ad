// The discrete models of every named kernel, correction and rule in axisymmetric geometry
// (rkpm/solver/make_model.hpp), shared by the cases of that geometry (models.hpp).
#include "models.hpp"

namespace rkpm {
template discrete_model make_model<geometry::axisymmetric>(const method_names&, particle_set<2>, background_mesh,
                                                           double);
}  // namespace rkpm
