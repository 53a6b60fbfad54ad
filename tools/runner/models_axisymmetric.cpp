// The discrete models of every named kernel, correction and rule in axisymmetric geometry
// (model_builder.hpp), shared by the cases of that geometry.
#include <rkpm/geometry/axisymmetric.hpp>

#include "model_builder_impl.hpp"

namespace rkpm::runner {
template discrete_model build_model<geometry::axisymmetric>(std::string_view, std::string_view, std::string_view,
                                                   particle_set<2>, background_mesh, double);
}  // namespace rkpm::runner
