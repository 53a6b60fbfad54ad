#pragma once
// Checkpoints in parts of a run on P processes (docs/method.md section 9.5; the files:
// io/checkpoint_parts.hpp): no rank gathers anything whole.
//   write_checkpoint_parts(run, folder, configuration, description)   collective; rank K writes
//       folder/part-K-of-P.rkpmcp: its owned particles' and points' values with their global
//       indices, and the sections every rank holds whole
//   read_checkpoint_parts(run, folder, configuration)   collective; on any number of processes,
//       each rank takes its particles' and points' values (ghosts included) from the parts
// A one-process solver reads a folder of parts through rkpm::read_checkpoint (solver/checkpoint.hpp).
// A refused set (a part missing, damaged, or of another checkpoint) is refused on every rank with
// the same line naming the part (communicator::agree), the run unchanged.

#include <cstdint>
#include <filesystem>
#include <numeric>
#include <string_view>
#include <system_error>
#include <utility>

#include <rkpm/core/error.hpp>
#include <rkpm/io/checkpoint.hpp>
#include <rkpm/io/checkpoint_parts.hpp>
#include <rkpm/parallel/distributed_checkpoint.hpp>
#include <rkpm/parallel/distributed_solver.hpp>
#include <rkpm/solver/checkpoint.hpp>

namespace rkpm::parallel {

namespace detail {

// Puts the folder `writing` in place of `folder` (a folder of parts or a file of the same name
// from before is removed once the new one is in place).
inline void replace_folder(const std::filesystem::path& writing, const std::filesystem::path& folder) {
  std::filesystem::path old = folder;
  old += ".old";
  std::error_code ec;
  std::filesystem::remove_all(old, ec);
  if (std::filesystem::exists(folder)) std::filesystem::rename(folder, old, ec);
  if (ec) fail("cannot move the previous checkpoint '{}' aside: {}", folder.string(), ec.message());
  std::filesystem::rename(writing, folder, ec);
  if (ec) fail("cannot rename '{}' to '{}': {}", writing.string(), folder.string(), ec.message());
  std::filesystem::remove_all(old, ec);
}

}  // namespace detail

// Collective: every rank writes its part into folder + ".writing", which rank 0 renames to
// `folder` once every part is in it; every rank returns once it is in place (or throws the same
// error).
template <class Solver>
void write_checkpoint_parts(distributed_solver<Solver>& run, const std::filesystem::path& folder,
                            std::string_view configuration, std::string_view description = {}) {
  mpi_process_group& group = run.group();
  const halo_plan& plan = group.plan();
  const Solver& s = run.solver();
  std::filesystem::path writing = folder;
  writing += ".writing";
  group.guarded([&] {
    if (group.rank() != 0) return;
    std::filesystem::remove_all(writing);
    std::filesystem::create_directories(writing);
  });
  group.agree();
  group.guarded([&] {
    // Owned particles are the local ones first; owned points are the group's (point owners).
    io::checkpoint_whole_array particles{checkpoint_particle_sections, std::vector<stored_index>(plan.owned.size()),
                                         plan.owned};
    std::iota(particles.local.begin(), particles.local.end(), stored_index{0});
    io::checkpoint_whole_array points{checkpoint_point_sections, group.owned_points(), {}};
    for (const stored_index k : points.local) points.global.push_back(plan.points[k]);
    io::checkpoint_part_layout layout(std::move(particles), std::move(points));
    const auto K = static_cast<std::uint64_t>(group.rank()), P = static_cast<std::uint64_t>(group.size());
    io::checkpoint_writer w(io::checkpoint_part_path(writing, K, P), whole_identity(run, configuration), description,
                            &layout);
    layout.open_part(w, {K, P, static_cast<std::uint64_t>(s.steps()), s.time()});
    w.array("solver.mass", s.mass());
    w.part(s);
    w.commit();
  });
  group.agree();
  group.guarded([&] {
    if (group.rank() == 0) detail::replace_folder(writing, folder);
  });
  group.agree();
}

// Collective: every rank reads the parts (written on any number of processes) and takes the
// values of its particles and points. Refused on every rank alike, the run unchanged.
template <class Solver>
void read_checkpoint_parts(distributed_solver<Solver>& run, const std::filesystem::path& folder,
                           std::string_view configuration) {
  if (run.rereferences_through_whole()) return run.read_whole(folder, configuration);  // as read_checkpoint
  run.group().guarded([&] {
    const discrete_model& part = run.solver().model();
    io::checkpoint_parts parts(folder, whole_identity(run, configuration),
                               {checkpoint_particle_sections, {}, part.particle_id},
                               {checkpoint_point_sections, {}, part.point_id});
    load_checkpoint(run.solver(), parts.reader());
  });
  run.group().agree();
}

}  // namespace rkpm::parallel
