// penetration_filter: step 2 of the two-step filter as a service. Reads
// rt/<ns>/jump_filtered_scan, labels misdetected points, publishes the
// labelled scan on rt/<ns>/labeled_scan and a REP 117 LaserScan (removed
// beams NaN by default, kept beams bit-identical) on rt/<ns>/scan_filtered for
// rviz2, slam_toolbox or nav2.
#include <memory>

#include <spdlog/spdlog.h>

#include "scanfilter/dds/filter_stage.hpp"
#include "scanfilter/dds/service_cli.hpp"
#include "scanfilter/dds/shutdown_signal.hpp"
#include "scanfilter/dds/topic_names.hpp"
#include "scanfilter/filter_config.hpp"
#include "scanfilter/input_error.hpp"
#include "scanfilter/penetration_filter.hpp"
#include "scanfilter/yaml_section.hpp"

using namespace scanfilter;
using namespace scanfilter::dds_io;

int main(int argc, char** argv) {
  ServiceCli cli("penetration_filter",
                 "scanfilter penetration_filter: step 2 (misdetected points) of the two-step LiDAR filter",
                 "127.0.0.1:9473", {"filter", "laser_scan"});
  if (const auto exit_code = cli.parse(argc, argv)) return *exit_code;
  const ServiceConfigFile& config = cli.config();
  return runLogged([&] {
    const FilterConfig filter_config = loadStageFilterConfig(config);
    YamlSection scan_section(config.root, "laser_scan", config.path);
    std::string frame_id = "laser";
    scan_section.read("frame_id", frame_id);
    std::string removed_beams = "nan";
    scan_section.readChoice("removed_beams", removed_beams, {"nan", "inf"});
    const RemovedBeamValue removed = removed_beams == "nan" ? RemovedBeamValue::kNaN : RemovedBeamValue::kInfinity;
    scan_section.rejectUnknownKeys();

    ShutdownSignal::install();
    ServiceMetrics metrics("penetration_filter", config.service.metrics_address, scanfilterVersion());
    DdsParticipant participant(config.service.participant);
    const std::string& ns = config.service.topic_namespace;
    // Step 2's parameters have no `auto` values: one filter, whatever the sensor.
    auto filter = makePenetrationFilter(filter_config.params.penetration, Implementation::kFast);
    const bool enabled = filter_config.params.penetration_enabled;
    TypedWriter<sensor_msgs::msg::dds_::LaserScan_PubSubType> laser_writer(
        participant, rosTopic(ns, kFilteredLaserScanTopic), rosDefaultWriterQos());
    LaserScanMsg laser;
    FilterStage stage(
        participant, config.service, metrics, "penetration_filter", rosTopic(ns, kJumpFilteredTopic),
        rosTopic(ns, kLabeledScanTopic),
        [&](const Scan& scan, const SensorInfo& sensor, std::span<std::uint8_t> labels) {
          if (enabled) filter->apply(scan, sensor, labels);
        },
        [&](const LabeledScanMsg& msg) {
          toFilteredLaserScan(msg, frame_id, removed, laser);
          laser_writer.write(laser);
        });
    spdlog::info("started: domain {}, {} -> {} and {}, metrics http://{}/metrics",
                 config.service.participant.domain_id, rosTopic(ns, kJumpFilteredTopic),
                 rosTopic(ns, kLabeledScanTopic), rosTopic(ns, kFilteredLaserScanTopic), metrics.address());
    while (!ShutdownSignal::waitFor(std::chrono::seconds(1))) {
      metrics.updateProcessStats();
      metrics.matched("reader", rosTopic(ns, kJumpFilteredTopic), stage.matchedWriters());
      metrics.matched("writer", rosTopic(ns, kLabeledScanTopic), stage.matchedReaders());
      metrics.matched("writer", rosTopic(ns, kFilteredLaserScanTopic), laser_writer.matchedReaders());
    }
    spdlog::info("stopping after {} scans ({} penetration cache resets)", stage.processed(), filter->resetCount());
    spdlog::info("stopped");
    return 0;
  });
}
