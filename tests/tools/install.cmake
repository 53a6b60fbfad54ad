# tools.find_package: installs this build's rkpm package into a scratch prefix, then
# configures, builds and runs tests/tools/consumer against it (find_package(rkpm CONFIG)).
# Included by tests/CMakeLists.txt; the steps are in install/find_package.cmake.
add_test(NAME tools.find_package
  COMMAND ${CMAKE_COMMAND}
          -DRKPM_BUILD_DIR=${CMAKE_BINARY_DIR}
          -DCONSUMER_SOURCE_DIR=${CMAKE_CURRENT_LIST_DIR}/consumer
          -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/tools/find_package
          -DGENERATOR=${CMAKE_GENERATOR}
          -DCXX_COMPILER=${CMAKE_CXX_COMPILER}
          -P ${CMAKE_CURRENT_LIST_DIR}/install/find_package.cmake)
set_tests_properties(tools.find_package PROPERTIES TIMEOUT 300 LABELS "tools/install")
