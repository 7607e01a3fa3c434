#include "scanfilter/dds/upstream_presence.hpp"

#include <spdlog/spdlog.h>

namespace scanfilter::dds_io {

UpstreamPresence::UpstreamPresence(ServiceMetrics& metrics, std::string topic)
    : metrics_(metrics), topic_(std::move(topic)) {
  metrics_.upstreamAlive(topic_, false);
}

void UpstreamPresence::onChanged(int matched_writers) {
  std::lock_guard lock(mutex_);
  const bool alive = matched_writers > 0;
  if (alive == alive_) return;
  alive_ = alive;
  metrics_.upstreamAlive(topic_, alive);
  if (alive) spdlog::info("upstream of {} alive ({} writer(s) matched)", topic_, matched_writers);
  else spdlog::warn("upstream of {} lost: discovery dropped its last writer (it left, or its participant's lease ran out)", topic_);
}

}  // namespace scanfilter::dds_io
