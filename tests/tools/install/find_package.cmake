# cmake -P script behind the tools.find_package test (registered in tests/tools/install.cmake).
# Inputs: RKPM_BUILD_DIR, CONSUMER_SOURCE_DIR, WORK_DIR, GENERATOR, CXX_COMPILER.
# Every step must succeed; the first failure stops the script with FATAL_ERROR (non-zero exit).
cmake_minimum_required(VERSION 3.20)

foreach(var RKPM_BUILD_DIR CONSUMER_SOURCE_DIR WORK_DIR GENERATOR CXX_COMPILER)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "find_package test: -D${var}=... is required")
  endif()
endforeach()

set(prefix ${WORK_DIR}/prefix)
set(consumer_build ${WORK_DIR}/consumer-build)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

function(step what)
  message(STATUS "find_package test: ${what}")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "find_package test: ${what} failed (${rc})")
  endif()
endfunction()

# Only the library's component: the tools may add install rules for programs that a partial
# build has not made, and they are not what a consumer needs.
step("install rkpm into ${prefix}"
     ${CMAKE_COMMAND} --install ${RKPM_BUILD_DIR} --prefix ${prefix} --component rkpm)

# The library's target carries only what its headers need: no compiled Boost library, libgmsh,
# MPI nor METIS (those come with the optional components gnuplot, gmsh and mpi, defined by
# rkpmConfig.cmake).
file(GLOB_RECURSE rkpm_targets_files ${prefix}/*/rkpmTargets.cmake)
if(NOT rkpm_targets_files)
  message(FATAL_ERROR "find_package test: no rkpmTargets.cmake under ${prefix}")
endif()
foreach(f ${rkpm_targets_files})
  file(READ ${f} rkpm_targets_text)
  foreach(lib Boost::iostreams Boost::system Boost::filesystem libgmsh MPI:: libmetis)
    string(FIND "${rkpm_targets_text}" "${lib}" at)
    if(NOT at EQUAL -1)
      message(FATAL_ERROR "find_package test: the installed rkpm::rkpm links ${lib} (${f}); "
                          "only rkpm::gnuplot, rkpm::gmsh and rkpm::mpi may")
    endif()
  endforeach()
endforeach()

# Unoptimized and without debug information: the consumer's checks are small, and an optimized
# build of its three programs took most of this test's 25 s.
step("configure the consumer"
     ${CMAKE_COMMAND} -S ${CONSUMER_SOURCE_DIR} -B ${consumer_build} -G ${GENERATOR}
     -DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-O0" -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
     -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)

# The consumer must have found the installed copy, not the source or build tree.
file(STRINGS ${consumer_build}/CMakeCache.txt rkpm_dir_line REGEX "^rkpm_DIR:")
string(REGEX REPLACE "^rkpm_DIR:[A-Z]+=" "" rkpm_dir "${rkpm_dir_line}")
file(REAL_PATH "${rkpm_dir}" rkpm_dir)
file(REAL_PATH "${prefix}" real_prefix)
string(FIND "${rkpm_dir}" "${real_prefix}/" at)
if(NOT at EQUAL 0)
  message(FATAL_ERROR "find_package test: the consumer found rkpm in '${rkpm_dir}', "
                      "not in the install prefix ${real_prefix}")
endif()

step("build the consumer" ${CMAKE_COMMAND} --build ${consumer_build})
step("run the consumer" ${consumer_build}/app)
step("draw with the consumer's gnuplot component" ${consumer_build}/plot ${WORK_DIR}/consumer.png)
step("mesh with the consumer's gmsh component" ${consumer_build}/mesh)
