// scan_recorder: subscribes to the pipeline's labelled scans and writes them
// to a scan log, so a live run can be compared with `scanfilter replay` or
// drawn with `scanfilter render`. Stops on SIGINT/SIGTERM or after --count scans.
// With --progress-every it says how many it has so far, so that a launcher
// can stop it once it holds every scan the source published
// (deploy/run-pipeline.sh): a pause in the source is no end of it.
#include <atomic>
#include <cmath>
#include <iostream>
#include <mutex>

#include <CLI/CLI.hpp>

#include "namespace_check.hpp"
#include "scanfilter/cli/option_checks.hpp"
#include "scanfilter/dds/dds_participant.hpp"
#include "scanfilter/dds/default_paths.hpp"
#include "scanfilter/dds/scan_message.hpp"
#include "scanfilter/dds/service_config.hpp"
#include "scanfilter/dds/shutdown_signal.hpp"
#include "scanfilter/dds/stream_qos.hpp"
#include "scanfilter/dds/topic_names.hpp"
#include "scanfilter/dds/typed_reader.hpp"
#include "scanfilter/scan_log_writer.hpp"
#include "scanfilter_typesPubSubTypes.h"

using namespace scanfilter;
using namespace scanfilter::dds_io;

int main(int argc, char** argv) {
  CLI::App app{"scan_recorder: record rt/<ns>/labeled_scan (or another LabeledScan topic) to a scan log"};
  // Bad arguments: one line (what and which), no usage dump.
  app.failure_message([](const CLI::App*, const CLI::Error& e) { return std::string(e.what()) + " (see --help)\n"; });
  ParticipantSettings participant_settings;
  participant_settings.profiles_file = defaultProfilesFile();
  participant_settings.name = "scanfilter_scan_recorder";
  std::string ns, topic = kLabeledScanTopic, output, config;
  std::uint64_t count = 0;
  double timeout_s = 0;
  double idle_exit_s = 0;
  double progress_every_s = 0;
  int queue_depth = StreamQos{}.queue_depth;
  app.add_option("-o,--output", output, "scan log to write")->required();
  app.add_option("--domain", participant_settings.domain_id, "DDS domain id")
      ->check(CLI::Range(0, kMaxDomainId))
      ->capture_default_str();
  app.add_option("--namespace", ns, "topic namespace (rt/<ns>/...)")->check(kNamespaceCheck);
  app.add_option("--topic", topic, "topic name under rt/<ns>/")->capture_default_str();
  app.add_option("--profiles-file", participant_settings.profiles_file, "Fast DDS XML profiles")->capture_default_str();
  std::string enclave;
  app.add_option("--enclave", enclave,
                 "DDS Security enclave directory (scanfilter-make-keystore; default: security off, or "
                 "--config's service.security)");
  app.add_option("--count", count, "stop after this many scans (0: until SIGINT/SIGTERM)")
      ->check(cli::wholeNumber("a scan count"));
  app.add_option("--timeout", timeout_s, "stop after this many seconds (0: no limit)")
      ->check(cli::numberAtLeast(0.0, "s"));
  app.add_option("--idle-exit", idle_exit_s, "stop once no scan arrived for this many seconds after the first (0: never)")
      ->check(cli::numberAtLeast(0.0, "s"));
  // A launcher polls these lines to know when the recorder holds everything;
  // a period beyond a minute would only make it wait.
  constexpr double kMaxProgressEveryS = 60.0;
  app.add_option("--progress-every", progress_every_s,
                 "print \"progress: N scans recorded\" on stdout at most this often, when N changed (0: never)")
      ->check(CLI::Range(0.0, kMaxProgressEveryS));
  app.add_option("--queue-depth", queue_depth, "reliable reader queue (match the services')")
      ->check(CLI::Range(1, kMaxQueueDepth))
      ->capture_default_str();
  app.add_option("--config", config,
                 "a YAML file with only a `service` section (config/scan_ingest.yaml documents it): its domain, "
                 "profile and discovery replace --domain and --profiles-file, e.g. to record on another host");
  app.set_version_flag("--version", "scan_recorder (scanfilter " SCANFILTER_VERSION ")");
  CLI11_PARSE(app, argc, argv);

  try {
    ShutdownSignal::install();
    if (!config.empty()) {
      const std::string name = participant_settings.name;
      participant_settings = loadServiceConfig(config, "127.0.0.1:0", {}).service.participant;
      participant_settings.name = name;
    }
    if (!enclave.empty()) participant_settings.security.enclave = enclave;
    DdsParticipant participant(participant_settings);
    std::mutex mutex;
    std::optional<ScanLogWriter> writer;
    std::atomic<std::uint64_t> recorded{0};
    std::atomic<std::int64_t> last_arrival_ns{0};
    ScanRecord record;
    StreamQos qos;
    qos.queue_depth = queue_depth;
    TypedReader<scanfilter_msgs::msg::dds_::LabeledScan_PubSubType> reader(
        participant, rosTopic(ns, topic), losslessReaderQos(qos), [&](LabeledScanMsg& msg) {
          std::lock_guard lock(mutex);
          if (count > 0 && recorded >= count) return;
          SensorInfo sensor;
          fromMessage(msg, record.scan, sensor);
          if (!writer) writer.emplace(output, ScanLogHeader{1, "scan_recorder " + rosTopic(ns, topic), sensor});
          writer->write(record);
          last_arrival_ns = std::chrono::steady_clock::now().time_since_epoch().count();
          if (++recorded == count) ShutdownSignal::request();
        });
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    const auto progress_period = std::chrono::duration<double>(progress_every_s);
    auto progress_at = std::chrono::steady_clock::now();
    std::uint64_t progress_said = 0;
    while (!ShutdownSignal::waitFor(std::chrono::milliseconds(100))) {
      const auto now = std::chrono::steady_clock::now();
      const std::uint64_t holds = recorded.load();
      if (progress_every_s > 0 && now - progress_at >= progress_period && holds != progress_said) {
        progress_said = holds;
        progress_at = now;
        std::cout << "progress: " << progress_said << " scans recorded" << std::endl;  // flushed: read while it runs
      }
      if (timeout_s > 0 && now > deadline) break;
      const auto idle = now - std::chrono::steady_clock::time_point(std::chrono::steady_clock::duration(last_arrival_ns.load()));
      if (idle_exit_s > 0 && last_arrival_ns.load() != 0 && idle > std::chrono::duration<double>(idle_exit_s)) break;
    }
    std::lock_guard lock(mutex);
    if (writer) writer->close();
    if (recorded == 0) {
      // The log's header is the first scan's sensor: without a scan there is no log to write.
      std::cout << "recorded 0 scans; nothing written to " << output << " (no scan arrived on " << rosTopic(ns, topic)
                << ")\n";
    } else {
      std::cout << "recorded " << recorded << " scans -> " << output << "\n";
    }
    return count > 0 && recorded < count ? 1 : 0;
  } catch (const std::exception& e) {
    std::cerr << "scan_recorder: error: " << e.what() << "\n";
    return 1;
  }
}
