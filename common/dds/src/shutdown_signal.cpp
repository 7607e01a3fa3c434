#include "scanfilter/dds/shutdown_signal.hpp"

#include <semaphore.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <ctime>

namespace scanfilter::dds_io {

namespace {
std::atomic<bool> g_requested{false};
// Posted once per request and passed on by every waiter it wakes, so a
// request wakes all waiters at once and later waits return at once. A
// semaphore because sem_post is async-signal-safe (a condition variable is
// not); the waiters sleep in the kernel instead of polling, which woke every
// service 50 times a second (docs/performance.md).
sem_t g_wakeup;
// Cannot fail: a process-private semaphore starting at 0.
[[maybe_unused]] const int g_wakeup_init = sem_init(&g_wakeup, 0, 0);

extern "C" void onSignal(int) {
  g_requested.store(true);
  sem_post(&g_wakeup);
}

timespec deadlineAfter(std::chrono::milliseconds timeout) {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);
  const auto ns = std::chrono::nanoseconds(timeout).count() + now.tv_nsec;
  return {now.tv_sec + static_cast<time_t>(ns / 1'000'000'000), static_cast<long>(ns % 1'000'000'000)};
}
}  // namespace

void ShutdownSignal::install() {
  struct sigaction action {};
  action.sa_handler = onSignal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

bool ShutdownSignal::requested() { return g_requested.load(); }

void ShutdownSignal::request() {
  g_requested.store(true);
  sem_post(&g_wakeup);
}

bool ShutdownSignal::waitFor(std::chrono::milliseconds timeout) {
  if (g_requested.load()) return true;
  const timespec deadline = deadlineAfter(timeout);
  while (!g_requested.load()) {
    if (sem_clockwait(&g_wakeup, CLOCK_MONOTONIC, &deadline) == 0) {
      sem_post(&g_wakeup);  // pass the wake-up on to the next waiter
      break;
    }
    if (errno != EINTR) break;  // ETIMEDOUT
  }
  return g_requested.load();
}

}  // namespace scanfilter::dds_io
