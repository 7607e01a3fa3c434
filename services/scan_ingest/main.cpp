// scan_ingest: the pipeline's source. Replays a scan log or a CARMEN log (at
// the recorded speed, a multiple of it, or as fast as the pipeline accepts
// without loss) or runs the simulator on a scene, and publishes posed scans on
// rt/<ns>/posed_scan.
#include <memory>

#include <spdlog/spdlog.h>

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

namespace {

struct IngestSettings {
  std::string kind = "simulator";
  std::string path;
  std::string scene = "hall";
  std::uint64_t seed = 1;
  double carmen_range_max = 80.0;
  ingest::PlaybackRate rate;
  ingest::LiveSettings live;
  int wait_for_subscribers = 1;
  double wait_timeout_s = 30.0;
  bool exit_at_end = true;
  std::string progress_path;
};

IngestSettings readIngestSettings(const ServiceConfigFile& config) {
  IngestSettings s;
  YamlSection source(config.root, "source", config.path);
  source.readChoice("kind", s.kind, {"log", "simulator", "live"});
  source.read("path", s.path);
  source.read("scene", s.scene);
  source.read("seed", s.seed);
  source.read("carmen_range_max", s.carmen_range_max);
  std::string rate = "recorded";
  source.read("rate", rate);
  if (!ingest::parsePlaybackRate(rate, s.rate))
    source.fail("rate", "expected recorded, max or a speed factor > 0, got \"" + rate + "\"");
  if (s.kind == "log" && s.path.empty()) source.fail("path", "a log source needs a path");
  s.path = config.resolvePath(s.path);
  source.rejectUnknownKeys();
  YamlSection live(config.root, "live", config.path);
  live.read("scan_topic", s.live.scan_topic);
  live.read("odom_topic", s.live.odom_topic);
  std::vector<double> mount = {0.0, 0.0, 0.0};
  live.read("mount", mount);
  if (mount.size() != 3) live.fail("mount", "expected [x, y, yaw]");
  s.live.mount.pose = {mount[0], mount[1], mount[2]};
  live.read("upside_down", s.live.mount.upside_down);
  live.read("max_pose_gap_s", s.live.max_pose_gap_s);
  live.read("max_pose_wait_s", s.live.max_pose_wait_s);
  live.read("reliable", s.live.reliable);
  live.requireRange("max_pose_gap_s", s.live.max_pose_gap_s, 1e-4, 60, "0.0001-60 (s)");
  live.requireRange("max_pose_wait_s", s.live.max_pose_wait_s, 0, 60, "0-60 (s)");
  live.rejectUnknownKeys();
  YamlSection playback(config.root, "playback", config.path);
  playback.read("wait_for_subscribers", s.wait_for_subscribers);
  playback.read("wait_timeout_s", s.wait_timeout_s);
  playback.read("exit_at_end", s.exit_at_end);
  playback.read("progress_path", s.progress_path);
  if (!s.progress_path.empty()) s.progress_path = config.resolvePath(s.progress_path);
  playback.requireRange("wait_for_subscribers", s.wait_for_subscribers, 0, 1000, "an integer 0-1000");
  playback.rejectUnknownKeys();
  return s;
}

std::unique_ptr<ScanSource> openSource(const IngestSettings& s) {
  if (s.kind == "log") return openScanSource(s.path, {.carmen_range_max = s.carmen_range_max});
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
  ingest::LiveSource live(runtime.participant(), runtime.settings().topic_namespace, settings.live, metrics);
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
  spdlog::info("published {} live scans, dropped {} without a pose", sequence, live.dropped());
  return 0;
}

// A log or the simulator: publish every scan, then (unless exit_at_end) keep
// the metrics current until stopped.
int runPlayback(ServiceRuntime& runtime, const IngestSettings& settings, ScanSource& source,
                ingest::ScanPlayer::Writer& writer) {
  runtime.logStarted();
  const ingest::PlaybackProgress progress(settings.progress_path);
  ingest::ScanPlayer player(source, writer, runtime.metrics(), settings.rate, progress);
  const std::uint64_t published = player.play();
  writer.waitForAcknowledgments(runtime.settings().stream.max_blocking_s);
  spdlog::info("published {} scans", published);
  runtime.refreshGauges();
  if (!settings.exit_at_end) runtime.runUntilStopped();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const ServiceDescription description{
      "scan_ingest", "scanfilter scan_ingest: replays a scan log or CARMEN log, or simulates a scene",
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
