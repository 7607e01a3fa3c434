#pragma once
#include <chrono>

namespace scanfilter::dds_io {

// SIGINT and SIGTERM end a service cleanly: install() routes them here, and
// the main loop waits on waitFor() until one arrives.
class ShutdownSignal {
 public:
  static void install();
  static bool requested();
  // Sleeps up to `timeout`; true when a shutdown was requested.
  static bool waitFor(std::chrono::milliseconds timeout);
  // Sleeps until `due` (a paced source's next sample); true when a shutdown
  // was requested. A plain sleep resumes after a signal: a recording's pause
  // of hours would keep SIGTERM waiting as long.
  static bool waitUntil(std::chrono::steady_clock::time_point due);
  static void request();  // as if a signal arrived (tests, end of input)
};

}  // namespace scanfilter::dds_io
