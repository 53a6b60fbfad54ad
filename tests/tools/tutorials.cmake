# tutorials.NN_name: each C++ tutorial (tutorials/NN_name/main.cpp, built by tutorials/CMakeLists.txt
# and, through rkpm_tests, by `tools/rkpm test`) run at a small size into the build directory;
# the test is its exit status 0 (a tutorial checks its own results and exits non-zero on an
# error). The arguments make each run a few seconds at the test build's -O1: the same code paths
# as the full run (set-up, steps, contact, output, figures), far fewer steps. A tutorial not in
# the table runs with its output directory alone (its defaults: the full size).
set(rkpm_tutorial_args_04_taylor_bar 5e-6)                         # end time
set(rkpm_tutorial_args_05_block_forging 2e-4)                      # end time
set(rkpm_tutorial_args_06_wheel_forging 2e-4)                      # stroke
set(rkpm_tutorial_args_07_bodies_in_contact 2e-6 1)                # end time, resolution
set(rkpm_tutorial_args_09_your_own_problem 2e-6 1)                 # end time, resolution
set(rkpm_tutorial_args_10_rate_and_temperature 2e-6)               # end time of part 1
set(rkpm_tutorial_args_11_many_processes 1e-6 1)                   # end time, resolution
set(rkpm_tutorial_args_13_extreme_deformation 300 1 1.5 2e-6)      # speed, resolution, stretch, end time
set(rkpm_tutorial_args_14_fracture 5 4e-5)                         # cell size (mm), end time
set(rkpm_tutorial_args_15_hot_forging 0.05 11)                     # end time (5% reduction), particles per side

file(GLOB rkpm_tutorial_sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/tutorials/[0-9][0-9]_*/main.cpp)
foreach(src ${rkpm_tutorial_sources})
  get_filename_component(dir ${src} DIRECTORY)
  get_filename_component(name ${dir} NAME)
  if(NOT TARGET tutorial_${name})
    continue()  # tutorial 11 without rkpm::mpi (a configure error under RKPM_REQUIRE_ALL_TESTS)
  endif()
  add_dependencies(rkpm_tests tutorial_${name})
  set(out ${CMAKE_CURRENT_BINARY_DIR}/tutorials/${name})
  file(MAKE_DIRECTORY ${out})
  if(name STREQUAL "11_many_processes")
    # On two processes, as its README runs it (flags as for tests/mpi).
    add_test(NAME tutorials.${name}
             COMMAND ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} 2 ${rkpm_mpiexec_flags}
                     $<TARGET_FILE:tutorial_${name}> ${MPIEXEC_POSTFLAGS} ${out} ${rkpm_tutorial_args_${name}})
    set_tests_properties(tutorials.${name} PROPERTIES PROCESSORS 2 ENVIRONMENT "${rkpm_mpi_test_environment}")
  else()
    add_test(NAME tutorials.${name} COMMAND tutorial_${name} ${out} ${rkpm_tutorial_args_${name}})
    set_tests_properties(tutorials.${name} PROPERTIES ENVIRONMENT "OMP_NUM_THREADS=1;OMP_WAIT_POLICY=passive")
  endif()
  set_tests_properties(tutorials.${name} PROPERTIES TIMEOUT 120 LABELS "tutorials/${name}" WORKING_DIRECTORY ${out})
endforeach()

# Tutorial 12, a Python script: its --quick sweep (11 x 21 particles, 20 us, five speeds) with the
# module rkpm importable, as `tools/rkpm python` runs it; when the module is built (pybind11).
if(TARGET rkpm_python)
  set(out ${CMAKE_CURRENT_BINARY_DIR}/tutorials/12_python)
  file(MAKE_DIRECTORY ${out})
  add_test(NAME tutorials.12_python
           COMMAND ${RKPM_SYSTEM_PYTHON} ${PROJECT_SOURCE_DIR}/tutorials/12_python/speed_sweep.py ${out} --quick)
  set_tests_properties(tutorials.12_python PROPERTIES TIMEOUT 120 LABELS "tutorials/12_python" WORKING_DIRECTORY ${out}
                       ENVIRONMENT "PYTHONPATH=$<TARGET_FILE_DIR:rkpm_python>;OMP_NUM_THREADS=1;OMP_WAIT_POLICY=passive")
endif()
