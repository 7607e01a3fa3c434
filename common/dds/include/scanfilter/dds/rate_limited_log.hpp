#pragma once
#include <map>
#include <mutex>
#include <string>

#include <spdlog/spdlog.h>

namespace scanfilter::dds_io {

// Logs a warning the first time each kind of problem happens and then only
// counts it: a bad sample stream must not flood the log.
class OncePerKindLog {
 public:
  void warn(const std::string& kind, const std::string& message) {
    std::lock_guard lock(mutex_);
    if (seen_[kind]++ == 0) spdlog::warn("{} (first '{}'; further ones are counted in metrics)", message, kind);
  }

 private:
  std::mutex mutex_;
  std::map<std::string, std::size_t> seen_;
};

}  // namespace scanfilter::dds_io
