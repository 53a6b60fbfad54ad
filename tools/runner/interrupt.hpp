#pragma once
// Ctrl-C (SIGINT) and SIGTERM stop rkpm_run between two steps instead of at once: the handler
// only records the signal; the run observer sees it after the step under way, and the run ends
// with a checkpoint to continue from (--restart) and its outputs complete up to that step.
// A second signal while the first is pending ends the program at once, as usual.

#include <atomic>
#include <csignal>

namespace rkpm::runner {

inline std::atomic<int>& pending_interrupt() {
  static std::atomic<int> signal_number{0};
  return signal_number;
}

extern "C" inline void record_interrupt(int signal_number) {
  if (pending_interrupt().exchange(signal_number) != 0) {
    std::signal(signal_number, SIG_DFL);
    std::raise(signal_number);
  }
}

inline void stop_between_steps_on_interrupt() {
  std::signal(SIGINT, record_interrupt);
  std::signal(SIGTERM, record_interrupt);
}

}  // namespace rkpm::runner
