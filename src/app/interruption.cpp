#include "app/interruption.h"

#include <unistd.h>

#include <csignal>
#include <cstring>
#include <stdexcept>

namespace columba {

namespace {

// Signal handlers can only reach globals; lock-free atomics are safe to use in them.
std::atomic<bool> stopRequested{false}, stopsDeferred{false};
std::atomic<int> firstSignal{0};
const char* stoppingMessage = "";
size_t stoppingLength = 0;
struct sigaction previousInterrupt, previousTerminate;
bool guardAlive = false;

extern "C" void onStopSignal(int signal) {
  // Before the work has anything to save, and at a second signal: no waiting.
  if (!stopsDeferred || stopRequested.exchange(true)) _exit(128 + signal);
  firstSignal = signal;
  ssize_t ignored = ::write(STDERR_FILENO, stoppingMessage, stoppingLength);
  (void)ignored;
}

}  // namespace

InterruptionGuard::InterruptionGuard(const char* stopping) {
  if (guardAlive) throw std::logic_error("only one InterruptionGuard may be alive at a time");
  guardAlive = true;
  stopRequested = false;
  stopsDeferred = false;
  firstSignal = 0;
  stoppingMessage = stopping;
  stoppingLength = std::strlen(stopping);
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
  stopsDeferred = false;
  guardAlive = false;
}

void InterruptionGuard::deferStops() { stopsDeferred = true; }

void InterruptionGuard::stopAtOnce() { stopsDeferred = false; }

const std::atomic<bool>& InterruptionGuard::requested() const { return stopRequested; }

int InterruptionGuard::signalNumber() const { return firstSignal; }

}  // namespace columba
