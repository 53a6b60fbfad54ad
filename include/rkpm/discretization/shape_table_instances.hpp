#pragma once
// build_shape_table for the kernels and corrections rkpm ships, compiled once per program
// instead of once per file. It is the heaviest template the solver instantiates (the RK
// moment matrices and their solves, a third of a runner file's compile), and every file that
// builds a discrete model instantiates it again. A program that wants it once:
//   - compiles one file that defines RKPM_INSTANTIATE_SHAPE_TABLES and includes this header
//     (the explicit instantiation definitions), e.g. the project's cmake/shape_tables.cpp;
//   - defines RKPM_EXTERN_SHAPE_TABLES in every other file (then shape_table.hpp includes this
//     header and declares them extern, so those files only call them).
// Without either macro nothing changes: the header-only library instantiates as usual.

#include <rkpm/correction/polynomial_bases.hpp>
#include <rkpm/discretization/shape_table.hpp>
#include <rkpm/kernel/cubic_spline.hpp>
#include <rkpm/kernel/quartic_spline.hpp>

// With the tables, the shape functions' evaluate() (the moment matrix and its solves), which
// the tests and tutorials also call directly, in 2D and in 1D (tutorial 01's profiles and the
// reproduction tests: each of the four took several seconds of a file's compile, mostly
// Eigen's eigensolver of the moment matrix in check_conditioning).
#if defined(RKPM_INSTANTIATE_SHAPE_TABLES)
#define RKPM_SHAPE_TABLE_INSTANCE(K, C) \
  template class rk_shape_functions<K, C, 1>; \
  template class rk_shape_functions<K, C, 2>; \
  template shape_table<2> build_shape_table<K, C, 2>(const neighbor_search<2>&, const std::vector<vec<2>>&, \
                                                      const rk_shape_functions<K, C, 2>&, shape_table_contents);
#elif defined(RKPM_EXTERN_SHAPE_TABLES)
#define RKPM_SHAPE_TABLE_INSTANCE(K, C) \
  extern template class rk_shape_functions<K, C, 1>; \
  extern template class rk_shape_functions<K, C, 2>; \
  extern template shape_table<2> build_shape_table<K, C, 2>(const neighbor_search<2>&, \
                                                             const std::vector<vec<2>>&, \
                                                             const rk_shape_functions<K, C, 2>&, \
                                                             shape_table_contents);
#endif

#ifdef RKPM_SHAPE_TABLE_INSTANCE
namespace rkpm {
RKPM_SHAPE_TABLE_INSTANCE(kernel::cubic_spline, correction::linear)
RKPM_SHAPE_TABLE_INSTANCE(kernel::cubic_spline, correction::quadratic)
RKPM_SHAPE_TABLE_INSTANCE(kernel::quartic_spline, correction::linear)
RKPM_SHAPE_TABLE_INSTANCE(kernel::quartic_spline, correction::quadratic)
}  // namespace rkpm
#undef RKPM_SHAPE_TABLE_INSTANCE
#endif
