#pragma once
// A file in the test's temporary directory, removed when the test ends. The
// name carries the process id: ctest -j runs each test case as its own
// process, and two cases writing "bad.scanlog.jsonl" at once would race.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

namespace scanfilter::test {

class TempFile {
 public:
  explicit TempFile(const std::string& name, const std::string& content = "")
      : path_(std::filesystem::path(::testing::TempDir()) / (std::to_string(::getpid()) + "-" + name)) {
    if (!content.empty()) std::ofstream(path_) << content;
  }
  ~TempFile() { std::filesystem::remove(path_); }
  std::string path() const { return path_.string(); }

 private:
  std::filesystem::path path_;
};

}  // namespace scanfilter::test
