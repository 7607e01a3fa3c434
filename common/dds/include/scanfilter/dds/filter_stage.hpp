#pragma once
#include <atomic>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "scanfilter/dds/rate_limited_log.hpp"
#include "scanfilter/dds/scan_message.hpp"
#include "scanfilter/dds/service_runtime.hpp"
#include "scanfilter/dds/typed_reader.hpp"
#include "scanfilter/dds/typed_writer.hpp"
#include "scanfilter/dds/upstream_presence.hpp"
#include "scanfilter_typesPubSubTypes.h"

namespace scanfilter::dds_io {

// One filtering step as a service: takes labelled scans from one topic, runs
// the step, publishes them with the step's labels on another, and meters it
// all. Invalid samples are counted, logged once per kind, and dropped. The
// output holds while fewer than service.required_readers read it, and
// scanfilter_upstream_alive follows the input's writers.
class FilterStage {
 public:
  // The step: reads the scan and its labels so far, writes the new labels.
  using Step = std::function<void(const Scan&, const SensorInfo&, std::span<std::uint8_t> labels)>;
  // Called after each publish (the penetration filter also sends a LaserScan).
  using AfterPublish = std::function<void(const LabeledScanMsg&)>;

  // Reads rt/<ns>/<input>, writes rt/<ns>/<output>; both reported to the
  // runtime's matched-endpoint gauges.
  FilterStage(ServiceRuntime& runtime, std::string stage, const std::string& input, const std::string& output,
              Step step, AfterPublish after_publish = {});

  std::uint64_t processed() const { return processed_.load(); }

 private:
  void onSample(LabeledScanMsg& msg);
  void countRemoved(std::span<const std::uint8_t> before, std::span<const std::uint8_t> after);

  ServiceMetrics& metrics_;
  std::string stage_;
  Step step_;
  AfterPublish after_publish_;
  OncePerKindLog rejections_;
  Scan scan_;
  SensorInfo sensor_;
  std::vector<std::uint8_t> labels_before_;
  std::atomic<std::uint64_t> processed_{0};
  UpstreamPresence upstream_;
  using Writer = TypedWriter<scanfilter_msgs::msg::dds_::LabeledScan_PubSubType>;
  Writer writer_;
  TypedReader<scanfilter_msgs::msg::dds_::LabeledScan_PubSubType> reader_;  // last: callbacks see a ready writer
};

}  // namespace scanfilter::dds_io
