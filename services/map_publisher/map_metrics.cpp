#include "map_metrics.hpp"

namespace scanfilter::map_service {

namespace {

const prometheus::Labels kLabels{{"service", "map_publisher"}};

prometheus::Gauge& gauge(dds_io::ServiceMetrics& metrics, const char* name, const char* help) {
  return prometheus::BuildGauge().Name(name).Help(help).Register(metrics.registry()).Add(kLabels);
}

std::size_t occupiedCells(const OccupancyGrid& grid) {
  const CellBox box = grid.bounds();
  std::size_t n = 0;
  for (std::int32_t y = box.lo.y; y <= box.hi.y; ++y)
    for (std::int32_t x = box.lo.x; x <= box.hi.x; ++x) n += grid.probability({x, y}) > grid.params().occupied_threshold;
  return n;
}

}  // namespace

MapMetrics::MapMetrics(dds_io::ServiceMetrics& metrics)
    : cells_(gauge(metrics, "scanfilter_map_cells", "Cells in the map's bounds")),
      bytes_(gauge(metrics, "scanfilter_map_memory_bytes", "Memory of the map's tiles")),
      integrated_(prometheus::BuildCounter()
                      .Name("scanfilter_map_scans_integrated_total")
                      .Help("Scans integrated into the map")
                      .Register(metrics.registry())
                      .Add(kLabels)),
      occupied_(gauge(metrics, "scanfilter_map_occupied_cells", "Cells above occupied_threshold")),
      publish_time_(prometheus::BuildHistogram()
                        .Name("scanfilter_map_publish_seconds")
                        .Help("Time to build and publish rt/map")
                        .Register(metrics.registry())
                        .Add(kLabels, dds_io::ServiceMetrics::latencyBuckets())),
      publish_age_(gauge(metrics, "scanfilter_map_last_publish_age_seconds", "Seconds since rt/map was last published")),
      saves_(prometheus::BuildCounter()
                 .Name("scanfilter_map_saves_total")
                 .Help("Times the map files were written")
                 .Register(metrics.registry())
                 .Add(kLabels)),
      saved_time_family_(prometheus::BuildGauge()
                             .Name("scanfilter_map_last_save_timestamp_seconds")
                             .Help("Unix time the saved map files last held all of the map (absent: no save_path)")
                             .Register(metrics.registry())) {}

void MapMetrics::published(const OccupancyGrid& grid, double seconds) {
  publish_time_.Observe(seconds);
  cells_.Set(static_cast<double>(grid.bounds().width() * grid.bounds().height()));
  bytes_.Set(static_cast<double>(grid.memoryBytes()));
  occupied_.Set(static_cast<double>(occupiedCells(grid)));
}

void MapMetrics::mapSaved() { saves_.Increment(); }

void MapMetrics::savedMapCurrent() { saved_time_family_.Add(kLabels).SetToCurrentTime(); }

}  // namespace scanfilter::map_service
