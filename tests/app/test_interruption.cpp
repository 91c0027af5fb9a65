#include <gtest/gtest.h>

#include <csignal>

#include "app/interruption.h"

using namespace columba;

namespace {
const char* kStopping = "\nStopping (interrupt again to quit at once)\n";
}  // namespace

TEST(Interruption, TheFirstSignalAsksToStopWhileStopsAreDeferred) {
  for (int signal : {SIGINT, SIGTERM}) {
    InterruptionGuard guard(kStopping);
    guard.deferStops();
    EXPECT_FALSE(guard.requested());
    std::raise(signal);
    EXPECT_TRUE(guard.requested());
    EXPECT_EQ(guard.signalNumber(), signal);
  }
}

TEST(InterruptionDeathTest, ASecondSignalExitsAtOnce) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  for (int signal : {SIGINT, SIGTERM}) {
    EXPECT_EXIT(
        {
          InterruptionGuard guard(kStopping);
          guard.deferStops();
          std::raise(signal);
          std::raise(signal);
          std::exit(0);  // not reached
        },
        ::testing::ExitedWithCode(128 + signal), "interrupt again");
  }
}

// While there is nothing to save (a scene loading), and again once stops are no longer deferred.
TEST(InterruptionDeathTest, ASignalExitsAtOnceWhileStopsAreNotDeferred) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  for (int signal : {SIGINT, SIGTERM}) {
    EXPECT_EXIT(
        {
          InterruptionGuard guard(kStopping);
          std::raise(signal);
          std::exit(0);  // not reached
        },
        ::testing::ExitedWithCode(128 + signal), "");
    EXPECT_EXIT(
        {
          InterruptionGuard guard(kStopping);
          guard.deferStops();
          guard.stopAtOnce();
          std::raise(signal);
          std::exit(0);  // not reached
        },
        ::testing::ExitedWithCode(128 + signal), "");
  }
}

TEST(Interruption, TheOldHandlersComeBack) {
  auto previous = std::signal(SIGTERM, SIG_IGN);
  { InterruptionGuard guard(kStopping); }
  EXPECT_EQ(std::signal(SIGTERM, previous), SIG_IGN);
}
