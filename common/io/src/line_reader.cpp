#include "scanfilter/line_reader.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <sstream>

#include <zlib.h>

#include "scanfilter/input_error.hpp"

namespace scanfilter {

namespace {
constexpr int kChunkBytes = 64 * 1024;
}

LineReader::LineReader(const std::string& path) : path_(path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) throw InputError(path, 0, "", "is a directory, expected a file");
  file_ = gzopen(path.c_str(), "rb");
  if (file_ == nullptr)
    throw InputError(path, 0, "", std::string("cannot open: ") + std::strerror(errno));
}

LineReader::~LineReader() {
  if (file_ != nullptr) gzclose(static_cast<gzFile>(file_));
}

bool LineReader::next(std::string& line) {
  line.clear();
  char chunk[kChunkBytes];
  bool got_any = false;
  while (gzgets(static_cast<gzFile>(file_), chunk, kChunkBytes) != nullptr) {
    got_any = true;
    line.append(chunk);
    if (!line.empty() && line.back() == '\n') break;
    if (line.size() > kMaxLineBytes)
      throw InputError(path_, line_number_ + 1, "",
                       "line longer than " + std::to_string(kMaxLineBytes >> 20) + " MiB; not a log line");
  }
  if (!got_any) {
    int err = Z_OK;
    const char* message = gzerror(static_cast<gzFile>(file_), &err);
    if (err != Z_OK && err != Z_STREAM_END)
      throw InputError(path_, line_number_ + 1, "", std::string("read error: ") + message);
    return false;
  }
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
  ++line_number_;
  return true;
}

std::vector<std::string> splitFields(const std::string& line) {
  std::vector<std::string> fields;
  std::istringstream in(line);
  for (std::string field; in >> field;) fields.push_back(std::move(field));
  return fields;
}

}  // namespace scanfilter
