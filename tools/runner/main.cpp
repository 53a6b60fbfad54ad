// rkpm_run: runs one of the paper's cases with the policies chosen on the command line, or
// the whole paper (`rkpm_run paper`). See `rkpm_run --help`.
// Under mpiexec (`mpiexec -np P rkpm_run CASE ...`, or `tools/rkpm run CASE --ranks P`) the
// case runs on the P processes, each stepping a part (ranks.hpp); rank 0 writes the results
// and prints. Started otherwise, it is one process and does not start MPI.
#include <cstdio>
#include <algorithm>
#include <cstdlib>
#include <optional>
#include <string>

#include <fmt/format.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#ifdef _OPENMP
#include <omp.h>
#endif
#ifdef RKPM_RUNNER_MPI
#include <rkpm/parallel/communicator.hpp>
#endif

#include <rkpm/core/error.hpp>

#include "case_list.hpp"
#include "interrupt.hpp"
#include "paper.hpp"
#include "run_case_file.hpp"
#include "request.hpp"

namespace {

// The processes mpiexec started this one among (its environment: Open MPI's, PMIx's, MPICH's), or 1.
int launched_processes() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_SIZE", "PMI_SIZE"})
    if (const char* v = std::getenv(name)) return std::max(1, std::atoi(v));
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace rkpm::runner;
#ifdef __GLIBC__
  // Arrays above 6 MiB come straight from the system and go back to it when freed. By default
  // glibc raises this threshold to the size of each large block freed (up to 32 MB), after which
  // blocks below it come from the heap, which keeps their pages: the arrays of a large run's
  // first snapshot would stay in the process, and a later array might not fit in them, so the
  // peak would grow by their size. Below 6 MiB the snapshot's 4 MiB chunk buffers stay in the
  // heap, and so does up to 32 MiB of free space at its top (the trim threshold, which a fixed
  // mmap threshold would otherwise leave at 128 KiB): given back, the buffers would be faulted
  // in anew by every snapshot, and page faults make the output slower. The step allocates
  // nothing, so these settings do not touch its time. They are the program's, not the library's:
  // they apply to the whole process (docs/performance.md, the runner's memory).
  mallopt(M_MMAP_THRESHOLD, 6 * 1024 * 1024);
  mallopt(M_TRIM_THRESHOLD, 32 * 1024 * 1024);
#endif
  const int processes = launched_processes();
  int rank = 0, processes_here = 1, machine_rank = 0, with_rank_0 = 1;
#ifdef RKPM_RUNNER_MPI
  // MPI only under mpiexec: a run started alone needs none of it.
  std::optional<rkpm::parallel::mpi_session> session;
  if (processes > 1) {
    session.emplace(argc, argv);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    // The processes that share this machine's memory, in the world's order.
    MPI_Comm machine;
    MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank, MPI_INFO_NULL, &machine);
    MPI_Comm_size(machine, &processes_here);
    MPI_Comm_rank(machine, &machine_rank);
    with_rank_0 = rank == 0 ? 1 : 0;
    MPI_Bcast(&with_rank_0, 1, MPI_INT, 0, machine);  // its first process: rank 0 if rank 0 is here
    MPI_Comm_free(&machine);
  }
#endif
  bool parsed = false;
  try {
    const command_line cl = parse_command_line(argc, argv);
    parsed = true;
    if (cl.what == command_line::action::exit) return cl.exit_code;
    if (cl.what == command_line::action::paper) {
      if (processes > 1) rkpm::fail("rkpm_run paper runs on one process; run single cases on several (--ranks)");
      return run_paper(cl.paper);
    }
    run_request r = cl.run;
    r.processes = processes;
    r.processes_here = processes_here;
    r.machine_rank = machine_rank;
    r.with_rank_0 = with_rank_0 != 0;
    if (r.ranks > 0 && r.ranks != processes)
      rkpm::fail("--ranks {}: this is {} process{}; start it with mpiexec -np {} (tools/rkpm run CASE --ranks {} does)",
                 r.ranks, processes, processes == 1 ? "" : "es", r.ranks, r.ranks);
#ifdef _OPENMP
    if (r.threads > 0) omp_set_num_threads(r.threads);
#endif
    stop_between_steps_on_interrupt();
    const run_outcome out = r.case_file.empty() ? run_named_case(r) : run_case_file(r);
    if (rank != 0) return 0;
    const auto& s = out.summary;
    fmt::print("{} ({}-{}-{}-{}): {} steps in {:.2f} s (set-up {:.2f} s){}, energy balance error {:.2e}\n",
               s.at("case").get<std::string>(), s.at("kernel").get<std::string>(),
               s.at("correction").get<std::string>(), s.at("quadrature").get<std::string>(),
               s.at("contact").get<std::string>(), s.at("steps").get<long>(), s.at("wall_s").get<double>(),
               s.at("setup_s").get<double>(), processes > 1 ? fmt::format(" on {} processes", processes) : "",
               s.at("energy").at("balance_error").get<double>());
    for (const auto& [k, v] : s.at("results").items()) fmt::print("  {:<34} {:.6g}\n", k, v.get<double>());
    fmt::print("results in {}\n", out.directory);
    return 0;
  } catch (const std::exception& e) {
    // On several processes the command line's errors and the errors the ranks agreed on
    // (parallel::rank_failure) are every rank's: rank 0 says them. Another rank's own error may
    // leave the others waiting: it is said with the rank, and MPI_Abort ends every process.
    if (rank == 0) {
      fmt::print(stderr, "rkpm_run: {}\n", e.what());
      return 1;
    }
#ifdef RKPM_RUNNER_MPI
    if (parsed && !dynamic_cast<const rkpm::parallel::rank_failure*>(&e)) {
      fmt::print(stderr, "rkpm_run (rank {} of {}): {}\n", rank, processes, e.what());
      MPI_Abort(MPI_COMM_WORLD, 1);
    }
#endif
    return 1;
  }
}
