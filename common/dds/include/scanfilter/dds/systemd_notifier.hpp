#pragma once
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace scanfilter::dds_io {

// systemd's notify protocol (sd_notify(3)) for a service run by a
// Type=notify unit (deploy/systemd/):
// - READY=1 once the participant and the service's endpoints exist;
// - WATCHDOG=1 every quarter of WatchdogSec, but only while every
//   ProgressHeartbeat (each reader's worker, the runtime's loop) beat within
//   half of it: a thread stuck in a callback stops the pings and systemd
//   restarts the service;
// - STOPPING=1 once a stop was asked for;
// - STATUS= lines for `systemctl status`.
// Without NOTIFY_SOCKET in the environment (not run by systemd) it sends
// nothing; without WATCHDOG_USEC (or with a WATCHDOG_PID that is not this
// process) it runs no watchdog thread.
class SystemdNotifier {
 public:
  SystemdNotifier();
  ~SystemdNotifier();
  SystemdNotifier(const SystemdNotifier&) = delete;
  SystemdNotifier& operator=(const SystemdNotifier&) = delete;

  // const: what systemd is told is not the notifier's state.
  void ready(const std::string& status) const;
  void stopping() const;
  void status(const std::string& text) const;
  // WATCHDOG_USEC, or zero when systemd expects no pings.
  std::chrono::microseconds watchdogInterval() const { return interval_; }

 private:
  void watchLoop();

  std::chrono::microseconds interval_{0};
  mutable std::string ready_status_;  // sent again when a stall ends
  mutable bool stopping_sent_ = false;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  std::thread watchdog_;
};

}  // namespace scanfilter::dds_io
