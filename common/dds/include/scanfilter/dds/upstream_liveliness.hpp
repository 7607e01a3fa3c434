#pragma once
#include <mutex>
#include <string>

#include "scanfilter/dds/service_metrics.hpp"

namespace scanfilter::dds_io {

// What a service knows about the writers upstream of one stage topic it
// reads: alive or not by DDS liveliness (the stage topics' writers assert it
// automatically within a 1 s lease). Keeps scanfilter_upstream_alive current
// and logs each change once: up at info, gone at warn.
class UpstreamLiveliness {
 public:
  // The gauge starts at 0: nothing is known to be alive until a writer shows up.
  UpstreamLiveliness(ServiceMetrics& metrics, std::string topic);

  // The reader's liveliness callback: `alive_writers` live writers now.
  void onChanged(int alive_writers);

 private:
  ServiceMetrics& metrics_;
  std::string topic_;
  std::mutex mutex_;
  bool alive_ = false;
};

}  // namespace scanfilter::dds_io
