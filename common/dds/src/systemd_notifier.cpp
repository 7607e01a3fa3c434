#include "scanfilter/dds/systemd_notifier.hpp"

#include <cstring>

#include <spdlog/spdlog.h>
#include <systemd/sd-daemon.h>

#include "scanfilter/dds/progress_heartbeat.hpp"

namespace scanfilter::dds_io {

namespace {

// Pings this many times per watchdog interval: systemd's own advice is at
// least twice, and a quarter leaves room for a loaded machine.
constexpr int kPingsPerInterval = 4;
// A heartbeat older than this fraction of the interval means a stuck thread:
// with the last ping at most that old, systemd acts within 1.5 intervals.
constexpr int kStaleFractionOfInterval = 2;

void notify(const std::string& message) {
  // unset_environment = 0: a child process started later may not be ours to
  // notify for, but the service starts none.
  const int r = sd_notify(0, message.c_str());
  if (r < 0) spdlog::warn("sd_notify({}) failed: {}", message, std::strerror(-r));
}

std::string seconds(std::chrono::steady_clock::duration d) {
  return fmt::format("{:.1f} s", std::chrono::duration<double>(d).count());
}

}  // namespace

SystemdNotifier::SystemdNotifier() {
  std::uint64_t usec = 0;
  if (sd_watchdog_enabled(0, &usec) > 0 && usec > 0) {
    interval_ = std::chrono::microseconds(usec);
    watchdog_ = std::thread([this] { watchLoop(); });
  }
}

SystemdNotifier::~SystemdNotifier() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  if (watchdog_.joinable()) watchdog_.join();
}

void SystemdNotifier::ready(const std::string& status) const {
  {
    std::lock_guard lock(mutex_);
    ready_status_ = status;
  }
  notify("READY=1\nSTATUS=" + status);
}

void SystemdNotifier::stopping() const {
  std::lock_guard lock(mutex_);
  if (stopping_sent_) return;
  stopping_sent_ = true;
  notify("STOPPING=1\nSTATUS=stopping");
}

void SystemdNotifier::status(const std::string& text) const { notify("STATUS=" + text); }

void SystemdNotifier::watchLoop() {
  const auto period = interval_ / kPingsPerInterval;
  const auto max_age = interval_ / kStaleFractionOfInterval;
  bool stalled = false;
  std::unique_lock lock(mutex_);
  while (!wake_.wait_for(lock, period, [this] { return stop_; })) {
    const auto stale = ProgressHeartbeat::findStale(max_age);
    if (!stale) {
      notify("WATCHDOG=1");
      if (stalled) {
        spdlog::info("watchdog: every worker makes progress again; pinging systemd again");
        notify("STATUS=" + ready_status_);
      }
      stalled = false;
    } else if (!stalled) {
      const std::string what = stale->name + " made no progress for " + seconds(stale->age);
      spdlog::warn("watchdog: {}; no more pings to systemd (WatchdogSec {})", what, seconds(interval_));
      notify("STATUS=stalled: " + what);
      stalled = true;
    }
  }
}

}  // namespace scanfilter::dds_io
