#include <gtest/gtest.h>

#include <csignal>

#include "app/interruption.h"

using namespace columba;

TEST(Interruption, TheFirstSignalAsksToStop) {
  for (int signal : {SIGINT, SIGTERM}) {
    InterruptionGuard guard;
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
          InterruptionGuard guard;
          std::raise(signal);
          std::raise(signal);
          std::exit(0);  // not reached
        },
        ::testing::ExitedWithCode(128 + signal), "interrupt again");
  }
}

TEST(Interruption, TheOldHandlersComeBack) {
  auto previous = std::signal(SIGTERM, SIG_IGN);
  { InterruptionGuard guard; }
  EXPECT_EQ(std::signal(SIGTERM, previous), SIG_IGN);
}
