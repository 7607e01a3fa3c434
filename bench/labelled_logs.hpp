#pragma once
// Simulated labelled logs held in memory, and scoring a filter over them:
// shared by the accuracy sweep and the accuracy table.
#include <string>
#include <vector>

#include "scanfilter/filter_config.hpp"
#include "scanfilter/removal_score.hpp"
#include "scanfilter/sim/labelled_log.hpp"
#include "scanfilter/two_step_filter.hpp"

namespace scanfilter::bench {

using sim::LabelledLog;

inline LabelledLog simulateScene(const std::string& name, std::uint64_t seed, int max_frames = 0) {
  return sim::simulateLog(sim::findScene(name), seed, name, max_frames);
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
