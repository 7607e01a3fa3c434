// recovery_check: what the kill/restart test needs to know about a run.
// Scans are named by their sequence number: their index in the input log
// (the ingest numbers them so, across its own restarts).
//
//   recovery_check sequences INPUT_LOG RECORDED_LOG
// prints the sequence number of each recorded scan, one a line.
//
//   recovery_check map INPUT_LOG RECORDED_LOG MAP_CONFIG SAVED_BASE [SKIP_FROM SKIP_TO]...
// the map a restarted map_publisher saved, against the map built offline from
// exactly the scans it integrated (the recording of rt/labeled_scan: the live
// labels).
// Integrates every recorded scan but those with SKIP_FROM <= sequence <
// SKIP_TO (the ones the crash lost), compares with SAVED_BASE.logodds cell by
// cell, and prints: "cells: N differ of M; offline scans: K; cells the
// skipped scans change: D". Exit 0 when it ran (the caller checks N), 2 on
// bad input.
#include <cstdlib>
#include <iostream>
#include <utility>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "scanfilter/map_config.hpp"
#include "scanfilter/map_files.hpp"
#include "scanfilter/occupancy_grid.hpp"
#include "scanfilter/scan_source.hpp"

using namespace scanfilter;

namespace {

// Cells whose log-odds differ (an absent cell is 0) over both grids' bounds.
std::size_t differingCells(const OccupancyGrid& a, const OccupancyGrid& b, std::size_t& compared) {
  CellBox box = a.bounds();
  if (!b.bounds().empty()) box.include(b.bounds().lo), box.include(b.bounds().hi);
  std::size_t differ = 0;
  compared = 0;
  for (std::int32_t y = box.lo.y; y <= box.hi.y; ++y)
    for (std::int32_t x = box.lo.x; x <= box.hi.x; ++x, ++compared) differ += a.logOdds({x, y}) != b.logOdds({x, y});
  return differ;
}

}  // namespace

// The index in `input` of each scan of `recorded` (a subsequence of it, in order).
template <typename Each>
void forEachRecorded(ScanSource& input, ScanSource& recorded, Each&& each) {
  ScanRecord in, rec;
  std::uint64_t sequence = 0;
  while (recorded.next(rec)) {
    bool found = false;
    while (!found && input.next(in)) found = in.scan.stamp == rec.scan.stamp || (++sequence, false);
    if (!found) throw std::runtime_error("a recorded scan is not in the input log (in order)");
    each(sequence++, rec);
  }
}

int sequences(const char* input_path, const char* recorded_path) {
  auto input = openScanSource(input_path);
  auto recorded = openScanSource(recorded_path);
  forEachRecorded(*input, *recorded, [](std::uint64_t sequence, const ScanRecord&) { std::cout << sequence << "\n"; });
  return 0;
}

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  try {
    if (mode == "sequences" && argc == 4) return sequences(argv[2], argv[3]);
  } catch (const std::exception& e) {
    std::cerr << "recovery_check: " << e.what() << "\n";
    return 2;
  }
  if (mode != "map" || argc < 6 || argc % 2 == 1) {
    std::cerr << "usage: recovery_check sequences INPUT_LOG RECORDED_LOG\n"
                 "       recovery_check map INPUT_LOG RECORDED_LOG MAP_CONFIG SAVED_BASE [SKIP_FROM SKIP_TO]...\n";
    return 2;
  }
  ++argv;  // the map mode's arguments as documented, from argv[1]
  try {
    std::vector<std::pair<std::uint64_t, std::uint64_t>> skips;
    for (int k = 5; k + 1 < argc - 1; k += 2) skips.emplace_back(std::strtoull(argv[k], nullptr, 10), std::strtoull(argv[k + 1], nullptr, 10));
    const YAML::Node config = YAML::LoadFile(argv[3]);
    const OccupancyGridParams params = readMapParams(config, argv[3]);
    auto input = openScanSource(argv[1]);
    auto recorded = openScanSource(argv[2]);
    OccupancyGrid expected(params), everything(params), saved(params);
    loadMapState(saved, argv[4]);
    std::uint64_t integrated = 0;
    const SensorInfo& sensor = recorded->header().sensor;
    forEachRecorded(*input, *recorded, [&](std::uint64_t sequence, const ScanRecord& rec) {
      everything.integrate(rec.scan, sensor, rec.scan.labels);
      bool skip = false;
      for (const auto& [from, to] : skips) skip = skip || (sequence >= from && sequence < to);
      if (!skip) expected.integrate(rec.scan, sensor, rec.scan.labels), ++integrated;
    });
    std::size_t compared = 0, compared_all = 0;
    const std::size_t differ = differingCells(expected, saved, compared);
    const std::size_t cost = differingCells(expected, everything, compared_all);
    std::cout << "cells: " << differ << " differ of " << compared << "; offline scans: " << integrated
              << "; cells the skipped scans change: " << cost << "\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "recovery_check: " << e.what() << "\n";
    return 2;
  }
}
