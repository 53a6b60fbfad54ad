// An error thrown outside communicator::guarded() on one rank while the others wait in a
// collective call (ctest mpi.unguarded_error, on 3 processes, with a timeout): it unwinds
// through the mpi_session, whose destructor ends every rank with MPI_Abort and a line naming
// the rank, instead of leaving the others waiting. A plain program, not doctest: the exception
// has to leave the session's scope.

#include <cstdio>

#include <rkpm/parallel/communicator.hpp>

int main(int argc, char** argv) {
  try {
    rkpm::parallel::mpi_session session(argc, argv);
    rkpm::parallel::communicator world;
    if (world.rank() == 1 % world.size()) rkpm::fail("a deliberate error on rank {}, outside guarded()", world.rank());
    MPI_Barrier(world.get());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
}
