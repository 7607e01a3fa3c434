#include "scanfilter/dds/upstream_liveliness.hpp"

#include <spdlog/spdlog.h>

namespace scanfilter::dds_io {

UpstreamLiveliness::UpstreamLiveliness(ServiceMetrics& metrics, std::string topic)
    : metrics_(metrics), topic_(std::move(topic)) {
  metrics_.upstreamAlive(topic_, false);
}

void UpstreamLiveliness::onChanged(int alive_writers) {
  std::lock_guard lock(mutex_);
  const bool alive = alive_writers > 0;
  if (alive == alive_) return;
  alive_ = alive;
  metrics_.upstreamAlive(topic_, alive);
  if (alive) spdlog::info("upstream of {} alive ({} writer(s))", topic_, alive_writers);
  else spdlog::warn("upstream of {} lost: no writer asserted liveliness within its lease", topic_);
}

}  // namespace scanfilter::dds_io
