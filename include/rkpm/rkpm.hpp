#pragma once
// Umbrella header: everything a user needs to build and run an rkpm simulation.

#include <rkpm/correction/polynomial_bases.hpp>
#include <rkpm/approximation/rk_shape_functions.hpp>
#include <rkpm/contact/enforcement.hpp>
#include <rkpm/contact/friction.hpp>
#include <rkpm/contact/none.hpp>
#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/contact/rigid_tool.hpp>
#include <rkpm/discretization/background_mesh.hpp>
#include <rkpm/discretization/neighbor_search.hpp>
#include <rkpm/discretization/particle_set.hpp>
#include <rkpm/discretization/quadrature_points.hpp>
#include <rkpm/quadrature/cell_rules.hpp>
#include <rkpm/discretization/shape_table.hpp>
#include <rkpm/geometry/axisymmetric.hpp>
#include <rkpm/geometry/plane_strain.hpp>
#include <rkpm/kernel/cubic_spline.hpp>
#include <rkpm/kernel/quartic_spline.hpp>
#include <rkpm/material/elastic.hpp>
#include <rkpm/material/j2_plasticity.hpp>
#include <rkpm/solver/checkpoint.hpp>
#include <rkpm/solver/config.hpp>
#include <rkpm/solver/make_solver.hpp>
