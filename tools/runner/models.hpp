#pragma once
// The run-time model builder of the library (rkpm/solver/make_model.hpp) is compiled once per
// geometry, in models_GEOMETRY.cpp, and shared by every case and case file of that geometry;
// the files that build solvers see only these declarations.

#include <rkpm/geometry/axisymmetric.hpp>
#include <rkpm/geometry/plane_strain.hpp>
#include <rkpm/solver/make_model.hpp>

namespace rkpm {
extern template discrete_model make_model<geometry::axisymmetric>(const method_names&, particle_set<2>,
                                                                  background_mesh, double);
extern template discrete_model make_model<geometry::plane_strain>(const method_names&, particle_set<2>,
                                                                  background_mesh, double);
}  // namespace rkpm
