#include "scanfilter/dds/filter_stage.hpp"

#include <chrono>

#include <spdlog/spdlog.h>

#include "scanfilter/dds/shutdown_signal.hpp"
#include "scanfilter/dds/stream_qos.hpp"
#include "scanfilter/point_code.hpp"

namespace scanfilter::dds_io {

FilterStage::FilterStage(ServiceRuntime& runtime, std::string stage, const std::string& input,
                         const std::string& output, Step step, AfterPublish after_publish)
    : metrics_(runtime.metrics()),
      stage_(std::move(stage)),
      step_(std::move(step)),
      after_publish_(std::move(after_publish)),
      upstream_(runtime.metrics(), runtime.topic(input)),
      writer_(runtime.participant(), runtime.topic(output), losslessWriterQos(runtime.settings().stream)),
      reader_(runtime.participant(), runtime.topic(input), losslessReaderQos(runtime.settings().stream),
              [this](LabeledScanMsg& msg) { onSample(msg); }, [this](int writers) { upstream_.onChanged(writers); }) {
  writer_.setFlowControl(flowControlWindow(runtime.settings().stream), runtime.settings().stream.max_blocking_s);
  // Lossless: a departed reader (a crashed stage) is waited for, not written past.
  writer_.holdForReaders(runtime.settings().stream.required_readers, [] { return ShutdownSignal::requested(); });
  runtime.reportMatched("reader", runtime.topic(input), [this] { return reader_.matchedWriters(); });
  runtime.reportMatched("writer", runtime.topic(output), [this] { return writer_.matchedReaders(); });
}

void FilterStage::onSample(LabeledScanMsg& msg) {
  const TimeMsg received = wallClockNow();
  metrics_.scanReceived();
  if (const auto reason = rejectionReason(msg)) {
    metrics_.sampleRejected(*reason);
    rejections_.warn(*reason, "dropped scan " + std::to_string(msg.sequence_number()) + ": " + *reason);
    return;
  }
  // Where a restarted stage picked the stream up (what a crash cost is counted from it).
  if (processed_ == 0) spdlog::info("first scan since start: sequence {}", msg.sequence_number());
  if (!msg.timing().empty()) metrics_.hopLatency(toSeconds(received) - toSeconds(msg.timing().back().sent()));

  fromMessage(msg, scan_, sensor_);
  if (scan_.labels.empty()) {  // straight from ingest: every return valid so far
    scan_.labels.resize(scan_.size());
    for (std::size_t i = 0; i < scan_.size(); ++i)
      scan_.labels[i] = static_cast<std::uint8_t>(scan_.hasReturn(i) ? PointCode::kValid : PointCode::kNoReturn);
  }
  labels_before_ = scan_.labels;
  const auto start = std::chrono::steady_clock::now();
  step_(scan_, sensor_, scan_.labels);
  metrics_.processingTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  countRemoved(labels_before_, scan_.labels);

  msg.labels().assign(scan_.labels.begin(), scan_.labels.end());
  stampStage(msg, stage_, received);
  const auto outcome = writer_.send(msg);
  if (outcome == Writer::Outcome::kRefused) {
    metrics_.sampleRejected("write_failed");
    rejections_.warn("write_failed", "could not publish scan " + std::to_string(msg.sequence_number()) +
                                         " (Fast DDS return code " + std::to_string(writer_.lastError()) + ")");
    return;
  }
  if (outcome == Writer::Outcome::kSentUnacknowledged) {
    // The scan is out; a reader (one that crashed, say) did not acknowledge
    // in time. Its followers still get the scan and its LaserScan.
    metrics_.sampleRejected("unacknowledged");
    rejections_.warn("unacknowledged", "scan " + std::to_string(msg.sequence_number()) +
                                           " sent, but not every reader acknowledged within max_blocking_s");
  }
  metrics_.scanPublished();
  ++processed_;
  metrics_.endToEndLatency(toSeconds(wallClockNow()) - toSeconds(msg.timing().front().sent()));
  if (after_publish_) after_publish_(msg);
}

void FilterStage::countRemoved(std::span<const std::uint8_t> before, std::span<const std::uint8_t> after) {
  double jump = 0, misdetected = 0, restored = 0;
  for (std::size_t i = 0; i < after.size(); ++i) {
    if (after[i] == before[i]) continue;
    jump += after[i] == static_cast<std::uint8_t>(PointCode::kJump);
    misdetected += after[i] == static_cast<std::uint8_t>(PointCode::kMisdetected);
    // Step 2's rescue gives back jump points it found persistent.
    restored += before[i] == static_cast<std::uint8_t>(PointCode::kJump);
  }
  if (jump > 0) metrics_.pointsRemoved("jump", jump);
  if (misdetected > 0) metrics_.pointsRemoved("misdetected", misdetected);
  if (restored > 0) metrics_.pointsRestored(restored);
}

}  // namespace scanfilter::dds_io
