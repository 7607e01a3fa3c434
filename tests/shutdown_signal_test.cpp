// ShutdownSignal: waiters sleep until a request or their timeout, and one
// request (a signal or request()) wakes every waiter at once. The request is
// process-wide and sticky; ctest runs each test in its own process.
#include <chrono>
#include <csignal>
#include <fstream>
#include <future>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "scanfilter/dds/shutdown_signal.hpp"

using scanfilter::dds_io::ShutdownSignal;
using Clock = std::chrono::steady_clock;

namespace {
constexpr auto kLongWait = std::chrono::seconds(20);
// Far below kLongWait, far above a wake-up on a loaded 2-core machine.
constexpr auto kPromptly = std::chrono::seconds(5);

// Seconds a waitFor(kLongWait) on another thread took, and what it returned.
std::future<std::pair<double, bool>> waitOnAnotherThread() {
  return std::async(std::launch::async, [] {
    const auto start = Clock::now();
    const bool requested = ShutdownSignal::waitFor(std::chrono::duration_cast<std::chrono::milliseconds>(kLongWait));
    return std::pair{std::chrono::duration<double>(Clock::now() - start).count(), requested};
  });
}

// The calling thread's voluntary context switches so far (Linux).
long voluntarySwitches() {
  std::ifstream status("/proc/thread-self/status");
  for (std::string key; status >> key;) {
    if (key == "voluntary_ctxt_switches:") {
      long n = 0;
      status >> n;
      return n;
    }
  }
  return -1;
}
}  // namespace

TEST(ShutdownSignal, SleepsThroughItsTimeoutWithoutARequest) {
  const long switches_before = voluntarySwitches();
  const auto start = Clock::now();
  EXPECT_FALSE(ShutdownSignal::waitFor(std::chrono::seconds(1)));
  EXPECT_GE(Clock::now() - start, std::chrono::seconds(1));
  // One sleep, not a poll: polling every 20 ms would switch ~50 times.
  EXPECT_LT(voluntarySwitches() - switches_before, 5);
  EXPECT_FALSE(ShutdownSignal::requested());
}

TEST(ShutdownSignal, ASignalWakesEveryWaiterAndLaterWaitsReturnAtOnce) {
  ShutdownSignal::install();
  auto first = waitOnAnotherThread();
  auto second = waitOnAnotherThread();
  std::this_thread::sleep_for(std::chrono::milliseconds(100));  // both asleep in waitFor
  std::raise(SIGTERM);
  for (auto* waiter : {&first, &second}) {
    const auto [seconds, requested] = waiter->get();
    EXPECT_TRUE(requested);
    EXPECT_LT(seconds, std::chrono::duration<double>(kPromptly).count());
  }
  const auto start = Clock::now();
  EXPECT_TRUE(ShutdownSignal::waitFor(std::chrono::duration_cast<std::chrono::milliseconds>(kLongWait)));
  EXPECT_LT(Clock::now() - start, kPromptly);
}

TEST(ShutdownSignal, RequestWakesAWaiter) {
  auto waiter = waitOnAnotherThread();
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  ShutdownSignal::request();
  const auto [seconds, requested] = waiter.get();
  EXPECT_TRUE(requested);
  EXPECT_LT(seconds, std::chrono::duration<double>(kPromptly).count());
}

TEST(ShutdownSignal, WaitUntilSleepsToItsTimeWithoutARequest) {
  const auto due = Clock::now() + std::chrono::milliseconds(300);
  EXPECT_FALSE(ShutdownSignal::waitUntil(due));
  EXPECT_GE(Clock::now(), due);
}

// A paced source waiting out a recording's long pause (the csail CARMEN
// log's stamps jump 10,000 s) stops as soon as it is asked to.
TEST(ShutdownSignal, RequestEndsAWaitUntilAtOnce) {
  auto waiter = std::async(std::launch::async, [] {
    const auto start = Clock::now();
    const bool requested = ShutdownSignal::waitUntil(start + kLongWait);
    return std::pair{std::chrono::duration<double>(Clock::now() - start).count(), requested};
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  ShutdownSignal::request();
  const auto [seconds, requested] = waiter.get();
  EXPECT_TRUE(requested);
  EXPECT_LT(seconds, std::chrono::duration<double>(kPromptly).count());
}
