# tools.python.*: the Python module rkpm (tools/python), driven from Debian's python3 with the
# module's folder on the path; the checks are in python/check_python.py. Registered when the
# module is built (pybind11 found); `tools/rkpm test` installs pybind11 so that CI runs them.
if(TARGET rkpm_python)
  add_dependencies(rkpm_tests rkpm_python)
  foreach(mode same-as-cli dict-case sweep observer errors)
    add_test(NAME tools.python.${mode}
             COMMAND ${RKPM_SYSTEM_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/python/check_python.py ${mode}
                     $<TARGET_FILE_DIR:rkpm_python> $<TARGET_FILE:rkpm_run> ${CMAKE_CURRENT_BINARY_DIR}/tools/python/${mode})
    set_tests_properties(tools.python.${mode} PROPERTIES TIMEOUT 300 LABELS "tools/python"
                         ENVIRONMENT "OMP_NUM_THREADS=1;OMP_WAIT_POLICY=passive")
  endforeach()
endif()
