#pragma once
// Stopping long work from outside: while an InterruptionGuard lives, SIGINT (Ctrl-C) and SIGTERM
// (timeout, batch schedulers, docker stop) end the process at once (128 + the signal's number)
// while there is nothing to save, such as while a scene loads. Between deferStops() and
// stopAtOnce() the first signal only asks the work to stop, so that what is done can be saved or
// cleaned up; a second signal exits at once.
#include <atomic>

namespace columba {

class InterruptionGuard {
 public:
  // `stopping` is printed at the first signal while stops are deferred: what the work does before
  // it stops. It must outlive the guard (a string literal).
  explicit InterruptionGuard(const char* stopping);  // installs the handlers
  ~InterruptionGuard();                              // restores the previous ones
  InterruptionGuard(const InterruptionGuard&) = delete;
  InterruptionGuard& operator=(const InterruptionGuard&) = delete;

  void deferStops();
  void stopAtOnce();

  // Set by the first signal while stops are deferred.
  const std::atomic<bool>& requested() const;
  // That signal's number, 0 if none came.
  int signalNumber() const;
};

}  // namespace columba
