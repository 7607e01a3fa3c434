#include "scanfilter/dds/progress_heartbeat.hpp"

#include <algorithm>
#include <mutex>
#include <vector>

namespace scanfilter::dds_io {

namespace {

// Every live heartbeat of the process: few (one per reader and the loop),
// changing only when endpoints are created or deleted.
struct Registry {
  std::mutex mutex;
  std::vector<const ProgressHeartbeat*> beats;
};

Registry& registry() {
  static Registry r;
  return r;
}

std::chrono::steady_clock::rep nowTicks() { return std::chrono::steady_clock::now().time_since_epoch().count(); }

// The heartbeat that last beat on this thread (a heartbeat is beaten by one
// thread: a reader's worker, the service loop).
thread_local ProgressHeartbeat* this_threads_heartbeat = nullptr;

}  // namespace

ProgressHeartbeat::ProgressHeartbeat(std::string name) : name_(std::move(name)), last_beat_(nowTicks()) {
  std::lock_guard lock(registry().mutex);
  registry().beats.push_back(this);
}

ProgressHeartbeat::~ProgressHeartbeat() {
  if (this_threads_heartbeat == this) this_threads_heartbeat = nullptr;
  std::lock_guard lock(registry().mutex);
  auto& beats = registry().beats;
  beats.erase(std::remove(beats.begin(), beats.end(), this), beats.end());
}

void ProgressHeartbeat::beat() {
  last_beat_.store(nowTicks(), std::memory_order_relaxed);
  idle_.store(false, std::memory_order_relaxed);
  this_threads_heartbeat = this;
}

void ProgressHeartbeat::beatThisThread() {
  if (this_threads_heartbeat != nullptr) this_threads_heartbeat->beat();
}

void ProgressHeartbeat::idle() { idle_.store(true, std::memory_order_relaxed); }

std::optional<ProgressHeartbeat::Stale> ProgressHeartbeat::findStale(std::chrono::steady_clock::duration max_age) {
  const auto now = std::chrono::steady_clock::now();
  std::lock_guard lock(registry().mutex);
  for (const ProgressHeartbeat* b : registry().beats) {
    if (b->idle_.load(std::memory_order_relaxed)) continue;
    const auto last = std::chrono::steady_clock::time_point(
        std::chrono::steady_clock::duration(b->last_beat_.load(std::memory_order_relaxed)));
    if (now - last > max_age) return Stale{b->name_, now - last};
  }
  return std::nullopt;
}

}  // namespace scanfilter::dds_io
