// Carries the test programs' precompiled header (tests/CMakeLists.txt, RKPM_TEST_PCH).
