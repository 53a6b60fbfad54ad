#pragma once
// Checkpoints of a run on P processes (docs/method.md section 9.5): the file one process would
// write at the same step, bit for bit, so that it restarts on any number of processes, one
// included (tests/mpi/distributed_restart.cpp).
//   write_checkpoint(run, path, configuration)   collective; rank 0 writes the file
//   read_checkpoint(run, path, configuration)    collective; every rank reads the file and
//                                                takes its particles' and points' values
//   mirror_state(run, layout, whole, configuration)  collective; rank 0's one-process solver of the
//                                                whole model takes the run's state
// The sections of the whole model's particles and points are named in solver/checkpoint.hpp
// (parallel/mpi_checkpoint_layout.hpp): each rank gives its owned particles' and owned points' values (point owners, parallel/
// global_blocks.hpp), gathered by global index on rank 0. The other sections (time, energies,
// the stable step's scalars, the contact's per-slave state) are the same on every rank.

#include <filesystem>
#include <string>
#include <string_view>

#include <rkpm/io/checkpoint.hpp>
#include <rkpm/parallel/distributed_solver.hpp>
#include <rkpm/parallel/mpi_checkpoint_layout.hpp>
#include <rkpm/parallel/mpi_process_group.hpp>
#include <rkpm/solver/checkpoint.hpp>

namespace rkpm::parallel {

// Collective: the checkpoint one process would write at this step, written by rank 0 through a
// temporary file and a rename; every rank returns once it is in place (or throws the same error).
template <class Solver>
void write_checkpoint(distributed_solver<Solver>& run, const std::filesystem::path& path,
                      std::string_view configuration, std::string_view description = {}) {
  mpi_checkpoint_layout layout(run.group(), run.solver().model());
  io::checkpoint_writer w(path, whole_identity(run, configuration), description, &layout);
  w.array("solver.mass", run.solver().mass());
  w.part(run.solver());
  run.group().guarded([&] { w.commit(); });
  run.group().agree();
}

// Collective: every rank reads a checkpoint of the whole model (written on any number of
// processes) and takes its particles' and points' values. Refused on every rank alike. Through
// the whole solver when the run has its maker (distributed_solver::read_whole): a re-referenced
// checkpoint's model is rebuilt there and the parts built from it.
template <class Solver>
void read_checkpoint(distributed_solver<Solver>& run, const std::filesystem::path& path,
                     std::string_view configuration) {
  if (run.rereferences_through_whole()) return run.read_whole(path, configuration);  // a re-referenced model
  mpi_checkpoint_layout layout(run.group(), run.solver().model());
  run.group().guarded([&] {
    io::checkpoint_reader r(path, whole_identity(run, configuration));
    r.set_layout(&layout);
    load_checkpoint(run.solver(), r);
  });
  run.group().agree();
}

// Collective: puts the run's whole state into `whole`, a one-process solver of the whole model
// on rank 0 (null on the other ranks), through a checkpoint held in memory: afterwards it is the
// solver one process would have at this step, bit for bit, and reads and writes as one (the
// runner observes it for its history rows, snapshots and checkpoints, tools/runner/ranks.hpp).
// `layout`: the run's (built once for a run that mirrors often).
template <class Solver>
void mirror_state(distributed_solver<Solver>& run, mpi_checkpoint_layout& layout, Solver* whole,
                  std::string_view configuration) {
  io::checkpoint_writer w({}, whole_identity(run, configuration), {}, &layout);
  w.skip_section_checksums();  // bytes in memory, read at once
  w.array("solver.mass", run.solver().mass());
  w.part(run.solver());
  run.group().guarded([&] {
    std::string bytes = w.close();
    if (run.group().rank() != 0) return;
    if (!whole) fail("mirror_state: rank 0 has no whole solver to put the run's state into");
    io::checkpoint_reader r(std::move(bytes), "the state of the run on several processes",
                            checkpoint_identity_of(*whole, configuration), false);
    load_checkpoint(*whole, r);
  });
  run.group().agree();
}

}  // namespace rkpm::parallel
