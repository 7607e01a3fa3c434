#include "fuzz_input.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace scanfilter::fuzz {

namespace {

std::string makeWorkDirectory() {
  std::string pattern = (std::filesystem::temp_directory_path() / "scanfilter-fuzz-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("cannot create a fuzz work directory");
  // The files a service config names by default, next to it as in config/.
  std::filesystem::copy_file(SCANFILTER_SOURCE_DIR "/config/filter.yaml", pattern + "/filter.yaml");
  std::filesystem::copy_file(SCANFILTER_SOURCE_DIR "/deploy/fastdds-loopback.xml", pattern + "/fastdds-loopback.xml");
  return pattern;
}

}  // namespace

const std::string& workDirectory() {
  static const std::string directory = makeWorkDirectory();
  static const bool cleanup_registered = [] {
    std::atexit([] { std::filesystem::remove_all(workDirectory()); });
    return true;
  }();
  (void)cleanup_registered;
  return directory;
}

std::string writeInput(const std::uint8_t* data, std::size_t size, const std::string& name) {
  const std::string path = workDirectory() + "/" + name;
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (file == nullptr) throw std::runtime_error("cannot write " + path);
  if (size > 0 && std::fwrite(data, 1, size, file) != size) throw std::runtime_error("short write to " + path);
  std::fclose(file);
  return path;
}

}  // namespace scanfilter::fuzz
