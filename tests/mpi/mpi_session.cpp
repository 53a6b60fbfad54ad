// MPI for the doctest program of the decomposition tests (tests/mpi), which mpiexec starts on 1,
// 2 or 3 processes (tests/CMakeLists.txt): the program's MPI session begins before main (and so
// before doctest runs the test cases) and ends after it. The program is the shared doctest
// runner of every test program; every rank runs the same test cases in the same order (their
// exchanges are collective), and mpiexec fails if any rank has a failed check. A check that
// only some ranks make is a CHECK, never a REQUIRE: leaving the test case on one rank would
// leave the others waiting in its next exchange (until ctest's timeout).

#include <rkpm/parallel/communicator.hpp>

namespace test_mpi_session {

const rkpm::parallel::mpi_session session;

}  // namespace test_mpi_session
