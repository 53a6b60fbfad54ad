# rkpm_shape_tables: build_shape_table for the shipped kernels and corrections, compiled once
# (cmake/shape_tables.cpp) and linked by the project's programs (runner, bench, tutorials,
# tests), which get RKPM_EXTERN_SHAPE_TABLES from it and so do not compile the tables in every
# file (include/rkpm/discretization/shape_table_instances.hpp). About a third of a runner
# file's compile time. Not installed: a consumer of the header-only library need not care.
add_library(rkpm_shape_tables STATIC ${CMAKE_CURRENT_LIST_DIR}/shape_tables.cpp)
# Position-independent: the Python module (a shared object) links it through the runner.
set_target_properties(rkpm_shape_tables PROPERTIES POSITION_INDEPENDENT_CODE ON)
target_link_libraries(rkpm_shape_tables PUBLIC rkpm::rkpm)
target_compile_definitions(rkpm_shape_tables PUBLIC RKPM_EXTERN_SHAPE_TABLES)
