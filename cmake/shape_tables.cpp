// build_shape_table for the shipped kernels and corrections, compiled once for the project's
// own programs (target rkpm_instances, cmake/rkpm_instances.cmake); see
// include/rkpm/discretization/shape_table_instances.hpp.
#define RKPM_INSTANTIATE_SHAPE_TABLES
#include <rkpm/discretization/shape_table_instances.hpp>
