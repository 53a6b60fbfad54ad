#pragma once
// Checkpoints of a run on P processes (docs/method.md section 9.5): the file one process would
// write at the same step, bit for bit, so that it restarts on any number of processes, one
// included (tests/mpi/distributed_restart.cpp).
//   write_checkpoint(run, path, configuration)   collective; rank 0 writes the file
//   read_checkpoint(run, path, configuration)    collective; every rank reads the file and
//                                                takes its particles' and points' values
//   mirror_state(run, layout, whole, configuration)  collective; rank 0's one-process solver of the
//                                                whole model takes the run's state
// The sections of the whole model's particles and points are named below (mpi_checkpoint_layout):
// each rank gives its owned particles' and owned points' values (point owners, parallel/
// global_blocks.hpp), gathered by global index on rank 0. The other sections (time, energies,
// the stable step's scalars, the contact's per-slave state) are the same on every rank.

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <iterator>
#include <ranges>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <mpi.h>

#include <rkpm/io/checkpoint.hpp>
#include <rkpm/io/checkpoint_layout.hpp>
#include <rkpm/parallel/distributed_solver.hpp>
#include <rkpm/parallel/mpi_process_group.hpp>
#include <rkpm/solver/checkpoint.hpp>

namespace rkpm::parallel {

class mpi_checkpoint_layout final : public io::checkpoint_layout {
 public:
  // The solver's sections of per-particle and per-point arrays (solver/checkpoint.hpp).
  static constexpr const auto& particle_sections = checkpoint_particle_sections;
  static constexpr const auto& point_sections = checkpoint_point_sections;

  mpi_checkpoint_layout(mpi_process_group& group, const discrete_model& part) : group_(group) {
    const halo_plan& plan = group.plan();
    particle_id_ = part.particle_id;
    point_id_ = part.point_id;
    particles_ = {plan.global_particles, std::vector<stored_index>(plan.owned.size())};
    for (std::size_t i = 0; i < plan.owned.size(); ++i) particles_.local[i] = static_cast<stored_index>(i);
    particles_.global = plan.owned;
    points_ = {plan.global_points, group.owned_points()};
    for (const stored_index k : points_.local) points_.global.push_back(plan.points[k]);
  }

  const std::vector<stored_index>* whole_index(std::string_view section) const override {
    if (std::ranges::find(particle_sections, section) != std::end(particle_sections)) return &particle_id_;
    if (std::ranges::find(point_sections, section) != std::end(point_sections)) return &point_id_;
    return nullptr;
  }

  std::string gather(std::string_view section, std::span<const char> local, std::size_t value_bytes) override {
    const owned_values& o = std::ranges::find(point_sections, section) != std::end(point_sections) ? points_ : particles_;
    communicator& comm = group_.comm();
    comm.agree();
    // This rank's owned values, in its order, and their global indices.
    std::string mine(o.local.size() * value_bytes, '\0');
    for (std::size_t k = 0; k < o.local.size(); ++k)
      std::memcpy(mine.data() + k * value_bytes, local.data() + o.local[k] * value_bytes, value_bytes);
    const int count = static_cast<int>(o.local.size());
    std::vector<int> counts(comm.size()), at(comm.size(), 0);
    MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm.get());
    for (int r = 1; r < comm.size(); ++r) at[r] = at[r - 1] + counts[r - 1];
    const bool root = comm.rank() == 0;
    std::vector<stored_index> ids(root ? o.whole : 0);
    MPI_Gatherv(o.global.data(), count, MPI_INT, ids.data(), counts.data(), at.data(), MPI_INT, 0, comm.get());
    std::vector<int> byte_counts(comm.size()), byte_at(comm.size());
    for (int r = 0; r < comm.size(); ++r) {
      byte_counts[r] = counts[r] * static_cast<int>(value_bytes);
      byte_at[r] = at[r] * static_cast<int>(value_bytes);
    }
    std::string all(root ? o.whole * value_bytes : 0, '\0');
    MPI_Gatherv(mine.data(), count * static_cast<int>(value_bytes), MPI_BYTE, all.data(), byte_counts.data(),
                byte_at.data(), MPI_BYTE, 0, comm.get());
    if (!root) return {};
    std::string whole(o.whole * value_bytes, '\0');
    for (std::size_t k = 0; k < ids.size(); ++k)
      std::memcpy(whole.data() + ids[k] * value_bytes, all.data() + k * value_bytes, value_bytes);
    return whole;
  }

  bool writes() const override { return group_.rank() == 0; }

 private:
  // The values a rank gives: local positions and global indices, and the whole array's length.
  struct owned_values {
    index_t whole = 0;
    std::vector<stored_index> local, global;
  };
  mpi_process_group& group_;
  std::vector<stored_index> particle_id_, point_id_;
  owned_values particles_, points_;
};

// The identity of the whole model's run (checkpoint_identity_of gives a part's local counts).
template <class Solver>
io::checkpoint_identity whole_identity(const distributed_solver<Solver>& run, std::string_view configuration) {
  const Solver& s = run.solver();
  return {std::string(configuration), run.plan().global_particles, run.plan().global_points,
          static_cast<index_t>(s.slave_particles().size()), static_cast<index_t>(std::ranges::size(s.contact().tools()))};
}

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
