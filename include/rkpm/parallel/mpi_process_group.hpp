#pragma once
// mpi_process_group: the process_group of the time step (core/process_group.hpp) on MPI, over one
// rank's plans (docs/method.md section 9.8):
//   forward        halo_exchange::forward along the halo plan (parallel/mpi_exchange.hpp)
//   sum_particles  global_block_sums<K>::combine (parallel/mpi_block_sums.hpp) over the
//                  particle partition, blocks of block_sums' size (the blocks a rank owns
//                  whole summed by the caller)
//   sum_points     global_block_sums<1> over the points' owners (point_owners), blocks of the
//                  traversal's tiles
//   max, min, guarded, agree   the communicator's
// Every call is collective and begins with communicator::agree(), so an error kept by guarded()
// on one rank is thrown on every rank from the same call. Made once per run, collectively.

#include <functional>
#include <span>
#include <vector>

#include <rkpm/core/block_sums.hpp>
#include <rkpm/core/error.hpp>
#include <rkpm/core/process_group.hpp>
#include <rkpm/discretization/point_traversal.hpp>
#include <rkpm/discretization/shape_table.hpp>
#include <rkpm/parallel/communicator.hpp>
#include <rkpm/parallel/global_blocks.hpp>
#include <rkpm/parallel/halo.hpp>
#include <rkpm/parallel/mpi_block_sums.hpp>
#include <rkpm/parallel/mpi_exchange.hpp>
#include <rkpm/parallel/partition.hpp>

namespace rkpm::parallel {

class mpi_process_group final : public process_group {
 public:
  // `at_points`: the whole model's rows at the points (its table, or search_rows), which the
  // plan was made from.
  template <ColumnRows Rows>
  mpi_process_group(communicator& comm, const particle_partition& particles, halo_plan plan, const Rows& at_points)
      : mpi_process_group(comm, particles, std::move(plan), point_owners(particles, at_points)) {}

  int rank() const override { return comm_.rank(); }
  int size() const override { return comm_.size(); }
  const halo_plan& plan() const { return halo_.plan(); }
  communicator& comm() const { return comm_; }

  void forward(std::vector<vec2>& a) override { halo_.forward(a); }
  void forward(std::vector<vec2>& a, std::vector<vec2>& b) override { halo_.forward(a, b); }
  void forward(std::vector<double>& a) override { halo_.forward(a); }

  const owned_blocks& particle_blocks() const override { return blocks_; }
  void sum_particles(std::span<const double> whole_sums, std::span<const double> terms,
                     std::span<double> totals) override {
    if (totals.size() == 1) {
      totals[0] = particle_sums_1_.combine(whole_sums, terms)[0];
      return;
    }
    if (totals.size() != 2)
      fail("process group: {} sums at once over the particles; 1 or 2 are available", totals.size());
    const auto s = particle_sums_2_.combine(whole_sums, terms);
    totals[0] = s[0];
    totals[1] = s[1];
  }
  const std::vector<stored_index>& owned_points() const override { return owned_points_; }
  double sum_points(std::span<const double> terms) override {
    return point_sums_([&](index_t i, global_block_sums<1>::sums& t) { t[0] += terms[i]; })[0];
  }
  double max(double value) override { return comm_.max(value); }
  double min(double value) override { return comm_.min(value); }
  void guarded(const std::function<void()>& work) override { comm_.guarded(work); }
  void agree() { comm_.agree(); }

  // `point_owner`: every point's owner (point_owners), when the caller has it.
  mpi_process_group(communicator& comm, const particle_partition& particles, halo_plan plan,
                    const particle_partition& point_owner)
      : comm_(comm),
        owned_points_(owned_point_positions(plan, point_owner)),
        halo_(comm, std::move(plan)),
        particle_sums_1_(comm, make_global_block_plan(particles, comm.rank(), block_sums<1>::block_size)),
        particle_sums_2_(comm, make_global_block_plan(particles, comm.rank(), block_sums<2>::block_size)),
        point_sums_(comm, make_global_block_plan(point_owner, comm.rank(), traversal_tile_points),
                    traversal_tile_points) {
    const global_block_plan& p = particle_sums_2_.plan();  // the blocks of 1 and 2 sums are the same
    blocks_ = {p.whole_first, p.whole_size, p.partial};
  }

 private:
  communicator& comm_;
  owned_blocks blocks_;
  std::vector<stored_index> owned_points_;
  halo_exchange halo_;
  global_block_sums<1> particle_sums_1_;
  global_block_sums<2> particle_sums_2_;
  global_block_sums<1> point_sums_;
};

}  // namespace rkpm::parallel
