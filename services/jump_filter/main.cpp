// jump_filter: step 1 of the two-step filter as a service. Reads posed scans
// (rt/<ns>/posed_scan), labels jump points, publishes rt/<ns>/jump_filtered_scan.
#include <memory>
#include <optional>

#include <spdlog/spdlog.h>

#include "scanfilter/dds/filter_stage.hpp"
#include "scanfilter/dds/service_runtime.hpp"
#include "scanfilter/dds/topic_names.hpp"
#include "scanfilter/filter_config.hpp"
#include "scanfilter/jump_filter.hpp"

using namespace scanfilter;
using namespace scanfilter::dds_io;

namespace {

bool sameSensor(const SensorInfo& a, const SensorInfo& b) {
  return a.range_min == b.range_min && a.range_max == b.range_max && a.angular_accuracy_deg == b.angular_accuracy_deg;
}

// The jump filter for the sensor of the scan at hand; its `auto` parameters
// come from the sensor, so it is rebuilt if the sensor changes.
class JumpStep {
 public:
  explicit JumpStep(FilterConfig config) : config_(std::move(config)) {}

  void operator()(const Scan& scan, const SensorInfo& sensor, std::span<std::uint8_t> labels) {
    if (!config_.params.jump_enabled) return;
    if (!filter_ || !sameSensor(sensor, sensor_)) {
      filter_ = makeJumpFilter(config_.resolve(sensor).jump, Implementation::kFast);
      sensor_ = sensor;
    }
    filter_->apply(scan, sensor, labels);
  }

 private:
  FilterConfig config_;
  SensorInfo sensor_;
  std::shared_ptr<JumpFilter> filter_;  // shared: std::function needs a copyable step
};

}  // namespace

int main(int argc, char** argv) {
  const ServiceDescription description{"jump_filter",
                                       "scanfilter jump_filter: step 1 (jump points) of the two-step LiDAR filter",
                                       "127.0.0.1:9472", {"filter"}};
  return runService(argc, argv, description, [](ServiceRuntime& runtime) {
    const FilterConfig filter = loadStageFilterConfig(runtime.config());
    FilterStage stage(runtime, "jump_filter", kPosedScanTopic, kJumpFilteredTopic, JumpStep(filter));
    runtime.runUntilStopped();
    spdlog::info("stopping after {} scans", stage.processed());
    return 0;
  });
}
