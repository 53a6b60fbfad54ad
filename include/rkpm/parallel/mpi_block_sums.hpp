#pragma once
// The sums of a step across ranks (docs/method.md section 9.8), over the fixed lists of a global
// block plan (parallel/global_blocks.hpp):
//   global_block_sums<K>   per-particle (or per-point) terms summed to the totals one process's
//                          block_sums<K> gives, bit for bit, on any number of ranks
// Each sum begins with communicator::agree(), so an error kept on one rank is thrown on every
// rank there (parallel/communicator.hpp). Terms are copied, never added in transit, so what
// arrives does not depend on the message timing; the buffers are sized once and reused.
// (The forward exchange of owned values to ghosts: parallel/mpi_exchange.hpp.)
// Needs MPI (the opt-in target rkpm::mpi).

#include <array>
#include <span>
#include <utility>
#include <vector>

#include <mpi.h>

#include <rkpm/core/block_sums.hpp>
#include <rkpm/core/error.hpp>
#include <rkpm/core/execution.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/parallel/communicator.hpp>
#include <rkpm/parallel/global_blocks.hpp>

namespace rkpm::parallel {

namespace detail {
// One message per linked rank; the tag keeps them apart from the halo's (mpi_exchange.hpp).
inline constexpr int block_tag = 2112;
}  // namespace detail

// K sums over the owned particles of every rank that equal, bit for bit, one process's
// block_sums<K> over all particles in global order (blocks of block_sums<K>::block_size):
//   global_block_sums<2> sums(comm, make_global_block_plan(partition, comm.rank(), block_sums<2>::block_size));
//   const auto [a, b] = sums([&](index_t i, global_block_sums<2>::sums& t) { t[0] += ...; t[1] += ...; });
// body(i, t) runs once for every owned particle (local id i, in parallel, so it must not throw,
// as block_sums' body must not). In a block this rank owns whole, t is the block's running sum,
// as in block_sums; elsewhere t is zeroed before it and the term kept for the block's collector.
// So a body adds at most one term to each t[k], as block_sums' bodies in the library do (a body
// that added twice to one sum would round differently from one process's running sum). Made
// once per plan, collectively; each sum is collective and agrees on errors first.
template <int K>
class global_block_sums {
 public:
  using sums = std::array<double, K>;

  // one_process_block: the block of the one-process sum to reproduce, block_sums<K>::block_size
  // for the solver's per-particle sums, or traversal_tile_points for point_materials' per-tile
  // sums over the points (a plan over point_owners, parallel/global_blocks.hpp).
  global_block_sums(communicator& comm, global_block_plan plan, index_t one_process_block = block_sums<K>::block_size)
      : comm_(comm), plan_(std::move(plan)) {
    comm.guarded([&] {
      if (comm.size() != plan_.ranks || comm.rank() != plan_.rank)
        fail("global block sums: the plan is rank {} of {} but this process is rank {} of {}; make the plan with "
             "the communicator's rank and as many parts as processes",
             plan_.rank, plan_.ranks, comm.rank(), comm.size());
      if (plan_.block_size != one_process_block)
        fail("global block sums: blocks of {} terms, but the one-process sum uses {}; make the plan with that block "
             "size (block_sums<K>::block_size for per-particle sums)",
             plan_.block_size, one_process_block);
    });
    comm.agree();
    index_t received = 0;
    for (const term_count& c : plan_.receives) received += c.count;
    owned_terms_.resize(plan_.owned * K);
    received_.resize(received * K);
    whole_sums_.resize(plan_.whole_first.size() * K);
    send_.resize(plan_.sends.size());
    requests_.resize(plan_.sends.size() + plan_.receives.size());
    // Where each rank's block sums land in the all-gather: the blocks it collects, in order.
    std::vector<int> collected_by(plan_.ranks, 0);
    for (const int r : plan_.collector) ++collected_by[r];
    counts_.resize(plan_.ranks);
    displacements_.resize(plan_.ranks);
    for (int r = 0, at = 0; r < plan_.ranks; ++r) {
      counts_[r] = collected_by[r] * K;
      displacements_[r] = at;
      at += counts_[r];
    }
    slot_.resize(plan_.blocks());
    std::vector<int> next(displacements_);
    for (index_t b = 0; b < plan_.blocks(); ++b) {
      slot_[b] = next[plan_.collector[b]];
      next[plan_.collector[b]] += K;
    }
    block_sum_.resize(plan_.blocks() * K);
    mine_.resize(plan_.collected.size() * K);
  }

  template <class Body>
  sums operator()(Body&& body) {
    // A whole block is summed from zero in index order where its terms are made, as one process
    // sums it; only the items of the other blocks keep their terms.
    exec::parallel_for(static_cast<index_t>(plan_.whole_first.size()), [&](index_t w) {
      sums s{};
      for (index_t i = plan_.whole_first[w]; i < plan_.whole_first[w] + plan_.whole_size[w]; ++i) body(i, s);
      for (int k = 0; k < K; ++k) whole_sums_[w * K + k] = s[k];
    });
    exec::parallel_for(static_cast<index_t>(plan_.partial.size()), [&](index_t j) {
      const index_t i = plan_.partial[j];
      sums t{};
      body(i, t);
      for (int k = 0; k < K; ++k) owned_terms_[i * K + k] = t[k];
    });
    return combine(whole_sums_, owned_terms_);
  }

  // The totals from this rank's whole blocks' sums (K per block of plan().whole_first) and its
  // owned items' terms (K per owned item; only those of plan().partial are read). Collective.
  sums combine(std::span<const double> whole_sums, std::span<const double> owned_terms) {
    comm_.agree();
    // The terms of straddling blocks to their collectors.
    std::size_t request = 0;
    index_t at = 0;
    for (const term_count& c : plan_.receives) {
      MPI_Irecv(received_.data() + at, static_cast<int>(c.count * K), MPI_DOUBLE, c.rank, detail::block_tag,
                comm_.get(), &requests_[request++]);
      at += c.count * K;
    }
    for (std::size_t k = 0; k < plan_.sends.size(); ++k) {
      std::vector<double>& buffer = send_[k];
      buffer.resize(plan_.sends[k].particles.size() * K);
      double* out = buffer.data();
      for (const stored_index i : plan_.sends[k].particles)
        for (int j = 0; j < K; ++j) *out++ = owned_terms[i * K + j];
      MPI_Isend(buffer.data(), static_cast<int>(buffer.size()), MPI_DOUBLE, plan_.sends[k].rank, detail::block_tag,
                comm_.get(), &requests_[request++]);
    }
    MPI_Waitall(static_cast<int>(request), requests_.data(), MPI_STATUSES_IGNORE);
    // Our blocks, each from zero in index order (as block_sums sums a block).
    const index_t owned = plan_.owned;
    exec::parallel_for(static_cast<index_t>(plan_.collected.size()), [&](index_t k) {
      if (const index_t w = plan_.whole_of_collected[k]; w >= 0) {
        for (int j = 0; j < K; ++j) mine_[k * K + j] = whole_sums[w * K + j];
        return;
      }
      sums s{};
      for (index_t m = plan_.member_offset[k]; m < plan_.member_offset[k + 1]; ++m) {
        const index_t slot = plan_.member_term[m];
        const double* term = slot < owned ? &owned_terms[slot * K] : &received_[(slot - owned) * K];
        for (int j = 0; j < K; ++j) s[j] += term[j];
      }
      for (int j = 0; j < K; ++j) mine_[k * K + j] = s[j];
    });
    // Every block's sum on every rank, added in block order.
    MPI_Allgatherv(mine_.data(), static_cast<int>(mine_.size()), MPI_DOUBLE, block_sum_.data(), counts_.data(),
                   displacements_.data(), MPI_DOUBLE, comm_.get());
    sums total{};
    for (index_t b = 0; b < plan_.blocks(); ++b)
      for (int j = 0; j < K; ++j) total[j] += block_sum_[slot_[b] + j];
    return total;
  }

  const global_block_plan& plan() const { return plan_; }

 private:
  communicator& comm_;
  global_block_plan plan_;
  std::vector<double> owned_terms_, received_;  // K per item: the owned items' (of partial blocks), received
  std::vector<double> whole_sums_;             // K per whole block
  std::vector<std::vector<double>> send_;
  std::vector<MPI_Request> requests_;
  std::vector<int> counts_, displacements_;  // of the all-gather, in doubles
  std::vector<index_t> slot_;                // #blocks: where block b's sums are in block_sum_
  std::vector<double> block_sum_, mine_;
};

}  // namespace rkpm::parallel
