#include "scanfilter/dds/shutdown_signal.hpp"

#include <atomic>
#include <csignal>
#include <thread>

namespace scanfilter::dds_io {

namespace {
std::atomic<bool> g_requested{false};
extern "C" void onSignal(int) { g_requested.store(true); }  // async-signal-safe: one atomic store
constexpr std::chrono::milliseconds kPollStep{20};
}  // namespace

void ShutdownSignal::install() {
  struct sigaction action {};
  action.sa_handler = onSignal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

bool ShutdownSignal::requested() { return g_requested.load(); }

void ShutdownSignal::request() { g_requested.store(true); }

bool ShutdownSignal::waitFor(std::chrono::milliseconds timeout) {
  // Polling keeps the handler trivial (no condition variable in a signal handler).
  const auto end = std::chrono::steady_clock::now() + timeout;
  while (!g_requested.load() && std::chrono::steady_clock::now() < end) std::this_thread::sleep_for(kPollStep);
  return g_requested.load();
}

}  // namespace scanfilter::dds_io
