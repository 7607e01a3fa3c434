#pragma once
#include <mutex>
#include <string>

#include "scanfilter/dds/service_metrics.hpp"

namespace scanfilter::dds_io {

// What a service knows about the writers upstream of one stage topic it
// reads: present while at least one is matched. Discovery drops a writer when
// its process leaves or its participant's lease runs out (3 s in the shipped
// profile: a crash, a frozen process, a lost link). Keeps
// scanfilter_upstream_alive current and logs each change once: up at info,
// gone at warn.
class UpstreamPresence {
 public:
  // The gauge starts at 0: nothing is known to be there until a writer matches.
  UpstreamPresence(ServiceMetrics& metrics, std::string topic);

  // The reader's matching callback: `matched_writers` writers matched now.
  void onChanged(int matched_writers);

 private:
  ServiceMetrics& metrics_;
  std::string topic_;
  std::mutex mutex_;
  bool alive_ = false;
};

}  // namespace scanfilter::dds_io
