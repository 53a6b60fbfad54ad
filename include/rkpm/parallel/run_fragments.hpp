#pragma once
// The pieces of a run on P processes counted from the ranks' parts (docs/method.md sections 5.12
// and 9.8): one process's crack_fragments (solver/crack_growth.hpp) bit for bit, on every rank.
//   part_fragments(comm, part, physical_mass)   collective
// crack_fragments joins two particles when a point's row holds both and roots each piece at its
// smallest particle index. Here each piece is labelled by that index: every rank joins the
// particles of its points' rows (a union-find over its part, once) and gives each owned
// particle the smallest label in its set (row_pieces, solver/crack_growth.hpp); the owners forward their labels to the ghosts, and
// again, until no rank lowers a label (an MPI_MAX). A point whose row holds particles of two
// ranks is computed by both (the redundant points of parallel/halo.hpp), so every link is seen
// by both particles' owners, and at the end every piece carries one label, its smallest index.
// A label crosses one cut per round: the rounds are the most cuts a piece's smallest particle
// is from one of its particles, plus one. Then every rank gathers each owned particle's (index,
// label, mass) (MPI_Allgatherv) and adds the pieces' masses in index order, as crack_fragments
// does. Cost: the rounds' forwards and maxima, and the gather of three values a particle.

#include <algorithm>
#include <limits>
#include <numeric>
#include <vector>

#include <mpi.h>

#include <rkpm/core/process_group.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/parallel/communicator.hpp>
#include <rkpm/solver/crack_growth.hpp>
#include <rkpm/solver/discrete_model.hpp>

namespace rkpm::parallel {

// `part`: a rank's model (parallel/local_model.hpp, its process group set); `mass`: the part's
// physical masses (#particles of the part, owned first).
inline fragment_count part_fragments(communicator& comm, const discrete_model& part, const std::vector<double>& mass) {
  const index_t n = part.particle_count(), owned = part.own.particles.end;
  // The part's sets: particles joined by its points' rows.
  const std::vector<index_t> root = row_pieces(part);
  // The labels, global indices (exact in a double below 2^53), lowered until no rank lowers one.
  std::vector<double> label(n), smallest(n);
  for (index_t i = 0; i < n; ++i) label[i] = static_cast<double>(part.global_particle(i));
  for (;;) {
    std::fill(smallest.begin(), smallest.end(), std::numeric_limits<double>::infinity());
    for (index_t i = 0; i < n; ++i) smallest[root[i]] = std::min(smallest[root[i]], label[i]);
    bool lowered = false;
    for (index_t i = 0; i < owned; ++i)
      if (smallest[root[i]] < label[i]) {
        label[i] = smallest[root[i]];
        lowered = true;
      }
    part.own.group->forward(label);
    if (!(part.own.group->max(lowered ? 1.0 : 0.0) > 0.0)) break;
  }
  // Every owned particle's (index, label, mass) on every rank, then the sums in index order.
  std::vector<double> mine(3 * static_cast<std::size_t>(owned));
  for (index_t i = 0; i < owned; ++i) {
    mine[3 * i] = static_cast<double>(part.global_particle(i));
    mine[3 * i + 1] = label[i];
    mine[3 * i + 2] = mass[i];
  }
  const int count = static_cast<int>(mine.size());
  std::vector<int> counts(comm.size()), displacements(comm.size(), 0);
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm.get());
  for (int r = 1; r < comm.size(); ++r) displacements[r] = displacements[r - 1] + counts[r - 1];
  std::vector<double> all(static_cast<std::size_t>(displacements.back() + counts.back()));
  MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), displacements.data(), MPI_DOUBLE,
                 comm.get());
  const std::size_t whole = all.size() / 3;
  std::vector<index_t> label_of(whole);
  std::vector<double> mass_of(whole), piece(whole, 0.0);
  for (std::size_t k = 0; k < whole; ++k) {
    const auto I = static_cast<std::size_t>(all[3 * k]);
    label_of[I] = static_cast<index_t>(all[3 * k + 1]);
    mass_of[I] = all[3 * k + 2];
  }
  fragment_count out;
  for (std::size_t I = 0; I < whole; ++I) {
    if (label_of[I] == static_cast<index_t>(I)) ++out.pieces;
    piece[label_of[I]] += mass_of[I];
  }
  out.largest_mass = *std::max_element(piece.begin(), piece.end());
  return out;
}

}  // namespace rkpm::parallel
