#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace scanfilter {

// Reads a text file line by line without holding it in memory; gzip files are
// decompressed on the fly (zlib reads plain files unchanged).
class LineReader {
 public:
  explicit LineReader(const std::string& path);  // throws InputError if unreadable
  ~LineReader();
  LineReader(const LineReader&) = delete;
  LineReader& operator=(const LineReader&) = delete;

  // Next line without its line ending; false at the end of the file.
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
