#include "scanfilter/scan_source.hpp"

#include "scanfilter/carmen_log_reader.hpp"
#include "scanfilter/input_error.hpp"
#include "scanfilter/line_reader.hpp"
#include "scanfilter/mines_log_reader.hpp"
#include "scanfilter/scan_log_reader.hpp"

namespace scanfilter {

std::unique_ptr<ScanSource> openScanSource(const std::string& path, const ScanSourceOptions& options) {
  // A scan log starts with a JSON object, a Mines URG-04LX log with a line of
  // 707 numbers; anything else is read as CARMEN.
  LineReader probe(path);
  std::string first;
  bool any_line = false;
  while (probe.next(first)) {
    any_line = true;
    if (first.find_first_not_of(" \t") != std::string::npos) break;
  }
  if (!any_line) throw InputError(path, 0, "", "empty file: expected a scan log, a CARMEN log or a Mines log");
  const auto start = first.find_first_not_of(" \t");
  if (start != std::string::npos && first[start] == '{') return std::make_unique<ScanLogReader>(path);
  if (MinesLogReader::looksLikeMinesLine(first)) return std::make_unique<MinesLogReader>(path);
  return std::make_unique<CarmenLogReader>(path, options);
}

}  // namespace scanfilter
