#include "sample_pipeline.hpp"

#include "scanfilter/point_code.hpp"
#include "scanfilter_typesPubSubTypes.h"

namespace scanfilter::fuzz {

namespace {
constexpr std::size_t kFrameLengthBytes = 2;

// Read once per process: the config is not the input under test, and parsing
// it three times an input was most of an execution's time.
const FilterConfig& shippedFilterConfig() {
  static const FilterConfig config = loadFilterConfig(SCANFILTER_SOURCE_DIR "/config/filter.yaml");
  return config;
}
}  // namespace

std::vector<std::span<const std::uint8_t>> splitFrames(const std::uint8_t* data, std::size_t size) {
  std::vector<std::span<const std::uint8_t>> frames;
  std::size_t at = 0;
  while (at + kFrameLengthBytes <= size && frames.size() < kMaxFrames) {
    const std::size_t length = data[at] | (static_cast<std::size_t>(data[at + 1]) << 8);
    at += kFrameLengthBytes;
    const std::size_t taken = std::min(length, size - at);
    frames.emplace_back(data + at, taken);
    at += taken;
  }
  return frames;
}

ServiceChain::ServiceChain()
    : jump_(shippedFilterConfig(),
            [](const TwoStepFilterParams& p) { return makeJumpFilter(p.jump, Implementation::kFast); }),
      penetration_(shippedFilterConfig(),
                   [](const TwoStepFilterParams& p) { return makePenetrationFilter(p.penetration, Implementation::kFast); }),
      config_(shippedFilterConfig()),
      grid_(OccupancyGridParams{}) {}

template <typename Filter>
bool ServiceChain::filterStage(dds_io::LabeledScanMsg& msg, const char* stage, dds_io::PerSensorFilter<Filter>& filters,
                               bool enabled) {
  const dds_io::TimeMsg received = dds_io::wallClockNow();
  if (dds_io::rejectionReason(msg)) return false;
  dds_io::fromMessage(msg, scan_, sensor_);
  if (scan_.labels.empty()) {
    scan_.labels.resize(scan_.size());
    for (std::size_t i = 0; i < scan_.size(); ++i)
      scan_.labels[i] = static_cast<std::uint8_t>(scan_.hasReturn(i) ? PointCode::kValid : PointCode::kNoReturn);
  }
  if (enabled) filters.forSensor(sensor_).apply(scan_, sensor_, scan_.labels);
  msg.labels().assign(scan_.labels.begin(), scan_.labels.end());
  dds_io::stampStage(msg, stage, received);
  serialize<scanfilter_msgs::msg::dds_::LabeledScan_PubSubType>(msg);
  return true;
}

void ServiceChain::onPosedScan(dds_io::LabeledScanMsg& msg) {
  if (!filterStage(msg, "jump_filter", jump_, config_.params.jump_enabled)) return;
  if (!filterStage(msg, "penetration_filter", penetration_, config_.params.penetration_enabled)) return;
  dds_io::toFilteredLaserScan(msg, "laser", dds_io::RemovedBeamValue::kNaN, laser_);
  serialize<sensor_msgs::msg::dds_::LaserScan_PubSubType>(laser_);
  // map_publisher's integrate().
  if (dds_io::rejectionReason(msg)) return;
  dds_io::fromMessage(msg, scan_, sensor_);
  grid_.integrate(scan_, sensor_, scan_.labels);
}

}  // namespace scanfilter::fuzz
