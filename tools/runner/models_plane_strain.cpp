// The discrete models of every named kernel, correction and rule in plane strain
// (rkpm/solver/make_model.hpp), shared by the cases of that geometry (models.hpp).
#include "models.hpp"

namespace rkpm {
template discrete_model make_model<geometry::plane_strain>(const method_names&, particle_set<2>, background_mesh,
                                                           double);
}  // namespace rkpm
