#pragma once
// build_model<Geometry>(kernel, correction, rule, particles, mesh): the discrete model for the
// policies named at run time. Kernel, correction and quadrature rule change the tables of the
// model (shape functions, points, weights, VCI test gradients) but not the solver's type, so
// the runner chooses them here, at run time, and compiles the time loop once per geometry,
// material and enforcement. The builders of all named combinations are compiled in one file
// per geometry (models_GEOMETRY.cpp) and shared by every case of that geometry.

#include <string_view>

#include <rkpm/discretization/background_mesh.hpp>
#include <rkpm/discretization/particle_set.hpp>
#include <rkpm/solver/discrete_model.hpp>

namespace rkpm::runner {

// Refuses, in one line, a name that is not one of methods.hpp's lists.
template <class Geometry>
discrete_model build_model(std::string_view kernel, std::string_view correction, std::string_view rule,
                           particle_set<2> particles, background_mesh mesh, double max_condition);

}  // namespace rkpm::runner
