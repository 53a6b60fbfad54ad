# tools.require_all_tests: `tools/rkpm test` configures with RKPM_REQUIRE_ALL_TESTS=ON, so that a
# missing MPI, pybind11 or meshio stops the configure with the package to install instead of
# leaving their tests out. This configures the project into a scratch directory with those three
# hidden (require/require_all_tests.cmake) and checks that it fails naming each package, and that
# with the option OFF (a consumer's build) the same configure succeeds.
add_test(NAME tools.require_all_tests
  COMMAND ${CMAKE_COMMAND}
          -DSOURCE_DIR=${PROJECT_SOURCE_DIR}
          -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/tools/require_all_tests
          -DGENERATOR=${CMAKE_GENERATOR}
          -DCXX_COMPILER=${CMAKE_CXX_COMPILER}
          -P ${CMAKE_CURRENT_LIST_DIR}/require/require_all_tests.cmake)
set_tests_properties(tools.require_all_tests PROPERTIES TIMEOUT 120 LABELS "tools/require")
