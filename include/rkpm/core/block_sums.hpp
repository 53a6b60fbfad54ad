#pragma once
// block_sums<K>: K sums over an index range 0 .. n-1 that come out the same whatever the thread
// count. The range is cut into blocks of a fixed size; the blocks run in parallel, each summing
// its indices in order, and then the blocks' sums are added in block order. A plain OpenMP
// reduction would add the threads' partial sums in an order that depends on the thread count,
// and a serial loop leaves the other cores idle while the solver's sums over the particles
// (the energy ledger, the kinetic energy) run, a part of every step that would not shrink with
// the threads (docs/performance.md).
//
//   block_sums<2> sums(n);
//   const auto [a, b] = sums([&](index_t I, std::array<double, 2>& s) { x[I] += ...; s[0] += ...; s[1] += ...; });
//
// The body may do other per-index work (it runs once for every index), so one pass over the
// particles can update them and sum at once. No allocation after construction.
//
// On several processes (a process_group, core/process_group.hpp) the indices are this process's
// owned particles. The blocks of the whole model's particles that it owns whole are summed here
// as one process sums them; the other particles' terms are kept, and the group adds everything
// over all processes to the totals one process's blocks give, bit for bit. A body therefore adds
// at most one term to each s[k] per index, as the library's bodies do.

#include <algorithm>
#include <array>
#include <memory>
#include <type_traits>
#include <vector>

#include <rkpm/core/process_group.hpp>
#include <rkpm/core/single_thread.hpp>
#include <rkpm/core/types.hpp>

namespace rkpm {

template <int K>
class block_sums {
 public:
  using sums = std::array<double, K>;
  // Indices per block: a few thousand, so a block is one chunk of work for a thread and its
  // partial sums are a negligible extra store.
  static constexpr index_t block_size = 2048;

  block_sums() = default;
  explicit block_sums(index_t n, process_group* group = nullptr)
      : n_(n), partial_(static_cast<std::size_t>((n + block_size - 1) / block_size)), group_(group) {
    if (group_) terms_.resize(static_cast<std::size_t>(n * K));
  }

  index_t size() const { return n_; }

  // Calls body(I, s) for every I, s the sums of I's block; returns the K totals.
  template <class Body>
  sums operator()(Body&& body) const {
    if (group_) {
      // Through a plain function pointer: the loops below are compiled once per K, not once per
      // body of every solver type (they run only on several processes).
      using B = std::remove_reference_t<Body>;
      return across_processes({const_cast<void*>(static_cast<const void*>(std::addressof(body))),
                               [](void* b, index_t I, sums& s) { (*static_cast<B*>(b))(I, s); }});
    }
    const index_t blocks = static_cast<index_t>(partial_.size());
#pragma omp parallel for schedule(static) if (!exec::single_thread())
    for (index_t b = 0; b < blocks; ++b) {
      sums s{};
      const index_t last = std::min(n_, (b + 1) * block_size);
      for (index_t I = b * block_size; I < last; ++I) body(I, s);
      partial_[b] = s;
    }
    sums total{};
    for (const sums& s : partial_)
      for (int k = 0; k < K; ++k) total[k] += s[k];
    return total;
  }

 private:
  // A body, called through a pointer.
  struct body_ref {
    void* body;
    void (*call)(void*, index_t, sums&);
    void operator()(index_t I, sums& s) const { call(body, I, s); }
  };

  sums across_processes(body_ref body) const {
    const process_group::owned_blocks& blocks = group_->particle_blocks();
    const auto whole = static_cast<index_t>(blocks.whole_first.size());
    const auto partial = static_cast<index_t>(blocks.partial.size());
    whole_sums_.resize(static_cast<std::size_t>(whole * K));
#pragma omp parallel for schedule(static) if (!exec::single_thread())
    for (index_t w = 0; w < whole; ++w) {
      sums s{};
      for (index_t I = blocks.whole_first[w]; I < blocks.whole_first[w] + blocks.whole_size[w]; ++I) body(I, s);
      for (int k = 0; k < K; ++k) whole_sums_[static_cast<std::size_t>(w * K + k)] = s[k];
    }
#pragma omp parallel for schedule(static) if (!exec::single_thread())
    for (index_t j = 0; j < partial; ++j) {
      const index_t I = blocks.partial[j];
      sums s{};
      body(I, s);
      for (int k = 0; k < K; ++k) terms_[static_cast<std::size_t>(I * K + k)] = s[k];
    }
    sums total{};
    group_->sum_particles(whole_sums_, terms_, total);
    return total;
  }

  index_t n_ = 0;
  mutable std::vector<sums> partial_;  // one per block
  process_group* group_ = nullptr;
  mutable std::vector<double> terms_, whole_sums_;  // with a group: K per index, K per whole block
};

}  // namespace rkpm
