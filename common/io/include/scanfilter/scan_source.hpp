#pragma once
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "scanfilter/scan.hpp"
#include "scanfilter/sensor_info.hpp"

namespace scanfilter {

// One scan as read from a log, with the line it came from so a filter's
// output can keep every key of its input.
struct ScanRecord {
  Scan scan;
  nlohmann::ordered_json original;  // null when the scan did not come from a scan log
  std::size_t line = 0;
};

// A stream of scans with a fixed header: a scan log, a CARMEN log, the simulator.
class ScanSource {
 public:
  virtual ~ScanSource() = default;
  virtual const ScanLogHeader& header() const = 0;
  // Next scan; false at the end. Throws InputError on bad input.
  virtual bool next(ScanRecord& record) = 0;
  // Scans so far whose stamp is earlier than the one before (kept in file
  // order, warned about once).
  virtual std::size_t stampRegressions() const { return 0; }
  // Scans so far whose stamp equals the one before (warned about once).
  virtual std::size_t stampRepeats() const { return 0; }
};

// Options for logs whose header does not say everything.
// The smallest carmen_range_max taken (m); the largest is kMaxPlausibleRange.
inline constexpr double kMinCarmenRangeMax = 0.01;

struct ScanSourceOptions {
  double carmen_range_max = 80.0;  // m; CARMEN logs write >= 80 m for "no return"
  bool warn_stamps = true;         // warn once about stamps that step back or stand still (else only count them)
};

// Opens a scan log, a CARMEN log or a Mines log (plain or gzip), told apart
// by its first line; a regular file only (the reader reads it from its start).
std::unique_ptr<ScanSource> openScanSource(const std::string& path,
                                           const ScanSourceOptions& options = {});

// What reading a log through to its end found.
struct LogCheck {
  std::size_t scans = 0;
  std::size_t stamp_regressions = 0;
  std::size_t stamp_repeats = 0;
};

// Reads a log through to its end, every line parsed, so that a file cut short
// or a bad line anywhere fails (InputError, with its line) before a player
// publishes any of it.
LogCheck checkLogToEnd(const std::string& path, ScanSourceOptions options = {});

}  // namespace scanfilter
