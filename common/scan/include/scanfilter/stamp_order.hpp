#pragma once
#include <cstddef>
#include <string>

#include "scanfilter/stamp.hpp"

namespace scanfilter {

// Watches a log's stamps for going backwards. Real recordings do (the Intel
// CARMEN log at line 5647), and one command's output must be readable by
// every other, so a regression is warned about once, counted, and the scan
// kept in file order; it is never an error.
class StampOrder {
 public:
  // `what` names the stamp field in the warning ("stamp", "ipc_timestamp").
  StampOrder(std::string path, std::string what) : path_(std::move(path)), what_(std::move(what)) {}

  void check(Stamp stamp, std::size_t line);
  std::size_t regressions() const { return regressions_; }

 private:
  std::string path_;
  std::string what_;
  Stamp last_;
  bool have_last_ = false;
  std::size_t regressions_ = 0;
};

}  // namespace scanfilter
