#pragma once
#include <cstddef>
#include <string>

#include "scanfilter/stamp.hpp"

namespace scanfilter {

// Watches a log's stamps for going backwards or standing still. Real
// recordings do both: the Intel CARMEN log goes back at line 5647, and the
// csail one was written with six significant digits, so its 406 scans carry
// two stamps between them. One command's output must be readable by every
// other, so neither is an error: each is warned about once, counted, and the
// scan kept in file order.
class StampOrder {
 public:
  // `what` names the stamp field in the warning ("stamp", "ipc_timestamp").
  // Unless `warn`, only counted: a pass that checks a log before it is
  // played leaves the warnings to the pass that plays it.
  StampOrder(std::string path, std::string what, bool warn = true)
      : path_(std::move(path)), what_(std::move(what)), warn_(warn) {}

  void check(Stamp stamp, std::size_t line);
  // Scans whose stamp is earlier than the scan's before.
  std::size_t regressions() const { return regressions_; }
  // Scans whose stamp equals the scan's before.
  std::size_t repeats() const { return repeats_; }

 private:
  std::string path_;
  std::string what_;
  bool warn_;
  Stamp last_;
  bool have_last_ = false;
  std::size_t regressions_ = 0;
  std::size_t repeats_ = 0;
};

}  // namespace scanfilter
