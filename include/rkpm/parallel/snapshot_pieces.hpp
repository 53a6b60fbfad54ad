#pragma once
// A snapshot of a run on P processes written in pieces (docs/method.md sections 9.4 and 9.8):
// every rank writes one .vtu of its own particles and cells, at the same time as the others,
// and rank 0 then writes the .pvtu index that names them (io/pvtu.hpp). ParaView opens the
// index as one data set; put together, the pieces are the snapshot one process writes.
//   snapshot_piece_plan(partition, cells, rank)
//       pure C++: which cells of the whole snapshot (io::snapshot_cells of the whole model) a
//       rank writes and on which points. A cell goes to the owner of its first point; a rank's
//       piece holds its owned particles (increasing global id), then the other ranks' particles
//       its cells use (increasing), whose values their owners forward: a halo_plan of its own
//       (parallel/halo.hpp), so every point a piece holds has its owner's values.
//   snapshot_pieces   the plan and its exchange, made once per run (collective);
//       write(part, pvtu, format) writes the snapshot of the rank's part of the run (collective).
// The values at a rank's owned particles are one process's bit for bit: its part holds every
// point of their supports, in global order (parallel/local_model.hpp), so their projections
// and interpolations add the same terms in the same order. Each piece also holds "particle",
// every point's index in the whole model, which puts the pieces together (a particle on a cell
// boundary between ranks is in several pieces, with the same values). The tools' vertices go
// into piece 0's <FieldData>.
// Needs MPI (the opt-in target rkpm::mpi).

#include <cstdint>
#include <filesystem>
#include <optional>
#include <utility>
#include <vector>

#include <rkpm/core/error.hpp>
#include <rkpm/core/process_group.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/io/point_data.hpp>
#include <rkpm/io/pvtu.hpp>
#include <rkpm/io/solver_output.hpp>
#include <rkpm/io/vtk.hpp>
#include <rkpm/parallel/communicator.hpp>
#include <rkpm/parallel/halo.hpp>
#include <rkpm/parallel/mpi_exchange.hpp>
#include <rkpm/parallel/partition.hpp>
#include <rkpm/solver/fields.hpp>

namespace rkpm::parallel {

struct snapshot_piece {
  halo_plan plan;       // owned: the rank's particles; ghosts: the other ranks' its cells use
  io::vtu_cells cells;  // the rank's cells, on the piece's points (owned, then ghosts)
};

// The piece of `rank`. Every rank makes every rank's assignment alike from the same cells, so
// what one sends is what the other expects; nothing is communicated.
inline snapshot_piece snapshot_piece_plan(const particle_partition& partition, const io::vtu_cells& whole, int rank) {
  const index_t n = partition.particles();
  if (rank < 0 || rank >= partition.parts)
    fail("snapshot pieces: rank {} of a partition into {} parts; run on as many processes as parts", rank,
         partition.parts);
  const std::vector<stored_index>& part = partition.part;
  snapshot_piece s;
  halo_plan& h = s.plan;
  h.rank = rank;
  h.ranks = static_cast<int>(partition.parts);
  h.global_particles = n;
  std::vector<stored_index> local(n, -1);
  for (index_t I = 0; I < n; ++I)
    if (part[I] == rank) {
      local[I] = static_cast<stored_index>(h.owned.size());
      h.owned.push_back(static_cast<stored_index>(I));
    }
  std::vector<char> is_ghost(n, 0);
  std::vector<std::pair<stored_index, stored_index>> to_send;  // (rank, global particle)
  for (std::size_t c = 0, begin = 0; c < whole.size(); begin = static_cast<std::size_t>(whole.offsets[c++])) {
    const auto end = static_cast<std::size_t>(whole.offsets[c]);
    for (std::size_t k = begin; k < end; ++k)
      if (whole.connectivity[k] < 0 || whole.connectivity[k] >= n)
        fail("snapshot pieces: cell {} names point {} of {} particles; make the cells from the partitioned model",
             c, whole.connectivity[k], n);
    const auto writer = part[whole.connectivity[begin]];
    for (std::size_t k = begin; k < end; ++k) {
      const auto I = static_cast<stored_index>(whole.connectivity[k]);
      if (writer == rank && part[I] != rank) is_ghost[I] = 1;
      if (writer != rank && part[I] == rank) to_send.emplace_back(writer, I);
    }
  }
  link_ghosts(h, part, is_ghost, to_send, local);
  for (std::size_t c = 0, begin = 0; c < whole.size(); begin = static_cast<std::size_t>(whole.offsets[c++])) {
    if (part[whole.connectivity[begin]] != rank) continue;
    for (auto k = begin; k < static_cast<std::size_t>(whole.offsets[c]); ++k)
      s.cells.connectivity.push_back(local[whole.connectivity[k]]);
    s.cells.offsets.push_back(static_cast<std::int64_t>(s.cells.connectivity.size()));
    s.cells.types.push_back(whole.types[c]);
  }
  return s;
}

class snapshot_pieces {
 public:
  // Collective: `whole` is the whole model's snapshot cells, alike on every rank.
  snapshot_pieces(communicator& comm, const particle_partition& partition, const io::vtu_cells& whole)
      : comm_(comm) {
    comm.guarded([&] { piece_ = snapshot_piece_plan(partition, whole, comm.rank()); });
    comm.agree();
    exchange_.emplace(comm, piece_.plan);
  }

  const snapshot_piece& piece() const { return piece_; }

  // Collective: this rank's piece of the snapshot `pvtu` (io::pvtu_piece(pvtu, rank)) from its
  // part of the run, `part` (distributed_solver::solver(), on the partition the pieces were made
  // for), then rank 0's index. An error on any rank (a file that cannot be written) is thrown
  // on every rank, and no index names a piece that is not there.
  template <class Solver>
  void write(const Solver& part, const std::filesystem::path& pvtu, const io::vtu_format& format = {}) {
    const halo_plan& h = piece_.plan;
    const auto owned = static_cast<index_t>(h.owned.size()), n = h.local_particles();
    process_group* const group = part.model().own.group;
    comm_.guarded([&] {
      if (!group)
        fail("snapshot pieces: the solver is not a rank's part of a run on several processes (its model has no "
             "process group); give distributed_solver::solver(), or write one process's snapshot with io::write_vtu");
      if (part.model().own.particles.end != owned)
        fail("snapshot pieces: the part owns {} particles but the pieces were made for {}; make them from the "
             "run's partition",
             part.model().own.particles.end, owned);
    });
    comm_.agree();
    // The ghosts' coefficients as their owners have them: between steps a ghost may still hold
    // the value it was sent before the step's last corrections, which only its owner keeps.
    std::vector<vec2> d = part.coefficients(), v = part.coefficient_velocities();
    group->forward(d, v);
    std::vector<vec2> x = positions_at_particles(part.model(), d);
    x.resize(static_cast<std::size_t>(owned));
    x.resize(static_cast<std::size_t>(n), vec2::Zero());
    exchange_->forward(x);
    io::point_data data;
    for (io::point_data::array& a : io::snapshot_fields(part, io::field_arrays::now, {&d, &v}).take()) {
      const auto w = static_cast<std::size_t>(a.components);
      a.values.resize(w * static_cast<std::size_t>(owned));  // the owned rows, then the piece's others
      a.values.resize(w * static_cast<std::size_t>(n));
      exchange_->forward_rows(a.values, a.components);
      data.add_values(std::move(a.name), a.components, std::move(a.values));
    }
    std::vector<double> id(static_cast<std::size_t>(n));
    for (index_t i = 0; i < n; ++i) id[i] = static_cast<double>(h.global_particle(i));
    data.add_values("particle", 1, std::move(id));
    comm_.guarded([&] {
      io::write_vtu(io::pvtu_piece(pvtu, comm_.rank()), std::move(x), io::vtu_cells(piece_.cells), data, format,
                    comm_.rank() == 0 ? io::snapshot_tools(part) : io::point_data{});
    });
    comm_.agree();
    comm_.guarded([&] {
      if (comm_.rank() != 0) return;
      std::vector<std::filesystem::path> pieces;
      for (int r = 0; r < comm_.size(); ++r) pieces.push_back(io::pvtu_piece(pvtu, r));
      io::write_pvtu(pvtu, pieces, data);
    });
    comm_.agree();
  }

 private:
  communicator& comm_;
  snapshot_piece piece_;
  std::optional<halo_exchange> exchange_;
};

}  // namespace rkpm::parallel
