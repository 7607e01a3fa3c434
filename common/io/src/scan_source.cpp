#include "scanfilter/scan_source.hpp"

#include <zlib.h>

#include <algorithm>
#include <filesystem>
#include <vector>

#include "scanfilter/carmen_log_reader.hpp"
#include "scanfilter/input_error.hpp"
#include "scanfilter/line_reader.hpp"
#include "scanfilter/mines_log_reader.hpp"
#include "scanfilter/scan_log_reader.hpp"

namespace scanfilter {

namespace {

// A gzip file is decompressed once to its end before any scan is read, so a
// truncated or corrupt one fails at open with the line where it breaks, not
// after a player has published half of it. Plain files pass at no cost.
void checkGzipIntact(const std::string& path) {
  // Only regular files: a pipe cannot be read twice (nor a gzip one seeked).
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) return;
  gzFile file = gzopen(path.c_str(), "rb");
  if (file == nullptr) return;  // the reader reports it
  if (gzdirect(file) == 1) {
    gzclose(file);
    return;
  }
  constexpr unsigned kChunk = 1u << 20;
  std::vector<char> buffer(kChunk);
  std::size_t lines = 1;
  int n = 0;
  while ((n = gzread(file, buffer.data(), kChunk)) > 0) lines += static_cast<std::size_t>(std::count(buffer.begin(), buffer.begin() + n, '\n'));
  int err = Z_OK;
  const std::string message = gzerror(file, &err);
  gzclose(file);
  if (n < 0 || (err != Z_OK && err != Z_STREAM_END))
    throw InputError(path, lines, "", "gzip data truncated or corrupt (" + message + ")");
}

}  // namespace

std::unique_ptr<ScanSource> openScanSource(const std::string& path, const ScanSourceOptions& options) {
  // A scan log starts with a JSON object, a Mines URG-04LX log with a line of
  // 707 numbers; anything else is read as CARMEN.
  checkGzipIntact(path);
  LineReader probe(path);
  std::string first;
  bool any_line = false;
  while (probe.next(first)) {
    any_line = true;
    if (first.find_first_not_of(" \t") != std::string::npos) break;
  }
  if (!any_line) throw InputError(path, 0, "", "empty file: expected a scan log, a CARMEN log or a Mines log");
  // The reader opens the file again from its start: a pipe's first line is gone by then.
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    throw InputError(path, 0, "", "not a regular file (a pipe or device cannot be read from its start twice; "
                                  "write it to a file first)");
  const auto start = first.find_first_not_of(" \t");
  if (start != std::string::npos && first[start] == '{')
    return std::make_unique<ScanLogReader>(path, options.warn_stamps);
  if (MinesLogReader::looksLikeMinesLine(first))
    return std::make_unique<MinesLogReader>(path, MinesRobotModel{}, options.warn_stamps);
  return std::make_unique<CarmenLogReader>(path, options);
}

LogCheck checkLogToEnd(const std::string& path, ScanSourceOptions options) {
  options.warn_stamps = false;  // the pass that plays the log warns, at the scan it reaches
  auto source = openScanSource(path, options);
  LogCheck check;
  ScanRecord record;
  while (source->next(record)) ++check.scans;
  check.stamp_regressions = source->stampRegressions();
  check.stamp_repeats = source->stampRepeats();
  return check;
}

}  // namespace scanfilter
