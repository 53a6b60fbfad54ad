#pragma once
// The forward exchange of a step (docs/method.md section 9.8), over the fixed lists of a halo
// plan (parallel/halo.hpp):
//   halo_exchange::forward(fields...)   owned values -> the ranks that hold them as ghosts
//   halo_exchange::forward_rows(v, w)   the same for w doubles per particle
// (The sums across ranks, the other thing that moves in a step: parallel/mpi_block_sums.hpp.)
// It begins with communicator::agree(), so an error kept on one rank (communicator::guarded) is
// thrown on every rank there (parallel/communicator.hpp). Values are copied, never added in
// transit, so what arrives does not depend on the message timing; the buffers are sized once
// and reused (no allocation per step once the widest field set has been sent).
// Needs MPI (the opt-in target rkpm::mpi).

#include <cstring>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include <mpi.h>

#include <rkpm/core/error.hpp>
#include <rkpm/core/execution.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/parallel/communicator.hpp>
#include <rkpm/parallel/halo.hpp>

namespace rkpm::parallel {

namespace detail {

// Doubles per value of a per-particle field: double, or a fixed-size Eigen vector of doubles.
template <class T>
constexpr int field_width() {
  if constexpr (std::is_same_v<T, double>)
    return 1;
  else {
    static_assert(std::is_same_v<typename T::Scalar, double> && T::SizeAtCompileTime > 0,
                  "forward: a field is a std::vector of double or of a fixed-size Eigen vector of double");
    return T::SizeAtCompileTime;
  }
}
template <class T>
const double* field_data(const T& v) {
  if constexpr (std::is_same_v<T, double>)
    return &v;
  else
    return v.data();
}
template <class T>
double* field_data(T& v) {
  if constexpr (std::is_same_v<T, double>)
    return &v;
  else
    return v.data();
}

// One message per linked rank; the tag keeps them apart from anything else on the communicator.
inline constexpr int halo_tag = 2111;

}  // namespace detail

// The forward exchange of a halo plan: after the owners update their particles, every ghost
// gets its owner's value. Fields are indexed by local id (owned, then ghosts: halo_plan::own()).
// Made once per plan, collectively (a plan that is not this rank's is an error on every rank).
class halo_exchange {
 public:
  halo_exchange(communicator& comm, halo_plan plan) : comm_(comm), plan_(std::move(plan)) {
    comm.guarded([&] {
      if (comm.size() != plan_.ranks || comm.rank() != plan_.rank)
        fail("halo exchange: the plan is rank {} of {} but this process is rank {} of {}; make the plan with "
             "the communicator's rank and as many parts as processes",
             plan_.rank, plan_.ranks, comm.rank(), comm.size());
    });
    comm.agree();
    send_.resize(plan_.sends.size());
    receive_.resize(plan_.receives.size());
    requests_.resize(plan_.sends.size() + plan_.receives.size());
  }

  const halo_plan& plan() const { return plan_; }

  // Collective: agrees on errors first (communicator::agree), then copies the owned values of
  // every field into the ghosts of the ranks that hold them. A field of the wrong length is an
  // error on every rank.
  template <class... Fields>
  void forward(std::vector<Fields>&... fields) {
    constexpr int width = (0 + ... + detail::field_width<Fields>());
    index_t wrong = -1;
    ((wrong < 0 && static_cast<index_t>(fields.size()) != plan_.local_particles()
          ? wrong = static_cast<index_t>(fields.size())
          : 0),
     ...);
    exchange(
        width, wrong, [&](double*& out, stored_index i) { (pack(out, fields[i]), ...); },
        [&](const double*& in, stored_index i) { (unpack(in, fields[i]), ...); });
  }

  // The same for a field of `width` doubles per particle, row after row (a snapshot's arrays of
  // 1, 3 or 9 components: parallel/snapshot_pieces.hpp).
  void forward_rows(std::vector<double>& rows, int width) {
    const auto w = static_cast<std::size_t>(width);
    const index_t values = static_cast<index_t>(rows.size() / w);
    exchange(
        width, rows.size() == w * static_cast<std::size_t>(plan_.local_particles()) ? -1 : values,
        [&](double*& out, stored_index i) {
          std::memcpy(out, rows.data() + w * static_cast<std::size_t>(i), w * sizeof(double));
          out += w;
        },
        [&](const double*& in, stored_index i) {
          std::memcpy(rows.data() + w * static_cast<std::size_t>(i), in, w * sizeof(double));
          in += w;
        });
  }

 private:
  // forward's messages: `wrong` >= 0 is a field's length that is not one value per local particle.
  template <class Pack, class Unpack>
  void exchange(int width, index_t wrong, Pack&& pack_particle, Unpack&& unpack_particle) {
    comm_.guarded([&] {
      if (wrong >= 0)
        fail("forward: a field has {} values but rank {} has {} local particles (owned and ghosts); size "
             "per-particle fields by halo_plan::local_particles()",
             wrong, plan_.rank, plan_.local_particles());
    });
    comm_.agree();
    for (std::size_t k = 0; k < plan_.receives.size(); ++k) {
      std::vector<double>& buffer = receive_[k];
      buffer.resize(plan_.receives[k].particles.size() * width);
      MPI_Irecv(buffer.data(), static_cast<int>(buffer.size()), MPI_DOUBLE, plan_.receives[k].rank,
                detail::halo_tag, comm_.get(), &requests_[k]);
    }
    for (std::size_t k = 0; k < plan_.sends.size(); ++k) {
      std::vector<double>& buffer = send_[k];
      buffer.resize(plan_.sends[k].particles.size() * width);
      double* out = buffer.data();
      for (const stored_index i : plan_.sends[k].particles) pack_particle(out, i);
      MPI_Isend(buffer.data(), static_cast<int>(buffer.size()), MPI_DOUBLE, plan_.sends[k].rank, detail::halo_tag,
                comm_.get(), &requests_[plan_.receives.size() + k]);
    }
    MPI_Waitall(static_cast<int>(requests_.size()), requests_.data(), MPI_STATUSES_IGNORE);
    for (std::size_t k = 0; k < plan_.receives.size(); ++k) {
      const double* in = receive_[k].data();
      for (const stored_index i : plan_.receives[k].particles) unpack_particle(in, i);
    }
  }

  template <class T>
  static void pack(double*& out, const T& v) {
    constexpr int w = detail::field_width<T>();
    std::memcpy(out, detail::field_data(v), w * sizeof(double));
    out += w;
  }
  template <class T>
  static void unpack(const double*& in, T& v) {
    constexpr int w = detail::field_width<T>();
    std::memcpy(detail::field_data(v), in, w * sizeof(double));
    in += w;
  }
  communicator& comm_;
  halo_plan plan_;
  std::vector<std::vector<double>> send_, receive_;
  std::vector<MPI_Request> requests_;
};

}  // namespace rkpm::parallel
