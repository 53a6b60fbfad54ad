// The discrete models of every named kernel, correction and rule in plane_strain geometry
// (model_builder.hpp), shared by the cases of that geometry.
#include <rkpm/geometry/plane_strain.hpp>

#include "model_builder_impl.hpp"

namespace rkpm::runner {
template discrete_model build_model<geometry::plane_strain>(std::string_view, std::string_view, std::string_view,
                                                   particle_set<2>, background_mesh, double);
}  // namespace rkpm::runner
