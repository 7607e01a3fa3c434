// map_publisher: the occupancy map from the filtered, posed scans. Reads
// rt/<ns>/labeled_scan; publishes rt/<ns>/map (nav_msgs/OccupancyGrid,
// reliable + transient local, depth 1) when it changed, at most at
// publishing.rate_hz, and the changed rectangle on rt/<ns>/map_updates; saves
// the map (map_server PGM + YAML, PNG, exact state) periodically and on exit.
#include <filesystem>
#include <mutex>

#include <prometheus/counter.h>
#include <prometheus/gauge.h>
#include <prometheus/histogram.h>
#include <spdlog/spdlog.h>

#include "scanfilter/dds/dds_participant.hpp"
#include "scanfilter/dds/scan_message.hpp"
#include "scanfilter/dds/service_cli.hpp"
#include "scanfilter/dds/service_metrics.hpp"
#include "scanfilter/dds/shutdown_signal.hpp"
#include "scanfilter/dds/stream_qos.hpp"
#include "scanfilter/dds/topic_names.hpp"
#include "scanfilter/dds/typed_reader.hpp"
#include "scanfilter/dds/typed_writer.hpp"
#include "scanfilter/map_config.hpp"
#include "scanfilter/map_files.hpp"
#include "scanfilter_typesPubSubTypes.h"

using namespace scanfilter;
using namespace scanfilter::dds_io;

namespace {

using MapMsg = nav_msgs::msg::dds_::OccupancyGrid_;
using MapUpdateMsg = map_msgs::msg::dds_::OccupancyGridUpdate_;

struct PublishSettings {
  double rate_hz = 1.0;
  std::string frame_id = "map";
  std::string save_path;
  double save_period_s = 30.0;
  bool load_on_start = false;
};

PublishSettings readPublishSettings(const ServiceConfigFile& config) {
  PublishSettings s;
  YamlSection section(config.root, "publishing", config.path);
  section.read("rate_hz", s.rate_hz);
  section.read("frame_id", s.frame_id);
  section.read("save_path", s.save_path);
  section.read("save_period_s", s.save_period_s);
  section.read("load_on_start", s.load_on_start);
  section.requireRange("rate_hz", s.rate_hz, 0.01, 100, "0.01-100 (Hz)");
  section.requireRange("save_period_s", s.save_period_s, 0.1, 1e6, "a value >= 0.1 (s)");
  section.rejectUnknownKeys();
  s.save_path = config.resolvePath(s.save_path);
  return s;
}

eprosima::fastdds::dds::DataWriterQos latchedMapQos() {
  auto qos = rosDefaultWriterQos();
  qos.durability().kind = eprosima::fastdds::dds::TRANSIENT_LOCAL_DURABILITY_QOS;
  qos.history().kind = eprosima::fastdds::dds::KEEP_LAST_HISTORY_QOS;
  qos.history().depth = 1;
  return qos;
}

// The whole map as a ROS OccupancyGrid: row-major from the lower-left cell.
void toMapMsg(const OccupancyGrid& grid, const std::string& frame_id, MapMsg& out) {
  const CellBox box = grid.bounds();
  out.header().stamp(wallClockNow());
  out.header().frame_id(frame_id);
  out.info().map_load_time(wallClockNow());
  out.info().resolution(static_cast<float>(grid.params().resolution));
  out.info().width(static_cast<uint32_t>(box.width()));
  out.info().height(static_cast<uint32_t>(box.height()));
  const Eigen::Vector2d corner = grid.cellCentre(box.lo) - Eigen::Vector2d::Constant(grid.params().resolution / 2);
  out.info().origin().position().x(corner.x());
  out.info().origin().position().y(corner.y());
  out.info().origin().orientation().w(1.0);
  out.data().resize(static_cast<std::size_t>(box.width() * box.height()));
  std::size_t k = 0;
  for (std::int32_t y = box.lo.y; y <= box.hi.y; ++y)
    for (std::int32_t x = box.lo.x; x <= box.hi.x; ++x) out.data()[k++] = static_cast<char>(grid.rosValue({x, y}));
}

// The changed rectangle, in cells of the published map (origin = bounds.lo).
void toUpdateMsg(const OccupancyGrid& grid, const CellBox& changed, const std::string& frame_id, MapUpdateMsg& out) {
  out.header().stamp(wallClockNow());
  out.header().frame_id(frame_id);
  out.x(changed.lo.x - grid.bounds().lo.x);
  out.y(changed.lo.y - grid.bounds().lo.y);
  out.width(static_cast<uint32_t>(changed.width()));
  out.height(static_cast<uint32_t>(changed.height()));
  out.data().resize(static_cast<std::size_t>(changed.width() * changed.height()));
  std::size_t k = 0;
  for (std::int32_t y = changed.lo.y; y <= changed.hi.y; ++y)
    for (std::int32_t x = changed.lo.x; x <= changed.hi.x; ++x) out.data()[k++] = static_cast<char>(grid.rosValue({x, y}));
}

std::size_t occupiedCells(const OccupancyGrid& grid) {
  const CellBox box = grid.bounds();
  std::size_t n = 0;
  for (std::int32_t y = box.lo.y; y <= box.hi.y; ++y)
    for (std::int32_t x = box.lo.x; x <= box.hi.x; ++x) n += grid.probability({x, y}) > grid.params().occupied_threshold;
  return n;
}

}  // namespace

int main(int argc, char** argv) {
  ServiceCli cli("map_publisher", "scanfilter map_publisher: occupancy map from the filtered scans, on rt/map",
                 "127.0.0.1:9474", {"map", "publishing"});
  if (const auto exit_code = cli.parse(argc, argv)) return *exit_code;
  const ServiceConfigFile& config = cli.config();
  return runLogged([&] {
    OccupancyGrid grid(readMapParams(config.root, config.path));
    const PublishSettings publish = readPublishSettings(config);
    if (publish.load_on_start && !publish.save_path.empty() && std::filesystem::exists(publish.save_path + ".logodds")) {
      loadMapState(grid, publish.save_path);
      spdlog::info("continuing from {}.logodds ({} x {} cells)", publish.save_path, grid.bounds().width(),
                   grid.bounds().height());
    }
    ShutdownSignal::install();
    ServiceMetrics metrics("map_publisher", config.service.metrics_address, scanfilterVersion());
    const prometheus::Labels labels{{"service", "map_publisher"}};
    auto& cells = prometheus::BuildGauge().Name("scanfilter_map_cells").Help("Cells in the map's bounds").Register(metrics.registry()).Add(labels);
    auto& bytes = prometheus::BuildGauge().Name("scanfilter_map_memory_bytes").Help("Memory of the map's tiles").Register(metrics.registry()).Add(labels);
    auto& integrated = prometheus::BuildCounter().Name("scanfilter_map_scans_integrated_total").Help("Scans integrated into the map").Register(metrics.registry()).Add(labels);
    auto& occupied = prometheus::BuildGauge().Name("scanfilter_map_occupied_cells").Help("Cells above occupied_threshold").Register(metrics.registry()).Add(labels);
    auto& publish_time = prometheus::BuildHistogram().Name("scanfilter_map_publish_seconds").Help("Time to build and publish rt/map")
                             .Register(metrics.registry()).Add(labels, ServiceMetrics::latencyBuckets());
    auto& publish_age = prometheus::BuildGauge().Name("scanfilter_map_last_publish_age_seconds").Help("Seconds since rt/map was last published")
                            .Register(metrics.registry()).Add(labels);

    DdsParticipant participant(config.service.participant);
    const std::string& ns = config.service.topic_namespace;
    TypedWriter<nav_msgs::msg::dds_::OccupancyGrid_PubSubType> map_writer(participant, rosTopic(ns, "map"), latchedMapQos());
    TypedWriter<map_msgs::msg::dds_::OccupancyGridUpdate_PubSubType> update_writer(participant, rosTopic(ns, "map_updates"),
                                                                                  rosDefaultWriterQos());
    std::mutex mutex;
    Scan scan;
    SensorInfo sensor;
    TypedReader<scanfilter_msgs::msg::dds_::LabeledScan_PubSubType> reader(
        participant, rosTopic(ns, kLabeledScanTopic), losslessReaderQos(config.service.stream), [&](LabeledScanMsg& msg) {
          metrics.scanReceived();
          if (const auto reason = rejectionReason(msg)) {
            metrics.sampleRejected(*reason);
            return;
          }
          fromMessage(msg, scan, sensor);
          std::lock_guard lock(mutex);
          grid.integrate(scan, sensor, scan.labels);
          integrated.Increment();
        });
    spdlog::info("started: domain {}, {} -> {} and {}, metrics http://{}/metrics", config.service.participant.domain_id,
                 rosTopic(ns, kLabeledScanTopic), rosTopic(ns, "map"), rosTopic(ns, "map_updates"), metrics.address());

    MapMsg map_msg;
    MapUpdateMsg update_msg;
    auto last_publish = std::chrono::steady_clock::now();
    auto last_save = last_publish;
    const auto period = std::chrono::duration<double>(1.0 / publish.rate_hz);
    const auto save = [&] {
      if (publish.save_path.empty()) return;
      std::lock_guard lock(mutex);
      if (!grid.bounds().empty()) saveMap(grid, publish.save_path);
    };
    while (!ShutdownSignal::waitFor(std::chrono::duration_cast<std::chrono::milliseconds>(period))) {
      const auto start = std::chrono::steady_clock::now();
      {
        std::lock_guard lock(mutex);
        const CellBox changed = grid.takeChanged();
        if (!changed.empty()) {
          toMapMsg(grid, publish.frame_id, map_msg);
          map_writer.write(map_msg);
          toUpdateMsg(grid, changed, publish.frame_id, update_msg);
          update_writer.write(update_msg);
          last_publish = std::chrono::steady_clock::now();
          publish_time.Observe(std::chrono::duration<double>(last_publish - start).count());
          cells.Set(static_cast<double>(grid.bounds().width() * grid.bounds().height()));
          bytes.Set(static_cast<double>(grid.memoryBytes()));
          occupied.Set(static_cast<double>(occupiedCells(grid)));
        }
      }
      publish_age.Set(std::chrono::duration<double>(std::chrono::steady_clock::now() - last_publish).count());
      metrics.updateProcessStats();
      metrics.matched("reader", rosTopic(ns, kLabeledScanTopic), reader.matchedWriters());
      metrics.matched("writer", rosTopic(ns, "map"), map_writer.matchedReaders());
      if (std::chrono::steady_clock::now() - last_save > std::chrono::duration<double>(publish.save_period_s)) {
        save();
        last_save = std::chrono::steady_clock::now();
      }
    }
    save();
    spdlog::info("stopped after {} scans{}", grid.scansIntegrated(),
                 publish.save_path.empty() ? "" : "; map saved to " + publish.save_path + ".*");
    return 0;
  });
}
