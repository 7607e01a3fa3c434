#pragma once
#include <fstream>
#include <string>

#include "scanfilter/scan_source.hpp"

namespace scanfilter {

// Writes a `.scanlog.jsonl` file. A scan read from a scan log is written as
// its original line plus `labels`; any other scan is serialised from Scan.
// The file is written as PATH.partial and renamed to PATH by close(): a
// writer destroyed before close() (an error on the way) removes it, so no
// partial log is ever left under the real name.
class ScanLogWriter {
 public:
  ScanLogWriter(const std::string& path, const ScanLogHeader& header);
  ~ScanLogWriter();
  ScanLogWriter(const ScanLogWriter&) = delete;
  ScanLogWriter& operator=(const ScanLogWriter&) = delete;

  void write(const ScanRecord& record);
  void close();

 private:
  std::string path_;
  std::string partial_path_;
  std::ofstream out_;
  bool closed_ = false;
};

// JSON of a header line (used by the writer and tests).
nlohmann::ordered_json headerToJson(const ScanLogHeader& header);
// A scan line: the record's original line (every key kept) with its labels,
// or the scan serialised. The stamp is written from its integer nanoseconds
// (nlohmann's numbers are doubles), so it reads back the same.
std::string scanLine(const ScanRecord& record);

}  // namespace scanfilter
