#pragma once
// A file in the test's temporary directory, removed when the test ends.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

namespace scanfilter::test {

class TempFile {
 public:
  explicit TempFile(const std::string& name, const std::string& content = "")
      : path_(std::filesystem::path(::testing::TempDir()) / name) {
    if (!content.empty()) std::ofstream(path_) << content;
  }
  ~TempFile() { std::filesystem::remove(path_); }
  std::string path() const { return path_.string(); }

 private:
  std::filesystem::path path_;
};

}  // namespace scanfilter::test
