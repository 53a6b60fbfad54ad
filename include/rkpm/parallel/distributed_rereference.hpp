#pragma once
// Re-referencing and cracks on P processes (docs/method.md sections 5.8, 5.12 and 9.8):
// distributed_solver's step(), rereference(), rebuild_from() and read_whole(). A re-reference
// is decided alike on every rank (every_steps counts steps; the distortion is the largest over
// every rank's points, an MPI_MAX: explicit_solver::rereference_due), and so is a crack's cut
// (whether the whole model's failed points cut a cell, or-ed over the ranks:
// solver/part_cracks.hpp); the step that decides either leaves the part between steps with the
// rebuild pending. Then, collectively:
//   1. the run's state, the checkpoint one process would write at this step (the owned values
//      gathered on rank 0, mpi_checkpoint_layout.hpp), is broadcast to every rank;
//   2. every rank reads it into a one-process solver of the whole model (rereference_through's
//      maker; a re-referenced state rebuilds its model through the builder as a restart does)
//      and ends the step as one process does (explicit_solver::end_step: the failed points'
//      cells cut, then the re-reference), or re-references it when asked between steps: the same
//      bits on every rank;
//   3. every rank measures the load of the partition on the new model as the partitioner
//      weighs it (load_imbalance: the table entries at each part's particles); past
//      run_options::rereference.rebalance_above (the largest part over the mean) it partitions
//      the new model again (partition_particles, METIS with fixed options: the same parts on
//      every rank, which all hold the same model), else it keeps the partition;
//   4. every rank builds its part again from that solver's model on that partition (the
//      particles keep their ids, the global indices; new owners if repartitioned, new ghosts,
//      halo plan and point owners), the whole solver's constraints and slaves, and its masses
//      (kept across a re-reference), and takes its values of the whole solver's state by global
//      index (read_checkpoint's path): the cuts among them (the reference sections), and each
//      point's cell (cells_around); and, when cracks can grow, the whole solver's pieces.
// So a re-referenced run on P processes is one process's bit for bit, on whichever partition.
// Memory: the whole model and its state on every rank during the rebuild, as at the set-up (and
// the particle graph while repartitioning).
// Included at the end of parallel/distributed_solver.hpp.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <rkpm/core/error.hpp>
#include <rkpm/io/checkpoint.hpp>
#include <rkpm/parallel/communicator.hpp>
#include <rkpm/parallel/mpi_checkpoint_layout.hpp>  // before distributed_solver.hpp, which includes this
#include <rkpm/parallel/distributed_solver.hpp>
#include <rkpm/solver/checkpoint.hpp>

namespace rkpm::parallel {

namespace detail {

inline constexpr std::string_view rebuild_configuration = "the run on several processes";

// A solver's whole state in memory (section checksums skipped: read at once).
template <class Solver>
std::string state_bytes(const Solver& s) {
  io::checkpoint_writer w({}, checkpoint_identity_of(s, rebuild_configuration), {});
  w.skip_section_checksums();
  w.array("solver.mass", s.mass());
  w.part(s);
  return w.close();
}

}  // namespace detail

template <class Solver>
void distributed_solver<Solver>::step() {
  solver_->step();
  if (solver_->rereference_pending()) rebuild(true);
}

template <class Solver>
void distributed_solver<Solver>::step_to_end() {
  solver_->step_to_end();
  if (solver_->rereference_pending()) rebuild(true);
}

template <class Solver>
void distributed_solver<Solver>::rereference() {
  rebuild(false);
}

template <class Solver>
void distributed_solver<Solver>::rebuild(bool step_end) {
  communicator& comm = group_->comm();
  comm.guarded([&] {
    if (!make_whole_)
      fail("re-referencing (or cutting cracks) on several processes needs the one-process solver of the whole "
           "model: give distributed_solver::rereference_through its maker");
    if (!solver_->between_steps()) fail("rereference() between steps only");
  });
  comm.agree();
  // 1. The run's state, on every rank.
  mpi_checkpoint_layout layout(*group_, solver_->model());
  io::checkpoint_writer w({}, whole_identity(*this, detail::rebuild_configuration), {}, &layout);
  w.skip_section_checksums();
  w.array("solver.mass", solver_->mass());
  w.part(*solver_);
  std::string bytes;
  comm.guarded([&] { bytes = w.close(); });
  comm.agree();
  comm.broadcast(bytes);
  // 2. One process's re-reference, on every rank alike.
  std::optional<Solver> whole;
  comm.guarded([&] {
    whole.emplace(make_whole_());
    io::checkpoint_reader r(std::move(bytes), std::string(detail::rebuild_configuration),
                            checkpoint_identity_of(*whole, detail::rebuild_configuration), false);
    load_checkpoint(*whole, r);
    if (step_end) whole->end_step();  // as one process's step ends: the cuts, then the re-reference
    else whole->rereference();
  });
  comm.agree();
  // 3 and 4. The parts again.
  rebuild_from(*whole);
}

template <class Solver>
void distributed_solver<Solver>::rebuild_from(const Solver& whole) {
  communicator& comm = group_->comm();
  std::string bytes;
  problem_type prob = *problem_;
  comm.guarded([&] {
    bytes = detail::state_bytes(whole);
    prob.constraints = whole.constraints().constraints();
    prob.slave_particles = whole.slave_particles();
    // 3. The new model's load on the partition; past the bound, a new partition.
    const discrete_model& m = whole.model();
    if (load_imbalance(m.at_points, partition_) > options_.rereference.rebalance_above) {
      partition_ = partition_particles(m.at_points, m.particle_count(), comm.size());
      ++repartitions_;
    }
  });
  comm.agree();
  solver_.reset();  // it points to the group built again below
  build(comm, whole.model(), std::move(prob), false);
  ++rebuilds_;
  comm.guarded([&] {
    // The masses: the run's, kept across re-references (not the new volumes').
    const index_t n = plan_.local_particles();
    const bool scaled = options_.mass_scaling.enabled();
    std::vector<double> mass(n), physical(scaled ? n : 0);
    for (index_t i = 0; i < n; ++i) {
      mass[i] = whole.mass()[plan_.global_particle(i)];
      if (scaled) physical[i] = whole.physical_mass()[plan_.global_particle(i)];
    }
    solver_->carry_masses(std::move(mass), std::move(physical), whole.mass_scaling_factor());
  });
  comm.agree();
  mpi_checkpoint_layout layout(*group_, solver_->model());
  comm.guarded([&] {
    io::checkpoint_reader r(std::move(bytes), std::string(detail::rebuild_configuration),
                            whole_identity(*this, detail::rebuild_configuration), false);
    r.set_layout(&layout);
    load_checkpoint(*solver_, r);
  });
  comm.agree();
  count_fragments(comm, &whole);
}

template <class Solver>
void distributed_solver<Solver>::read_whole(const std::filesystem::path& path, std::string_view configuration) {
  communicator& comm = group_->comm();
  std::optional<Solver> whole;
  comm.guarded([&] {
    if (!make_whole_) fail("read_whole: no maker of the whole solver (rereference_through)");
    whole.emplace(make_whole_());
    rkpm::read_checkpoint(*whole, path, configuration);
  });
  comm.agree();
  rebuild_from(*whole);
}

}  // namespace rkpm::parallel
