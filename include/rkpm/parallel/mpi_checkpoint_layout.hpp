#pragma once
// mpi_checkpoint_layout: the layout (io/checkpoint_layout.hpp) of a rank's part of a run on P
// processes (docs/method.md section 9.5): the whole model's particle and point sections
// (solver/checkpoint.hpp's lists) gathered by global index on rank 0 for writing, and each local
// value taken by its global index for reading; whole_identity: the whole model's identity of a
// run (parallel::distributed_solver). Used by parallel/distributed_checkpoint.hpp and
// parallel/distributed_rereference.hpp.

#include <algorithm>
#include <cstring>
#include <iterator>
#include <ranges>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <mpi.h>

#include <rkpm/io/checkpoint.hpp>
#include <rkpm/io/checkpoint_layout.hpp>
#include <rkpm/parallel/communicator.hpp>
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
template <class Run>
io::checkpoint_identity whole_identity(const Run& run, std::string_view configuration) {
  const auto& s = run.solver();
  return {std::string(configuration), run.plan().global_particles, run.plan().global_points,
          static_cast<index_t>(s.slave_particles().size()), static_cast<index_t>(std::ranges::size(s.contact().tools()))};
}

}  // namespace rkpm::parallel
