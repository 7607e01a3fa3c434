#include <iostream>
#include <string>

#include "commands.hpp"
#include "scanfilter/filter_config.hpp"
#include "scanfilter/map_files.hpp"
#include "scanfilter/occupancy_grid.hpp"
#include "scanfilter/scan_source.hpp"
#include "scanfilter/two_step_filter.hpp"

namespace scanfilter::cli {

int runMap(const MapOptions& options) {
  ScanSourceOptions source_options;
  source_options.carmen_range_max = options.carmen_range_max;
  auto source = openScanSource(options.input, source_options);
  const SensorInfo& sensor = source->header().sensor;
  const FilterConfig config = options.config.empty() ? FilterConfig{} : loadFilterConfig(options.config);
  TwoStepFilter filter(config.resolve(sensor), Implementation::kFast);
  OccupancyGridParams params;
  params.resolution = options.resolution;
  OccupancyGrid grid(params);
  ScanRecord record;
  while (source->next(record)) {
    std::vector<std::uint8_t> labels(record.scan.size());
    if (options.unfiltered) labels.clear();  // every return updates the map
    else filter.apply(record.scan, sensor, labels);
    grid.integrate(record.scan, sensor, labels);
  }
  saveMap(grid, options.output, {},
          (options.unfiltered ? "UNFILTERED" : "FILTERED") + std::string(" MAP, ") +
              std::to_string(grid.scansIntegrated()) + " SCANS");
  const CellBox box = grid.bounds();
  std::cout << "map of " << grid.scansIntegrated() << " scans (" << (options.unfiltered ? "unfiltered" : "filtered")
            << "): " << box.width() << " x " << box.height() << " cells at " << params.resolution << " m, "
            << grid.memoryBytes() / 1000 << " kB -> " << options.output << ".{pgm,yaml,png,logodds}\n";
  return 0;
}

}  // namespace scanfilter::cli
