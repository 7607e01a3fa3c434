#include "playback_progress.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "scanfilter/input_error.hpp"

namespace scanfilter::ingest {

namespace {
constexpr const char* kKey = "published_scans";
}  // namespace

std::uint64_t PlaybackProgress::load() const {
  if (path_.empty() || !std::filesystem::exists(path_)) return 0;
  std::ifstream in(path_);
  std::string key;
  long long count = -1;
  in >> key >> count;
  if (!in || key != std::string(kKey) + ":" || count < 0)
    throw InputError(path_, 1, kKey, "expected \"" + std::string(kKey) + ": <scans>\" (a playback progress file)");
  return static_cast<std::uint64_t>(count);
}

void PlaybackProgress::record(std::uint64_t published) const {
  if (path_.empty()) return;
  const std::string tmp = path_ + ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << kKey << ": " << published << "\n";
    if (!out) throw std::runtime_error(tmp + ": cannot write the playback progress");
  }
  std::filesystem::rename(tmp, path_);
}

}  // namespace scanfilter::ingest
