// The embedded runner's restart policy: restart however often a daemon is killed, give up only
// on a crash loop.
#include "coordinator/cli/crash_loop.h"

#include <gtest/gtest.h>

namespace rlpos {
namespace {

TEST(CrashLoopGuard, KillsNeverStopTheRestartsHoweverEarly) {
  CrashLoopGuard guard(3, 5.0);
  double t = 0;
  for (int kill = 0; kill < 100; ++kill) {
    guard.Died(t, t + 0.5, true);  // killed half a second after each start
    t += 0.5;
    ASSERT_FALSE(guard.CrashLooping()) << kill;
  }
  // Crashes after a long life do not either.
  for (int crash = 0; crash < 10; ++crash) {
    guard.Died(t, t + 6.0, false);
    t += 6.0;
    ASSERT_FALSE(guard.CrashLooping()) << crash;
  }
}

TEST(CrashLoopGuard, ThreeShortLivesInARowAreACrashLoop) {
  CrashLoopGuard guard(3, 5.0);
  guard.Died(0, 1, false);
  guard.Died(1, 2, false);
  EXPECT_FALSE(guard.CrashLooping());
  guard.Died(2, 10, false);  // a long life resets the count
  guard.Died(10, 11, false);
  guard.Died(11, 11.5, true);  // and so does a kill
  guard.Died(11.5, 12, false);
  guard.Died(12, 13, false);
  EXPECT_FALSE(guard.CrashLooping());
  guard.Died(13, 17.9, false);
  EXPECT_TRUE(guard.CrashLooping());
  EXPECT_EQ(guard.Describe(), "3 times in a row within 5 s of starting");
}

}  // namespace
}  // namespace rlpos
