#include "scanfilter/dds/shutdown_signal.hpp"

#include <poll.h>
#include <sys/eventfd.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <thread>

namespace scanfilter::dds_io {

namespace {
std::atomic<bool> g_requested{false};
// Becomes readable at the first request and is never read, so a request
// wakes every waiter at once and later waits return at once. An eventfd
// because write() is async-signal-safe (a condition variable is not), and
// the waiters sleep in ppoll() instead of polling a flag, which woke every
// service 50 times a second (docs/performance.md). ppoll and not
// sem_clockwait: ThreadSanitizer intercepts ppoll, and holds a signal back
// from a thread blocked in a call it does not intercept.
const int g_wakeup_fd = eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK);

void wakeWaiters() {
  const std::uint64_t one = 1;
  [[maybe_unused]] const auto written = write(g_wakeup_fd, &one, sizeof one);
}

extern "C" void onSignal(int) {
  const int saved_errno = errno;  // the interrupted code may be about to read it
  g_requested.store(true);
  wakeWaiters();
  errno = saved_errno;
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
  wakeWaiters();
}

bool ShutdownSignal::waitFor(std::chrono::milliseconds timeout) {
  const auto end = std::chrono::steady_clock::now() + timeout;
  while (!g_requested.load()) {
    const auto left = end - std::chrono::steady_clock::now();
    if (left <= std::chrono::steady_clock::duration::zero()) break;
    const auto s = std::chrono::duration_cast<std::chrono::seconds>(left);
    const timespec wait{static_cast<time_t>(s.count()),
                        static_cast<long>(std::chrono::duration_cast<std::chrono::nanoseconds>(left - s).count())};
    pollfd wakeup{g_wakeup_fd, POLLIN, 0};
    // A signal (EINTR) or the eventfd ends the wait; the loop re-checks the flag.
    // Without an eventfd (none could be made) the wait still ends at its time.
    if (ppoll(&wakeup, g_wakeup_fd >= 0 ? 1 : 0, &wait, nullptr) < 0 && errno != EINTR)
      std::this_thread::sleep_for(left);  // cannot happen with a valid fd; never spin
  }
  return g_requested.load();
}

bool ShutdownSignal::waitUntil(std::chrono::steady_clock::time_point due) {
  using std::chrono::steady_clock;
  // Rounded up, so that the last wait does not end just short of `due` and spin.
  for (auto now = steady_clock::now(); now < due && !g_requested.load(); now = steady_clock::now())
    waitFor(std::chrono::ceil<std::chrono::milliseconds>(due - now));
  return g_requested.load();
}

}  // namespace scanfilter::dds_io
