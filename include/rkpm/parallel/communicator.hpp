#pragma once
// MPI for the decomposition (docs/method.md section 9.8): the session that starts and ends MPI,
// and the communicator the exchanges go through, with the rule that keeps a failure on one
// process from leaving the others waiting.
//
// How an error reaches every process. An exception on one rank (a NaN, an inverted point) would
// leave the other ranks waiting forever in their next exchange, which this rank never reaches.
// So the work between two exchanges runs inside communicator::guarded(work): an exception is
// kept, not thrown, and the rank goes on to the next exchange. Every exchange and reduction
// (mpi_exchange.hpp, mpi_block_sums.hpp) begins with agree(): one MPI_Allreduce of the lowest
// failing rank; if any rank failed, that rank's message is broadcast and every rank throws the same rank_failure
// ("rank 1: ..."), from the same call, so each can stop cleanly (and MPI_Finalize). An error
// thrown outside guarded() that escapes to the mpi_session's scope ends the job with MPI_Abort
// (the session's destructor sees it unwinding), and one that escapes main makes the process
// terminate, which mpiexec turns into the end of every process: no rank is left hanging, but
// only the agreed path stops cleanly with the same message everywhere.
// MPI's own errors are fatal (MPI_ERRORS_ARE_FATAL, the default): they abort the job.
// Needs MPI (Debian libopenmpi-dev; the opt-in target rkpm::mpi links it).

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>
#include <utility>

#include <mpi.h>

#include <rkpm/core/error.hpp>

namespace rkpm::parallel {

// The error every rank throws when one failed: the failing rank's message, prefixed by its rank.
// The live count lets mpi_session tell an agreed failure from a local one while unwinding.
class rank_failure : public error {
 public:
  rank_failure(int rank, const std::string& what) : error(what), rank_(rank) { ++live(); }
  rank_failure(const rank_failure& other) : error(other), rank_(other.rank_) { ++live(); }
  rank_failure& operator=(const rank_failure&) = default;
  ~rank_failure() override { --live(); }
  int rank() const { return rank_; }
  // How many rank_failure objects exist (thrown, or held by a handler) on this process.
  static int& live() {
    static int count = 0;
    return count;
  }

 private:
  int rank_;
};

// Starts MPI for a program (MPI_Init_thread: MPI is called from the main thread only, OpenMP
// threads never call it) and ends it when the session goes out of scope. If the scope is left
// by an exception that the ranks did not agree on (not a rank_failure), the other ranks may be
// waiting for this one: MPI_Abort ends them all instead of MPI_Finalize.
class mpi_session {
 public:
  mpi_session(int& argc, char**& argv) : exceptions_(std::uncaught_exceptions()) { start(&argc, &argv); }
  // Without main's arguments (MPI does not need them): e.g. a session object of static storage
  // duration, which begins before main and ends after it.
  mpi_session() : exceptions_(std::uncaught_exceptions()) { start(nullptr, nullptr); }
  mpi_session(const mpi_session&) = delete;
  mpi_session& operator=(const mpi_session&) = delete;
  ~mpi_session() {
    // Unwinding with no agreed failure in flight: the exception may be on this rank alone,
    // with the others in a collective call this rank will not make.
    if (std::uncaught_exceptions() > exceptions_ && rank_failure::live() == 0) {
      int rank = 0;
      MPI_Comm_rank(MPI_COMM_WORLD, &rank);
      std::fprintf(stderr, "rkpm: rank %d left MPI with an error the other ranks did not agree on (thrown outside "
                           "communicator::guarded); ending every rank (MPI_Abort)\n", rank);
      MPI_Abort(MPI_COMM_WORLD, 1);
    }
    MPI_Finalize();
  }

 private:
  static void start(int* argc, char*** argv) {
    int initialized = 0;
    MPI_Initialized(&initialized);
    if (initialized) fail("MPI is already initialized: make one rkpm::parallel::mpi_session per program");
    int provided = 0;
    MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
    if (provided < MPI_THREAD_FUNNELED) {
      MPI_Finalize();
      fail("this MPI library does not support MPI_THREAD_FUNNELED (OpenMP threads beside MPI calls)");
    }
  }

  int exceptions_;
};

// A communicator and the error agreement of the exchanges that use it.
class communicator {
 public:
  explicit communicator(MPI_Comm comm = MPI_COMM_WORLD) : comm_(comm) {
    MPI_Comm_rank(comm_, &rank_);
    MPI_Comm_size(comm_, &size_);
  }
  // One error state per communicator: a copy would keep an error its original never agrees on.
  communicator(const communicator&) = delete;
  communicator& operator=(const communicator&) = delete;

  MPI_Comm get() const { return comm_; }
  int rank() const { return rank_; }
  int size() const { return size_; }

  // Runs work(); an exception it throws is kept for the next agree() instead of leaving this
  // rank (the first one kept; later ones are dropped). A rank_failure, which an agree() inside
  // work threw on every rank alike, goes on.
  template <class Work>
  void guarded(Work&& work) {
    try {
      std::forward<Work>(work)();
    } catch (const rank_failure&) {
      throw;  // already agreed: every rank throws it from the same collective call
    } catch (const std::exception& e) {
      if (!failed_) pending_ = e.what();
      failed_ = true;
    } catch (...) {
      if (!failed_) pending_ = "an exception that is not a std::exception";
      failed_ = true;
    }
  }
  bool failed() const { return failed_; }

  // Collective: throws rank_failure on every rank if any rank holds a kept error, naming the
  // lowest such rank and its message (and how many ranks failed). One MPI_Allreduce when none did.
  void agree() {
    int first = failed_ ? rank_ : size_;
    MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, comm_);
    if (first == size_) return;
    int failing = failed_ ? 1 : 0;
    MPI_Allreduce(MPI_IN_PLACE, &failing, 1, MPI_INT, MPI_SUM, comm_);
    std::string message = rank_ == first ? pending_ : std::string();
    int length = static_cast<int>(message.size());
    MPI_Bcast(&length, 1, MPI_INT, first, comm_);
    message.resize(length);
    MPI_Bcast(message.data(), length, MPI_CHAR, first, comm_);
    failed_ = false;
    pending_.clear();
    throw rank_failure(first, failing > 1 ? fmt::format("rank {} (and {} more of {} ranks): {}", first, failing - 1,
                                                        size_, message)
                                          : fmt::format("rank {} of {}: {}", first, size_, message));
  }

  // Collective: rank 0's `bytes` on every rank (in pieces below 2^31 bytes). No agree(): the
  // caller's, before it, when rank 0 made them inside guarded().
  void broadcast(std::string& bytes) {
    std::uint64_t size = bytes.size();
    MPI_Bcast(&size, 1, MPI_UINT64_T, 0, comm_);
    bytes.resize(size);
    constexpr std::uint64_t piece = std::uint64_t{1} << 30;
    for (std::uint64_t at = 0; at < size; at += piece)
      MPI_Bcast(bytes.data() + at, static_cast<int>(std::min(piece, size - at)), MPI_BYTE, 0, comm_);
  }

  // Order-free reductions (the largest and smallest value are the same in any order), after agree().
  double max(double value) {
    agree();
    MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MAX, comm_);
    return value;
  }
  double min(double value) {
    agree();
    MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MIN, comm_);
    return value;
  }

 private:
  MPI_Comm comm_;
  int rank_ = 0, size_ = 1;
  bool failed_ = false;
  std::string pending_;
};

}  // namespace rkpm::parallel
