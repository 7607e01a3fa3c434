// scan_ingest: the pipeline's source. Replays a scan log or a CARMEN log (at
// the recorded speed, a multiple of it, or as fast as the pipeline accepts
// without loss) or runs the simulator on a scene, and publishes posed scans on
// rt/<ns>/posed_scan.
#include <memory>

#include <spdlog/spdlog.h>

#include "ingest_settings.hpp"
#include "live_source.hpp"
#include "scan_player.hpp"
#include "scanfilter/dds/service_runtime.hpp"
#include "scanfilter/dds/shutdown_signal.hpp"
#include "scanfilter/dds/stream_qos.hpp"
#include "scanfilter/dds/topic_names.hpp"
#include "scanfilter/input_error.hpp"
#include "scanfilter/sim/scan_simulator.hpp"
#include "scanfilter/yaml_section.hpp"

using namespace scanfilter;
using namespace scanfilter::dds_io;
using scanfilter::ingest::IngestSettings;
using scanfilter::ingest::readIngestSettings;

namespace {

std::unique_ptr<ScanSource> openSource(const IngestSettings& s) {
  if (s.kind == "log") {
    const ScanSourceOptions options{.carmen_range_max = s.carmen_range_max};
    // Read through once before any scan is published: a log cut short or
    // with a bad line fails here, not after half of it went downstream.
    const LogCheck check = checkLogToEnd(s.path, options);
    spdlog::info("{}: read to its end: {} scans ({} stamps earlier than the scan before, {} equal to it)", s.path,
                 check.scans, check.stamp_regressions, check.stamp_repeats);
    return openScanSource(s.path, options);
  }
  return std::make_unique<sim::ScanSimulator>(sim::findScene(s.scene), s.seed);
}

// Until the downstream readers matched (and discovery settled), so that no
// stage misses the first scans; false on timeout or a stop signal.
bool waitForSubscribers(const ingest::ScanPlayer::Writer& writer, const IngestSettings& s) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(s.wait_timeout_s);
  while (writer.matchedReaders() < s.wait_for_subscribers) {
    if (ShutdownSignal::waitFor(std::chrono::milliseconds(50)) || std::chrono::steady_clock::now() > deadline)
      return false;
  }
  return s.wait_for_subscribers == 0 || !ShutdownSignal::waitFor(kDiscoverySettle);
}

// Live: pose each scan from the driver's odometry and publish it until stopped.
int runLive(ServiceRuntime& runtime, const IngestSettings& settings, ingest::ScanPlayer::Writer& writer) {
  constexpr auto kDrainPeriod = std::chrono::milliseconds(5);
  ServiceMetrics& metrics = runtime.metrics();
  const std::string& ns = runtime.settings().topic_namespace;
  ingest::LiveSource live(runtime.participant(), ns, settings.live, metrics);
  // The driver's side in the start line and scanfilter_dds_matched, as every stage's inputs are.
  runtime.reportMatched("reader", rosTopic(ns, settings.live.scan_topic), [&] { return live.scanWriters(); });
  runtime.reportMatched("reader", rosTopic(ns, settings.live.odom_topic), [&] { return live.odometryWriters(); });
  LabeledScanMsg msg;
  std::uint64_t sequence = 0;
  runtime.runUntilStopped(kDrainPeriod, [&] {
    live.drain([&](const Scan& scan, const SensorInfo& sensor, const SourceScanMsg& source) {
      const TimeMsg received = wallClockNow();
      toMessage(scan, sensor, sequence++, msg);
      msg.source_scan(source);
      stampStage(msg, "scan_ingest", received);
      if (writer.write(msg)) metrics.scanPublished();
      else metrics.sampleRejected("write_failed");
    });
  });
  spdlog::info("published {} live scans, dropped {} without a pose and {} held longer than their odometry is kept",
               sequence, live.dropped(), live.droppedHeld());
  return 0;
}

// A log or the simulator: publish every scan, then (unless exit_at_end) keep
// the metrics current until stopped.
int runPlayback(ServiceRuntime& runtime, const IngestSettings& settings, ScanSource& source,
                ingest::ScanPlayer::Writer& writer) {
  runtime.logStarted();
  const ingest::PlaybackProgress progress(settings.progress_path);
  ingest::ScanPlayer player(source, writer, runtime.metrics(), settings.rate, progress, settings.wait_notice_s);
  const std::uint64_t published = player.play();
  writer.waitForAcknowledgments(runtime.settings().stream.max_blocking_s);
  spdlog::info("published {} scans", published);
  runtime.refreshGauges();
  // A source not played to its end is a failure (a supervisor restarts the
  // ingest, which resumes after the scans its progress file records, if set).
  if (player.stoppedShort()) return 1;
  if (!settings.exit_at_end) runtime.runUntilStopped();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const ServiceDescription description{
      "scan_ingest",
      "scanfilter scan_ingest: replays a scan log, CARMEN log or Mines URG-04LX log, simulates a scene, or poses a "
      "live LaserScan with its odometry (source.kind: log, simulator, live)",
      "127.0.0.1:9471", {"source", "live", "playback"}};
  return runService(argc, argv, description, [](ServiceRuntime& runtime) {
    const IngestSettings settings = readIngestSettings(runtime.config());
    auto source = settings.kind == "live" ? nullptr : openSource(settings);
    const std::string topic = runtime.topic(kPosedScanTopic);
    const StreamQos& stream = runtime.settings().stream;
    ingest::ScanPlayer::Writer writer(runtime.participant(), topic, losslessWriterQos(stream));
    writer.setFlowControl(flowControlWindow(stream), stream.max_blocking_s);
    // Lossless: while the jump_filter is gone (crashed, restarting) the
    // source holds instead of writing scans no reader will get.
    writer.holdForReaders(settings.wait_for_subscribers, [] { return ShutdownSignal::requested(); });
    runtime.reportMatched("writer", topic, [&] { return writer.matchedReaders(); });
    spdlog::info("{} source; waiting for {} reader(s) of {}", settings.kind, settings.wait_for_subscribers, topic);
    if (!waitForSubscribers(writer, settings)) {
      if (ShutdownSignal::requested()) return 0;
      spdlog::error("{} of {} subscribers matched within {} s; is the jump_filter running on domain {}?",
                    writer.matchedReaders(), settings.wait_for_subscribers, settings.wait_timeout_s,
                    runtime.settings().participant.domain_id);
      return 1;
    }
    if (settings.kind == "live") return runLive(runtime, settings, writer);
    return runPlayback(runtime, settings, *source, writer);
  });
}
