#pragma once
// Stopping a long render from outside: while an InterruptionGuard lives, SIGINT (Ctrl-C) and
// SIGTERM (timeout, batch schedulers, docker stop) ask the work to stop instead of killing the
// process, so that what is done can be saved; a second signal exits at once.
#include <atomic>

namespace columba {

class InterruptionGuard {
 public:
  InterruptionGuard();   // installs the handlers
  ~InterruptionGuard();  // restores the previous ones
  InterruptionGuard(const InterruptionGuard&) = delete;
  InterruptionGuard& operator=(const InterruptionGuard&) = delete;

  // Set by the first signal.
  const std::atomic<bool>& requested() const;
  // The first signal's number, 0 if none came.
  int signalNumber() const;
};

}  // namespace columba
