# rkpm_instances: the library's heaviest templates for the shipped policies, compiled once and
# linked by the project's programs (runner, bench, tutorials, tests, the Python module), which
# get RKPM_EXTERN_SHAPE_TABLES, RKPM_EXTERN_MODELS, RKPM_EXTERN_CONSTRAINTS and RKPM_EXTERN_SOLVERS
# from it and so only call them:
#   shape_tables.cpp          build_shape_table per kernel and correction
#                             (include/rkpm/discretization/shape_table_instances.hpp)
#   models_plane_strain.cpp   the discrete model of every kernel, correction and rule, and
#   models_axisymmetric.cpp   make_model<G>, per geometry (include/rkpm/solver/model_instances.hpp)
#   constraints.cpp           the velocity constraints' projector, Eigen's sparse factorization
#                             (include/rkpm/solver/constraints.hpp): every file that includes the
#                             library would otherwise instantiate it at its end, used or not
#   solvers_1.cpp .. _3.cpp   explicit_solver of the configurations that several of the tests
#                             and tutorials use (include/rkpm/solver/solver_instances.hpp)
# Units that build side by side; without them every file that builds a model compiles the
# models again (the integration tests' unit 48 of them; its compile time did not measurably drop,
# most of it is the tests' own templates, but the runner's two model units are gone). Not
# installed: a consumer of the header-only library need not care.
add_library(rkpm_instances STATIC ${CMAKE_CURRENT_LIST_DIR}/shape_tables.cpp
            ${CMAKE_CURRENT_LIST_DIR}/models_plane_strain.cpp ${CMAKE_CURRENT_LIST_DIR}/models_axisymmetric.cpp
            ${CMAKE_CURRENT_LIST_DIR}/constraints.cpp ${CMAKE_CURRENT_LIST_DIR}/solvers_1.cpp
            ${CMAKE_CURRENT_LIST_DIR}/solvers_2.cpp ${CMAKE_CURRENT_LIST_DIR}/solvers_3.cpp)
# Position-independent: the Python module (a shared object) links it through the runner.
set_target_properties(rkpm_instances PROPERTIES POSITION_INDEPENDENT_CODE ON)
target_link_libraries(rkpm_instances PUBLIC rkpm::rkpm)
target_compile_definitions(rkpm_instances PUBLIC RKPM_EXTERN_SHAPE_TABLES RKPM_EXTERN_MODELS RKPM_EXTERN_CONSTRAINTS
                           RKPM_EXTERN_SOLVERS)
