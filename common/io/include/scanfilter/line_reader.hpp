#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace scanfilter {

// Reads a text file line by line without holding it in memory; gzip files are
// decompressed on the fly (zlib reads plain files unchanged).
class LineReader {
 public:
  // Longest line accepted. The longest real line is a scan log's with
  // ScanLogReader::kMaxBeams beams (~20 MB of JSON); a longer one is not a
  // log, and reading it whole would take the memory of a 2 GB line.
  static constexpr std::size_t kMaxLineBytes = std::size_t{64} << 20;

  explicit LineReader(const std::string& path);  // throws InputError if unreadable
  ~LineReader();
  LineReader(const LineReader&) = delete;
  LineReader& operator=(const LineReader&) = delete;

  // Next line without its line ending; false at the end of the file.
  // Throws InputError for a line longer than kMaxLineBytes or a read error
  // (a truncated or corrupt gzip file).
  bool next(std::string& line);
  std::size_t lineNumber() const { return line_number_; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  void* file_ = nullptr;  // gzFile, kept opaque so zlib stays out of the header
  std::size_t line_number_ = 0;
};

// The whitespace-separated fields of a line (the text log formats).
std::vector<std::string> splitFields(const std::string& line);

}  // namespace scanfilter
