// penetration_filter: step 2 of the two-step filter as a service. Reads
// rt/<ns>/jump_filtered_scan, labels misdetected points, publishes the
// labelled scan on rt/<ns>/labeled_scan and a REP 117 LaserScan (removed
// beams NaN by default, kept beams bit-identical) on rt/<ns>/scan_filtered for
// rviz2, slam_toolbox or nav2.
#include <cstdint>
#include <memory>
#include <optional>

#include <spdlog/spdlog.h>

#include "laser_scan_settings.hpp"
#include "scanfilter/dds/filter_stage.hpp"
#include "scanfilter/dds/per_sensor_filter.hpp"
#include "scanfilter/dds/service_runtime.hpp"
#include "scanfilter/dds/stream_qos.hpp"
#include "scanfilter/dds/topic_names.hpp"
#include "scanfilter/filter_config.hpp"
#include "scanfilter/penetration_filter.hpp"

using namespace scanfilter;
using namespace scanfilter::dds_io;

int main(int argc, char** argv) {
  const ServiceDescription description{
      "penetration_filter", "scanfilter penetration_filter: step 2 (misdetected points) of the two-step LiDAR filter",
      "127.0.0.1:9473", {"filter", "laser_scan"}};
  return runService(argc, argv, description, [](ServiceRuntime& runtime) {
    const FilterConfig filter_config = loadStageFilterConfig(runtime.config());
    const LaserScanSettings laser_settings = readLaserScanSettings(runtime.config());
    // obs_th follows the sensor's angular step: one filter per sensor.
    PerSensorFilter<PenetrationFilter> filters(filter_config, [](const TwoStepFilterParams& p) {
      return makePenetrationFilter(p.penetration, Implementation::kFast);
    });
    const bool enabled = filter_config.params.penetration_enabled;
    const std::string laser_topic = runtime.topic(kFilteredLaserScanTopic);
    TypedWriter<sensor_msgs::msg::dds_::LaserScan_PubSubType> laser_writer(runtime.participant(), laser_topic,
                                                                          rosDefaultWriterQos());
    runtime.reportMatched("writer", laser_topic, [&] { return laser_writer.matchedReaders(); });
    LaserScanMsg laser;
    std::optional<FilterStage> stage;
    stage.emplace(
        runtime, "penetration_filter", kJumpFilteredTopic, kLabeledScanTopic,
        [&](const Scan& scan, const SensorInfo& sensor, std::span<std::uint8_t> labels) {
          if (enabled) filters.forSensor(sensor).apply(scan, sensor, labels);
        },
        [&](const LabeledScanMsg& msg) {
          toFilteredLaserScan(msg, laser_settings.frame_id, laser_settings.removed, laser);
          laser_writer.write(laser);
        });
    runtime.runUntilStopped();
    // The stage's reader thread runs the filters until the stage is gone
    // (its destructor joins it): only then are they ours to read. Reading
    // them before was a data race (ThreadSanitizer, docs/reliability.md).
    const std::uint64_t processed = stage->processed();
    stage.reset();
    const PenetrationFilter* filter = filters.current();
    spdlog::info("stopping after {} scans ({} penetration cache resets, {} frames not judged: did not fit the cache)",
                 processed, filter ? filter->resetCount() : 0, filter ? filter->unalignedFrames() : 0);
    return 0;
  });
}
