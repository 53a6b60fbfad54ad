// Carries the runner's and tutorials' precompiled header (cmake/rkpm_program_pch.cmake).
