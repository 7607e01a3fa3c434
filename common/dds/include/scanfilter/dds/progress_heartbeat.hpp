#pragma once
#include <atomic>
#include <chrono>
#include <optional>
#include <string>

namespace scanfilter::dds_io {

// A thread that does a service's work (a reader's worker, the runtime's
// loop) shows it is still making progress by beating. The systemd watchdog
// (SystemdNotifier) pings only while every registered heartbeat is recent,
// so a thread stuck in a callback gets the service restarted.
// A heartbeat is registered for its lifetime; beat() and idle() are
// lock-free.
class ProgressHeartbeat {
 public:
  explicit ProgressHeartbeat(std::string name);
  ~ProgressHeartbeat();
  ProgressHeartbeat(const ProgressHeartbeat&) = delete;
  ProgressHeartbeat& operator=(const ProgressHeartbeat&) = delete;

  void beat();
  // Waiting for a timer (a bounded wait, not work): not stale until the
  // next beat(), however long the wait.
  void idle();
  // A deliberate, logged wait on the calling thread (a writer holding while
  // its reader is gone: docs/operations.md, "Crashed readers") is progress:
  // beats the heartbeat that last beat on this thread, if any. Without it
  // the watchdog would have a holding stage killed ~10 s into an outage
  // downstream, with the scan in its hands.
  static void beatThisThread();

  // The name of a registered heartbeat that has not beaten for longer than
  // max_age and for how long, or nullopt when every one is recent.
  struct Stale {
    std::string name;
    std::chrono::steady_clock::duration age;
  };
  static std::optional<Stale> findStale(std::chrono::steady_clock::duration max_age);

 private:
  std::string name_;
  std::atomic<std::chrono::steady_clock::rep> last_beat_;
  std::atomic<bool> idle_{false};
};

}  // namespace scanfilter::dds_io
