// The watchdog's view of the workers (common/dds ProgressHeartbeat): a
// heartbeat older than the limit is reported by name, an idle one (waiting on
// a timer) never is, and a destroyed one is forgotten. Ages come from sleeping
// at least that long, so the outcomes do not depend on the machine's speed.
#include <chrono>
#include <new>
#include <optional>
#include <thread>

#include <gtest/gtest.h>

#include "scanfilter/dds/progress_heartbeat.hpp"

using scanfilter::dds_io::ProgressHeartbeat;
using namespace std::chrono_literals;

namespace {
constexpr auto kOld = 30ms;      // a heartbeat made this long ago ...
constexpr auto kLimit = 10ms;    // ... is stale against this limit
constexpr auto kForever = 1h;    // and recent against this one
}  // namespace

TEST(ProgressHeartbeat, ReportsOnlyAHeartbeatOlderThanTheLimit) {
  ProgressHeartbeat beat("the reader of rt/x");
  EXPECT_FALSE(ProgressHeartbeat::findStale(kForever));
  std::this_thread::sleep_for(kOld);
  const auto stale = ProgressHeartbeat::findStale(kLimit);
  ASSERT_TRUE(stale);
  EXPECT_EQ(stale->name, "the reader of rt/x");
  EXPECT_GE(stale->age, kOld);
  EXPECT_FALSE(ProgressHeartbeat::findStale(kForever));
}

TEST(ProgressHeartbeat, ABeatMakesItRecentAgain) {
  ProgressHeartbeat beat("loop");
  std::this_thread::sleep_for(kOld);
  ASSERT_TRUE(ProgressHeartbeat::findStale(kLimit));
  const auto beaten = std::chrono::steady_clock::now();
  beat.beat();
  // Stale again only if this thread was descheduled past the limit; even then
  // no older than the beat.
  const auto stale = ProgressHeartbeat::findStale(kLimit);
  if (stale) {
    EXPECT_LE(stale->age, std::chrono::steady_clock::now() - beaten);
  }
}

TEST(ProgressHeartbeat, AnIdleHeartbeatIsNeverStaleUntilItBeatsAgain) {
  ProgressHeartbeat beat("loop");
  beat.idle();
  std::this_thread::sleep_for(kOld);
  EXPECT_FALSE(ProgressHeartbeat::findStale(kLimit));
  beat.beat();
  std::this_thread::sleep_for(kOld);
  EXPECT_TRUE(ProgressHeartbeat::findStale(kLimit));
}

TEST(ProgressHeartbeat, ADestroyedHeartbeatIsForgotten) {
  {
    ProgressHeartbeat beat("gone");
    std::this_thread::sleep_for(kOld);
    EXPECT_TRUE(ProgressHeartbeat::findStale(kLimit));
  }
  EXPECT_FALSE(ProgressHeartbeat::findStale(kLimit));
}

TEST(ProgressHeartbeat, NamesTheStaleOneAmongRecentOnes) {
  ProgressHeartbeat stuck("stuck");
  std::this_thread::sleep_for(kOld);
  ProgressHeartbeat fresh("fresh");
  const auto stale = ProgressHeartbeat::findStale(kLimit);
  ASSERT_TRUE(stale);
  EXPECT_EQ(stale->name, "stuck");
}

// A writer holding for a reader that is gone waits on the thread that does
// the stage's work: that wait beats the thread's own heartbeat, and no other.
TEST(ProgressHeartbeat, AHoldOnTheThreadThatBeatsItKeepsItRecent) {
  ProgressHeartbeat loop("loop");
  loop.beat();  // this thread's heartbeat from now on
  std::this_thread::sleep_for(kOld);
  ASSERT_TRUE(ProgressHeartbeat::findStale(kLimit));
  std::thread other([] { ProgressHeartbeat::beatThisThread(); });
  other.join();
  const auto still = ProgressHeartbeat::findStale(kLimit);
  ASSERT_TRUE(still) << "another thread's wait beat this thread's heartbeat";
  EXPECT_GE(still->age, kOld);
  const auto beaten = std::chrono::steady_clock::now();
  ProgressHeartbeat::beatThisThread();
  const auto stale = ProgressHeartbeat::findStale(kLimit);
  if (stale) {  // only if descheduled past the limit, and then no older than the beat
    EXPECT_LE(stale->age, std::chrono::steady_clock::now() - beaten);
  }
}

// The thread forgets a heartbeat destroyed: its next wait beats nothing,
// not whatever lives where the dead one did. The second heartbeat is made
// in the first one's storage, so a dangling pointer would beat it.
TEST(ProgressHeartbeat, AThreadsDestroyedHeartbeatIsNotBeaten) {
  alignas(ProgressHeartbeat) unsigned char storage[sizeof(ProgressHeartbeat)];
  auto* gone = new (storage) ProgressHeartbeat("gone");
  gone->beat();
  gone->~ProgressHeartbeat();
  auto* later = new (storage) ProgressHeartbeat("later");
  std::this_thread::sleep_for(kOld);
  ProgressHeartbeat::beatThisThread();
  const auto stale = ProgressHeartbeat::findStale(kLimit);
  later->~ProgressHeartbeat();
  ASSERT_TRUE(stale) << "a wait beat a heartbeat this thread never beat";
  EXPECT_EQ(stale->name, "later");
}
