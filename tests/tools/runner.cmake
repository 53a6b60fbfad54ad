# tools.runner.*: the command-line runner rkpm_run (tools/runner), driven as a user would and
# checked with /usr/bin/python3 (json, csv, and meshio as an independent VTK reader); the
# checks are in runner/check_runner.py. Included by tests/CMakeLists.txt; ctest does not build
# rkpm_run, build it first (cmake --build BUILD --target rkpm_run).
set(rkpm_runner_check ${CMAKE_CURRENT_LIST_DIR}/runner/check_runner.py)
set(rkpm_runner_work ${CMAKE_CURRENT_BINARY_DIR}/tools/runner)

add_test(NAME tools.runner.bad_options
         COMMAND ${RKPM_SYSTEM_PYTHON} ${rkpm_runner_check} bad-options $<TARGET_FILE:rkpm_run> ${rkpm_runner_work})
add_test(NAME tools.runner.step_budget
         COMMAND ${RKPM_SYSTEM_PYTHON} ${rkpm_runner_check} step-budget $<TARGET_FILE:rkpm_run> ${rkpm_runner_work})
add_test(NAME tools.runner.help COMMAND ${RKPM_SYSTEM_PYTHON} ${rkpm_runner_check} help $<TARGET_FILE:rkpm_run>)
# Two rods head on (rod_on_rod) with every contact policy, several rules, the other kernel and correction.
add_test(NAME tools.runner.rod_on_rod
         COMMAND ${RKPM_SYSTEM_PYTHON} ${rkpm_runner_check} rod-on-rod $<TARGET_FILE:rkpm_run> ${rkpm_runner_work})
# A 2 us Taylor bar on 21 x 21 particles writes the files the next two tests read.
add_test(NAME tools.runner.run
         COMMAND ${RKPM_SYSTEM_PYTHON} ${rkpm_runner_check} run $<TARGET_FILE:rkpm_run> ${rkpm_runner_work}/taylor_bar)
add_test(NAME tools.runner.outputs COMMAND ${RKPM_SYSTEM_PYTHON} ${rkpm_runner_check} outputs ${rkpm_runner_work}/taylor_bar)
add_test(NAME tools.runner.vtk COMMAND ${RKPM_SYSTEM_PYTHON} ${rkpm_runner_check} vtk ${rkpm_runner_work}/taylor_bar)
# tools/rkpm view on that run's folder.
add_test(NAME tools.runner.view
         COMMAND ${RKPM_SYSTEM_PYTHON} ${rkpm_runner_check} view ${PROJECT_SOURCE_DIR}/tools/view/rkpm_view.py
                 ${rkpm_runner_work}/taylor_bar)
set_tests_properties(tools.runner.run PROPERTIES FIXTURES_SETUP rkpm_runner_output)
set_tests_properties(tools.runner.outputs tools.runner.vtk tools.runner.view PROPERTIES FIXTURES_REQUIRED rkpm_runner_output)
set_tests_properties(tools.runner.bad_options tools.runner.step_budget tools.runner.help tools.runner.rod_on_rod tools.runner.run tools.runner.outputs tools.runner.vtk tools.runner.view
                     PROPERTIES TIMEOUT 120 LABELS "tools/runner"
                                ENVIRONMENT "OMP_NUM_THREADS=2;OMP_WAIT_POLICY=passive")

# Checkpoints and restarts (runner/check_restart.py): a restart gives the uninterrupted run's
# outputs bit for bit, so these run at one thread, where runs are reproducible to the bit.
set(rkpm_restart_check ${CMAKE_CURRENT_LIST_DIR}/runner/check_restart.py)
foreach(mode same kill refused)
  add_test(NAME tools.runner.restart_${mode}
           COMMAND ${RKPM_SYSTEM_PYTHON} ${rkpm_restart_check} ${mode} $<TARGET_FILE:rkpm_run> ${rkpm_runner_work}/restart)
  set_tests_properties(tools.runner.restart_${mode} PROPERTIES TIMEOUT 300 LABELS "tools/runner"
                       ENVIRONMENT "OMP_NUM_THREADS=1;OMP_WAIT_POLICY=passive")
endforeach()

# Case files (runner/check_case_files.py): cases/*.json against the built-in cases, a restart,
# bad files, a Gmsh body, several bodies, the energy ledger of summary.json, the Johnson-Cook and
# Zerilli-Armstrong files, a Johnson-Cook bar that breaks (fracture) and fields given as expressions. One thread, so that the comparisons can ask for equality.
set(rkpm_case_file_check ${CMAKE_CURRENT_LIST_DIR}/runner/check_case_files.py)
# The paper's cases are one test each (paper_*), so that they run side by side.
foreach(mode paper_taylor_bar paper_block_forging paper_wheel_forging paper_override restart errors mesh bodies
             ledger voce johnson_cook zerilli_armstrong fracture expressions)
  add_test(NAME tools.runner.case_files_${mode}
           COMMAND ${RKPM_SYSTEM_PYTHON} ${rkpm_case_file_check} ${mode} $<TARGET_FILE:rkpm_run>
                   ${PROJECT_SOURCE_DIR}/cases ${rkpm_runner_work}/case_files)
  set_tests_properties(tools.runner.case_files_${mode} PROPERTIES TIMEOUT 300 LABELS "tools/runner"
                       ENVIRONMENT "OMP_NUM_THREADS=1;OMP_WAIT_POLICY=passive")
endforeach()

# rkpm_run on several processes (runner/check_ranks.py; tools/runner/ranks.hpp), when rkpm::mpi
# exists: the paper's three cases (the Taylor bar re-referenced, parallel/
# distributed_rereference.hpp), rod_on_rod, the plate_impact case file (two bodies; its probes'
# nearest particles chosen by reduction, reduce_on_root.hpp) and the Johnson-Cook Taylor bar's
# (its rows by reduction: extents on an edge, a velocity probe, largest plastic strain and
# temperature, momentum, volume change; case_file/measure_parts.hpp) and the brittle bar (cracks:
# its fragments, parallel/run_fragments.hpp) each on 1, 2 and 3 processes give the same files byte
# for byte, and the same snapshots in pieces (.pvtu, put together by meshio: runner/pieces.py); a checkpoint from
# 2 processes continues on 1 and on 3 to the uninterrupted run; a failure stops every rank with
# one line. The cases without re-referencing or cracks, of one body or two, are set up in parts
# (each process about N/P particles and its ghosts, summary.json's local_particles;
# tools/runner/part_setup.hpp), the others whole, and the memory warning counts either form. One thread per process, oversubscribed and unbound
# (rkpm_mpiexec_flags, tests/CMakeLists.txt).
if(TARGET rkpm::mpi)
  set(rkpm_ranks_check ${CMAKE_CURRENT_LIST_DIR}/runner/check_ranks.py)
  set(rkpm_ranks_launcher ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} 1 ${rkpm_mpiexec_flags})
  list(REMOVE_ITEM rkpm_ranks_launcher ${MPIEXEC_NUMPROC_FLAG} 1)
  if(rkpm_mpiexec_version MATCHES "Open MPI|OpenRTE")
    list(APPEND rkpm_ranks_launcher --bind-to none)
  endif()
  string(JOIN " " rkpm_ranks_launcher ${rkpm_ranks_launcher})
  set(rkpm_ranks_cases
      "block_forging|--end-time|3e-4"
      "wheel_forging|--end-time|2e-5"
      "rod_on_rod|--end-time|2e-6"
      "${PROJECT_SOURCE_DIR}/cases/plate_impact/plate_impact.json|--end-time|2e-6"
      # (a Rankine bar broken in two: cuts through the parts' rebuilds, the run's fragments in the rows
      # and summary, the snapshots whole with their crack faces)
      "${PROJECT_SOURCE_DIR}/cases/brittle_bar.json"
      # (its height, length and failed fraction replaced by a probe of the velocity by the impact face
      # and sums over a part: momentum and volume change)
      "${PROJECT_SOURCE_DIR}/cases/taylor_bar_johnson_cook.json|--end-time|3e-6|--set|/histories/1={\"name\":\"foot_velocity_m_s\",\"probe\":{\"body\":\"bar\",\"point_m\":[0.001,0.001],\"quantity\":\"velocity\",\"component\":\"y\"}}|--set|/histories/2={\"name\":\"momentum_y_N_s\",\"momentum\":{\"body\":\"bar\",\"component\":\"y\"}}|--set|/histories/5={\"name\":\"volume_change\",\"volume_change\":{\"body\":\"bar\"}}")
  set(rkpm_ranks_tests)
  foreach(request IN LISTS rkpm_ranks_cases)
    string(REPLACE "|" ";" request "${request}")
    list(GET request 0 name)
    get_filename_component(label ${name} NAME_WE)
    add_test(NAME tools.runner.ranks_${label}
             COMMAND ${RKPM_SYSTEM_PYTHON} ${rkpm_ranks_check} same "${rkpm_ranks_launcher}" $<TARGET_FILE:rkpm_run>
                     ${rkpm_runner_work}/ranks ${request})
    list(APPEND rkpm_ranks_tests tools.runner.ranks_${label})
  endforeach()
  # The Taylor bar re-referenced by count and by stretch (parallel/distributed_rereference.hpp):
  # between its re-references it steps as a Lagrangian run does, so the bar is not run again
  # without them. A load bound just above 1 repartitions the particles at every re-reference on
  # several processes (summary.json's repartitions), and the snapshot pieces follow.
  add_test(NAME tools.runner.ranks_taylor_bar_rereferenced
           COMMAND ${RKPM_SYSTEM_PYTHON} ${rkpm_ranks_check} same "${rkpm_ranks_launcher}" $<TARGET_FILE:rkpm_run>
                   ${rkpm_runner_work}/ranks taylor_bar --end-time 2e-6 --rereference-every 10
                   --rereference-stretch 1.02 --rebalance-above 1.000001)
  list(APPEND rkpm_ranks_tests tools.runner.ranks_taylor_bar_rereferenced)
  foreach(mode restart errors)
    add_test(NAME tools.runner.ranks_${mode}
             COMMAND ${RKPM_SYSTEM_PYTHON} ${rkpm_ranks_check} ${mode} "${rkpm_ranks_launcher}"
                     $<TARGET_FILE:rkpm_run> ${rkpm_runner_work}/ranks)
    list(APPEND rkpm_ranks_tests tools.runner.ranks_${mode})
  endforeach()
  set_tests_properties(${rkpm_ranks_tests} PROPERTIES TIMEOUT 300 LABELS "tools/runner" PROCESSORS 3
                       ENVIRONMENT "${rkpm_mpi_test_environment}")
endif()

# tools/rkpm help: the usage text with every tutorial that has a main.cpp, and exit status 0
# (a tutorial without one, tutorials/12_python, once ended the script before it printed a word).
add_test(NAME tools.rkpm_help
         COMMAND bash -c "out=$(\"$0\" help) && grep -q 'usage: tools/rkpm' <<<\"$out\" && grep -q '04_taylor_bar' <<<\"$out\" && ! grep -q '12_python' <<<\"$out\""
                 ${PROJECT_SOURCE_DIR}/tools/rkpm)
set_tests_properties(tools.rkpm_help PROPERTIES TIMEOUT 60 LABELS "tools")
