#include "app/interruption.h"

#include <unistd.h>

#include <csignal>
#include <cstring>
#include <stdexcept>

namespace columba {

namespace {

// Signal handlers can only reach globals; lock-free atomics are safe to use in them.
std::atomic<bool> stopRequested{false};
std::atomic<int> firstSignal{0};
struct sigaction previousInterrupt, previousTerminate;
bool guardAlive = false;

extern "C" void onStopSignal(int signal) {
  if (stopRequested.exchange(true)) _exit(128 + signal);  // the second signal: no more waiting
  firstSignal = signal;
  const char message[] =
      "\nStopping: finishing the current samples and saving the partial image "
      "(interrupt again to quit at once)\n";
  ssize_t ignored = ::write(STDERR_FILENO, message, sizeof message - 1);
  (void)ignored;
}

}  // namespace

InterruptionGuard::InterruptionGuard() {
  if (guardAlive) throw std::logic_error("only one InterruptionGuard may be alive at a time");
  guardAlive = true;
  stopRequested = false;
  firstSignal = 0;
  struct sigaction action;
  std::memset(&action, 0, sizeof action);
  action.sa_handler = onStopSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, &previousInterrupt);
  sigaction(SIGTERM, &action, &previousTerminate);
}

InterruptionGuard::~InterruptionGuard() {
  sigaction(SIGINT, &previousInterrupt, nullptr);
  sigaction(SIGTERM, &previousTerminate, nullptr);
  guardAlive = false;
}

const std::atomic<bool>& InterruptionGuard::requested() const { return stopRequested; }

int InterruptionGuard::signalNumber() const { return firstSignal; }

}  // namespace columba
