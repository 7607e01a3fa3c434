#pragma once
// Simulated labelled logs held in memory, and scoring a filter over them:
// shared by the accuracy sweep and the accuracy table.
#include <string>
#include <vector>

#include "scanfilter/filter_config.hpp"
#include "scanfilter/removal_score.hpp"
#include "scanfilter/sim/scan_simulator.hpp"
#include "scanfilter/two_step_filter.hpp"

namespace scanfilter::bench {

struct LabelledLog {
  std::string scene;
  SensorInfo sensor;
  std::vector<Scan> scans;
};

inline LabelledLog simulateScene(const std::string& name, std::uint64_t seed, int max_frames = 0) {
  sim::ScanSimulator simulator(sim::findScene(name), seed);
  LabelledLog log{name, simulator.header().sensor, {}};
  ScanRecord record;
  while ((max_frames == 0 || static_cast<int>(log.scans.size()) < max_frames) && simulator.next(record))
    log.scans.push_back(record.scan);
  return log;
}

inline std::vector<LabelledLog> simulateAllScenes(std::uint64_t seed, int max_frames = 0) {
  std::vector<LabelledLog> logs;
  for (const auto& name : sim::builtinSceneNames()) logs.push_back(simulateScene(name, seed, max_frames));
  return logs;
}

// Scores `config` (its `auto` values filled from each log's sensor) over logs.
inline RemovalScore scoreFilter(const std::vector<LabelledLog>& logs, const FilterConfig& config) {
  RemovalScore total;
  std::vector<std::uint8_t> labels;
  for (const auto& log : logs) {
    TwoStepFilter filter(config.resolve(log.sensor), Implementation::kFast);
    for (const auto& scan : log.scans) {
      labels.resize(scan.size());
      filter.apply(scan, log.sensor, labels);
      total.add(scan, labels);
    }
  }
  return total;
}

}  // namespace scanfilter::bench
