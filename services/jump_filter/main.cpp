// jump_filter: step 1 of the two-step filter as a service. Reads posed scans
// (rt/<ns>/posed_scan), labels jump points, publishes rt/<ns>/jump_filtered_scan.
#include <memory>
#include <optional>

#include <spdlog/spdlog.h>

#include "scanfilter/dds/filter_stage.hpp"
#include "scanfilter/dds/service_cli.hpp"
#include "scanfilter/dds/shutdown_signal.hpp"
#include "scanfilter/dds/topic_names.hpp"
#include "scanfilter/filter_config.hpp"
#include "scanfilter/input_error.hpp"
#include "scanfilter/jump_filter.hpp"
#include "scanfilter/yaml_section.hpp"

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
  ServiceCli cli("jump_filter", "scanfilter jump_filter: step 1 (jump points) of the two-step LiDAR filter",
                 "127.0.0.1:9472", {"filter"});
  if (const auto exit_code = cli.parse(argc, argv)) return *exit_code;
  const ServiceConfigFile& config = cli.config();
  return runLogged([&] {
    const FilterConfig filter = loadStageFilterConfig(config);

    ShutdownSignal::install();
    ServiceMetrics metrics("jump_filter", config.service.metrics_address, scanfilterVersion());
    DdsParticipant participant(config.service.participant);
    const std::string& ns = config.service.topic_namespace;
    FilterStage stage(participant, config.service, metrics, "jump_filter", rosTopic(ns, kPosedScanTopic),
                      rosTopic(ns, kJumpFilteredTopic), JumpStep(filter));
    spdlog::info("started: domain {}, {} -> {}, metrics http://{}/metrics", config.service.participant.domain_id,
                 rosTopic(ns, kPosedScanTopic), rosTopic(ns, kJumpFilteredTopic), metrics.address());
    while (!ShutdownSignal::waitFor(std::chrono::seconds(1))) {
      metrics.updateProcessStats();
      metrics.matched("reader", rosTopic(ns, kPosedScanTopic), stage.matchedWriters());
      metrics.matched("writer", rosTopic(ns, kJumpFilteredTopic), stage.matchedReaders());
    }
    spdlog::info("stopping after {} scans", stage.processed());
    spdlog::info("stopped");
    return 0;
  });
}
