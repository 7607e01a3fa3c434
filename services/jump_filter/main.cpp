// jump_filter: step 1 of the two-step filter as a service. Reads posed scans
// (rt/<ns>/posed_scan), labels jump points, publishes rt/<ns>/jump_filtered_scan.

#include <spdlog/spdlog.h>

#include "scanfilter/dds/filter_stage.hpp"
#include "scanfilter/dds/per_sensor_filter.hpp"
#include "scanfilter/dds/service_runtime.hpp"
#include "scanfilter/dds/topic_names.hpp"
#include "scanfilter/filter_config.hpp"
#include "scanfilter/jump_filter.hpp"

#include "noise_metrics.hpp"

using namespace scanfilter;
using namespace scanfilter::dds_io;

int main(int argc, char** argv) {
  const ServiceDescription description{"jump_filter",
                                       "scanfilter jump_filter: step 1 (jump points) of the two-step LiDAR filter",
                                       "127.0.0.1:9472", {"filter"}};
  return runService(argc, argv, description, [](ServiceRuntime& runtime) {
    const FilterConfig config = loadStageFilterConfig(runtime.config());
    PerSensorFilter<JumpFilter> filters(
        config, [](const TwoStepFilterParams& p) { return makeJumpFilter(p.jump, Implementation::kFast); });
    const bool enabled = config.params.jump_enabled;
    jump_service::NoiseMetrics noise(runtime.metrics());
    FilterStage stage(runtime, "jump_filter", kPosedScanTopic, kJumpFilteredTopic,
                      [&](const Scan& scan, const SensorInfo& sensor, std::span<std::uint8_t> labels) {
                        if (!enabled) return;
                        JumpFilter& filter = filters.forSensor(sensor);
                        filter.apply(scan, sensor, labels);
                        noise.judgedWith(filter.noiseModel());
                      });
    runtime.runUntilStopped();
    spdlog::info("stopping after {} scans", stage.processed());
    return 0;
  });
}
