#pragma once
// process_group: what the time step needs from the other processes of a run, and nothing else
// (docs/method.md sections 9.7 and 9.8). One process has none (discrete_model::own.group is
// null) and the step runs as it always has. A backend is one class deriving from this, in one
// header: parallel/mpi_process_group.hpp runs it on MPI. The library's step calls it at fixed
// places, on every process in the same order, so a backend may make every call collective:
//   forward        the owned particles' values to the processes that hold them as ghosts
//   sum_particles  K sums over every process's owned particles, equal to one process's
//                  block_sums<K> over all particles, bit for bit (core/block_sums.hpp)
//   sum_points     one sum over every process's owned points, equal to one process's per-tile
//                  sum over the traversal (solver/point_materials.hpp), bit for bit
//   max, min       order-free reductions
//   guarded        work that may fail on one process alone (the force loop): its error is kept
//                  and thrown on every process, with the same message, from the next call above
// Declared without MPI, so that the library and a one-process build need none.

#include <functional>
#include <span>
#include <vector>

#include <rkpm/core/types.hpp>

namespace rkpm {

class process_group {
 public:
  virtual ~process_group() = default;

  virtual int rank() const = 0;
  virtual int size() const = 0;

  // Every ghost of these per-particle fields (local ids: owned, then ghosts) gets its owner's value.
  virtual void forward(std::vector<vec2>& a) = 0;
  virtual void forward(std::vector<vec2>& a, std::vector<vec2>& b) = 0;
  virtual void forward(std::vector<double>& a) = 0;
  // How the owned particles fall into the blocks of the one-process sum (core/block_sums.hpp):
  // the blocks this process owns whole (the first owned particle and the count of each, in
  // block order), which it sums itself from zero in particle order as one process does, and
  // the owned particles of the other blocks (increasing), whose terms it keeps.
  struct owned_blocks {
    std::vector<index_t> whole_first, whole_size;
    std::vector<stored_index> partial;
  };
  virtual const owned_blocks& particle_blocks() const = 0;
  // totals[k] (K = totals.size(): 1 or 2) over every process's owned particles, from this
  // process's whole blocks' sums (K each, in particle_blocks() order) and its partial
  // particles' terms (K per owned particle, terms[i K + k] for particle i; only the partial
  // particles' entries are read).
  virtual void sum_particles(std::span<const double> whole_sums, std::span<const double> terms,
                             std::span<double> totals) = 0;
  // The points this process owns among those it computes (positions in its point list), and the
  // sum over every process of one term per owned point, given in that order.
  virtual const std::vector<stored_index>& owned_points() const = 0;
  virtual double sum_points(std::span<const double> terms) = 0;
  virtual double max(double value) = 0;
  virtual double min(double value) = 0;
  virtual void guarded(const std::function<void()>& work) = 0;
};

}  // namespace rkpm
