# One precompiled header for the Release programs that draw figures (the runner rkpm_run and
# the tutorials): Eigen, fmt, Hana, gnuplot-iostream and the whole library are parsed once
# instead of once per translation unit. The header is built by a target of its own with the
# programs' flags and dependencies (a precompiled header is only used when they match).
# rkpm_use_program_pch(TARGET) makes TARGET reuse it; RKPM_PROGRAM_PCH=OFF turns it off.
option(RKPM_PROGRAM_PCH "Precompile the headers shared by the runner and the tutorials" ON)
if(RKPM_PROGRAM_PCH)
  add_library(rkpm_program_pch OBJECT ${CMAKE_CURRENT_LIST_DIR}/pch.cpp)
  target_link_libraries(rkpm_program_pch PUBLIC rkpm::rkpm rkpm::gnuplot rkpm_instances)
  target_precompile_headers(rkpm_program_pch PRIVATE
    <algorithm> <cmath> <filesystem> <functional> <string> <vector>
    <Eigen/Dense> <fmt/format.h> <boost/hana.hpp>
    <rkpm/rkpm.hpp> <rkpm/io/gnuplot.hpp> <rkpm/io/csv.hpp> <rkpm/io/vtk.hpp>
    # nlohmann-json: every runner file includes it (summary.json, checkpoints' records, case
    # files); parsed once here instead of in each of them.
    <nlohmann/json.hpp>)
endif()

# Compiled with -fPIC (the runner's library goes into the Python module, a shared object), so
# every program that uses the header is too: a header is only used with the flags it was made with.
if(RKPM_PROGRAM_PCH)
  target_compile_options(rkpm_program_pch PRIVATE -fPIC)
endif()
function(rkpm_use_program_pch target)
  if(RKPM_PROGRAM_PCH)
    target_precompile_headers(${target} REUSE_FROM rkpm_program_pch)
    target_compile_options(${target} PRIVATE -fPIC)
  endif()
endfunction()
