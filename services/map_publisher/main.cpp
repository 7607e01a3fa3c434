// map_publisher: the occupancy map from the filtered, posed scans. Reads
// rt/<ns>/labeled_scan; publishes rt/<ns>/map (nav_msgs/OccupancyGrid,
// reliable + transient local, depth 1) when it changed, at most at
// publishing.rate_hz, and the changed rectangle on rt/<ns>/map_updates; saves
// the map (map_server PGM + YAML, PNG, exact state) periodically and on exit.
#include <filesystem>
#include <mutex>
#include <string>

#include <spdlog/spdlog.h>

#include "map_metrics.hpp"
#include "map_message.hpp"
#include "map_progress.hpp"
#include "publish_settings.hpp"
#include "scanfilter/dds/scan_message.hpp"
#include "scanfilter/dds/service_runtime.hpp"
#include "scanfilter/dds/stream_qos.hpp"
#include "scanfilter/dds/topic_names.hpp"
#include "scanfilter/dds/typed_reader.hpp"
#include "scanfilter/dds/typed_writer.hpp"
#include "scanfilter/dds/upstream_presence.hpp"
#include "scanfilter/map_config.hpp"
#include "scanfilter/map_files.hpp"
#include "scanfilter_typesPubSubTypes.h"

using namespace scanfilter;
using namespace scanfilter::dds_io;
using scanfilter::map_service::PublishSettings;
using scanfilter::map_service::readPublishSettings;

namespace {

eprosima::fastdds::dds::DataWriterQos latchedMapQos() {
  auto qos = rosDefaultWriterQos();
  qos.durability().kind = eprosima::fastdds::dds::TRANSIENT_LOCAL_DURABILITY_QOS;
  qos.history().kind = eprosima::fastdds::dds::KEEP_LAST_HISTORY_QOS;
  qos.history().depth = 1;
  return qos;
}

// The map the service builds: integrates each labelled scan, publishes the
// map and the changed rectangle when it changed, saves it now and then.
class MapService {
 public:
  MapService(ServiceRuntime& runtime, OccupancyGrid& grid, PublishSettings settings, map_service::MapProgress progress)
      : runtime_(runtime),
        grid_(grid),
        settings_(std::move(settings)),
        metrics_(runtime.metrics()),
        progress_(progress),
        upstream_(runtime.metrics(), runtime.topic(kLabeledScanTopic)),
        map_writer_(runtime.participant(), runtime.topic("map"), latchedMapQos()),
        update_writer_(runtime.participant(), runtime.topic("map_updates"), rosDefaultWriterQos()),
        reader_(runtime.participant(), runtime.topic(kLabeledScanTopic), losslessReaderQos(runtime.settings().stream),
                [this](LabeledScanMsg& msg) { integrate(msg); }, [this](int writers) { upstream_.onChanged(writers); }) {
    runtime.reportMatched("reader", runtime.topic(kLabeledScanTopic), [this] { return reader_.matchedWriters(); });
    runtime.reportMatched("writer", runtime.topic("map"), [this] { return map_writer_.matchedReaders(); });
    runtime.reportMatched("writer", runtime.topic("map_updates"), [this] { return update_writer_.matchedReaders(); });
    if (!settings_.save_path.empty()) metrics_.savedMapCurrent();  // the map starts empty or as loaded: nothing unsaved
  }

  // Once per publishing period.
  void tick() {
    publishIfChanged();
    metrics_.lastPublishAge(std::chrono::duration<double>(std::chrono::steady_clock::now() - last_publish_).count());
    if (std::chrono::steady_clock::now() - last_save_ > std::chrono::duration<double>(settings_.save_period_s)) periodicSave();
  }

  // A periodic save that fails (disk full, folder gone) must not end the
  // service and the map in memory with it: it says why and tries again next
  // period, while scanfilter_map_last_save_timestamp_seconds stands still
  // (alert ScanfilterMapNotSaved). The save at shutdown still fails loudly.
  void periodicSave() {
    try {
      save();
    } catch (const std::exception& e) {
      spdlog::error("saving the map to {}.* failed: {}; the map stays in memory, next try in {} s",
                    settings_.save_path, e.what(), settings_.save_period_s);
    }
  }

  // The reader thread integrates under mutex_ for as long as the service
  // lives: main reads the count through here, not from the grid.
  std::size_t scansIntegrated() {
    std::lock_guard lock(mutex_);
    return grid_.scansIntegrated();
  }

  // Whether files were written: not without a save_path, nor for a map that holds nothing yet.
  bool save() {
    last_save_ = std::chrono::steady_clock::now();
    if (settings_.save_path.empty()) return false;
    std::lock_guard lock(mutex_);
    const bool any = !grid_.bounds().empty();
    if (any) {
      // The state and which scans it holds, in one rename.
      saveMap(grid_, settings_.save_path, progress_.toText(),
              "OCCUPANCY MAP, " + std::to_string(progress_.scans_integrated) + " SCANS");
      progress_.save(settings_.save_path);  // a readable copy
      metrics_.mapSaved();
    }
    metrics_.savedMapCurrent();
    return any;
  }

 private:
  void integrate(LabeledScanMsg& msg) {
    const TimeMsg received = wallClockNow();
    ServiceMetrics& service_metrics = runtime_.metrics();
    service_metrics.scanReceived();
    if (const auto reason = rejectionReason(msg)) {
      service_metrics.sampleRejected(*reason);
      return;
    }
    // The latencies as the filter stages meter them; this stage's "sent" is the scan in the map.
    if (!msg.timing().empty()) service_metrics.hopLatency(toSeconds(received) - toSeconds(msg.timing().back().sent()));
    fromMessage(msg, scan_, sensor_);
    std::lock_guard lock(mutex_);
    const auto start = std::chrono::steady_clock::now();
    grid_.integrate(scan_, sensor_, scan_.labels);
    service_metrics.processingTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    if (!msg.timing().empty())
      service_metrics.endToEndLatency(toSeconds(wallClockNow()) - toSeconds(msg.timing().front().sent()));
    metrics_.scanIntegrated();
    if (progress_.scans_integrated++ == loaded_scans_)  // which scan a restart resumed at
      spdlog::info("first scan integrated since start: sequence {}", msg.sequence_number());
    progress_.last_sequence = msg.sequence_number();
  }

  void publishIfChanged() {
    const auto start = std::chrono::steady_clock::now();
    std::lock_guard lock(mutex_);
    const CellBox changed = grid_.takeChanged();
    if (changed.empty()) return;
    toMapMsg(grid_, settings_.frame_id, map_msg_);
    map_writer_.write(map_msg_);
    toUpdateMsg(grid_, changed, settings_.frame_id, update_msg_);
    update_writer_.write(update_msg_);
    last_publish_ = std::chrono::steady_clock::now();
    metrics_.published(grid_, std::chrono::duration<double>(last_publish_ - start).count());
  }

  ServiceRuntime& runtime_;
  OccupancyGrid& grid_;
  PublishSettings settings_;
  map_service::MapMetrics metrics_;
  map_service::MapProgress progress_;  // what the map holds (saved with it)
  const std::uint64_t loaded_scans_ = progress_.scans_integrated;
  UpstreamPresence upstream_;
  std::mutex mutex_;
  Scan scan_;
  SensorInfo sensor_;
  MapMsg map_msg_;
  MapUpdateMsg update_msg_;
  std::chrono::steady_clock::time_point last_publish_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point last_save_ = last_publish_;
  TypedWriter<nav_msgs::msg::dds_::OccupancyGrid_PubSubType> map_writer_;
  TypedWriter<map_msgs::msg::dds_::OccupancyGridUpdate_PubSubType> update_writer_;
  TypedReader<scanfilter_msgs::msg::dds_::LabeledScan_PubSubType> reader_;  // last: callbacks see ready writers
};

}  // namespace

int main(int argc, char** argv) {
  const ServiceDescription description{"map_publisher",
                                       "scanfilter map_publisher: occupancy map from the filtered scans, on rt/map",
                                       "127.0.0.1:9474", {"map", "publishing"}};
  return runService(argc, argv, description, [](ServiceRuntime& runtime) {
    const ServiceConfigFile& config = runtime.config();
    OccupancyGrid grid(readMapParams(config.root, config.path));
    const PublishSettings publish = readPublishSettings(config);
    map_service::MapProgress progress;
    if (publish.load_on_start && !publish.save_path.empty() && std::filesystem::exists(publish.save_path + ".logodds")) {
      const std::string note = loadMapState(grid, publish.save_path);
      progress = note.empty() ? map_service::MapProgress::load(publish.save_path)  // saved before the note existed
                              : map_service::MapProgress::parse(note, publish.save_path + ".logodds");
      spdlog::info("continuing from {}.logodds ({} x {} cells, {} scans, the last sequence {})", publish.save_path,
                   grid.bounds().width(), grid.bounds().height(), progress.scans_integrated,
                   progress.last_sequence ? std::to_string(*progress.last_sequence) : "none");
    }
    MapService service(runtime, grid, publish, progress);
    const auto period = std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::duration<double>(1.0 / publish.rate_hz));
    runtime.runUntilStopped(period, [&] { service.tick(); });
    const bool saved = service.save();
    const std::string where = publish.save_path.empty() ? ""
                              : saved                   ? "; map saved to " + publish.save_path + ".*"
                                                        : "; the map holds nothing, nothing saved";
    spdlog::info("stopping after {} scans{}", service.scansIntegrated(), where);
    return 0;
  });
}
