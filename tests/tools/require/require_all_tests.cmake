# cmake -P script behind the tools.require_all_tests test (registered in tests/tools/require.cmake).
# Inputs: SOURCE_DIR, WORK_DIR, GENERATOR, CXX_COMPILER.
#
# Hides three of the dependencies RKPM_REQUIRE_ALL_TESTS requires, each the way it would be
# missing on a machine without its package:
#   MPI       -DCMAKE_DISABLE_FIND_PACKAGE_MPI=ON       (find_package(MPI) finds nothing)
#   pybind11  -DCMAKE_DISABLE_FIND_PACKAGE_pybind11=ON  (tools/python finds nothing)
#   meshio    PYTHONPATH=<dir with a meshio.py that raises ImportError> (import meshio fails)
# then configures the project twice: with RKPM_REQUIRE_ALL_TESTS=ON it must fail, naming each
# Debian package on its line, and generate nothing; OFF it must succeed (the tests left out).
# METIS shares MPI's line (one rkpm::mpi check); Gmsh and muparser were already configure errors
# in every build of the project (CMakeLists.txt, tests/CMakeLists.txt).
cmake_minimum_required(VERSION 3.20)

foreach(var SOURCE_DIR WORK_DIR GENERATOR CXX_COMPILER)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "require_all_tests test: -D${var}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR}/hidden_python)
file(WRITE ${WORK_DIR}/hidden_python/meshio.py "raise ImportError('meshio hidden by tools.require_all_tests')\n")

function(configure_hidden require build_dir out_rc out_text)
  execute_process(
    COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${WORK_DIR}/hidden_python
            ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${build_dir} -G ${GENERATOR}
            -DCMAKE_CXX_COMPILER=${CXX_COMPILER} -DCMAKE_BUILD_TYPE=Release
            -DCMAKE_DISABLE_FIND_PACKAGE_MPI=ON -DCMAKE_DISABLE_FIND_PACKAGE_pybind11=ON
            -DRKPM_REQUIRE_ALL_TESTS=${require}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(${out_rc} ${rc} PARENT_SCOPE)
  set(${out_text} "${out}${err}" PARENT_SCOPE)
endfunction()

configure_hidden(ON ${WORK_DIR}/required rc text)
message(STATUS "configure with RKPM_REQUIRE_ALL_TESTS=ON (exit status ${rc}):\n${text}")
if(rc EQUAL 0)
  message(FATAL_ERROR "require_all_tests test: the configure succeeded with MPI, pybind11 and meshio hidden")
endif()
# CMake wraps a message at about 80 columns, continuing it on indented lines: joined again here.
string(REGEX REPLACE "\n +" " " joined "${text}")
foreach(expected
    "MPI \\(rkpm::mpi\\) not found, its tests cannot run \\(RKPM_REQUIRE_ALL_TESTS\\): apt-get install libopenmpi-dev openmpi-bin libmetis-dev\n"
    "pybind11 \\(the Python module rkpm\\) not found, its tests cannot run \\(RKPM_REQUIRE_ALL_TESTS\\): apt-get install pybind11-dev python3-dev\n"
    "Python's meshio \\(import meshio in [^)]*\\) not found, its tests cannot run \\(RKPM_REQUIRE_ALL_TESTS\\): apt-get install python3-meshio\n")
  if(NOT joined MATCHES "${expected}")
    message(FATAL_ERROR "require_all_tests test: no line matching \"${expected}\" in the output above")
  endif()
endforeach()
if(EXISTS ${WORK_DIR}/required/build.ninja OR EXISTS ${WORK_DIR}/required/Makefile)
  message(FATAL_ERROR "require_all_tests test: the failed configure generated a build system")
endif()

configure_hidden(OFF ${WORK_DIR}/optional rc text)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "require_all_tests test: with RKPM_REQUIRE_ALL_TESTS=OFF the configure failed:\n${text}")
endif()
message(STATUS "require_all_tests test: the three missing packages named with the option ON; OFF configures")
