#pragma once
// A simulated labelled log held in memory: what the accuracy benchmarks score
// filters on.
#include <string>
#include <vector>

#include "scanfilter/sim/scan_simulator.hpp"

namespace scanfilter::sim {

struct LabelledLog {
  std::string name;
  SensorInfo sensor;
  std::vector<Scan> scans;
};

// Simulates `scene` with `seed`; max_frames 0 keeps the whole trajectory.
inline LabelledLog simulateLog(const Scene& scene, std::uint64_t seed, const std::string& name, int max_frames = 0) {
  ScanSimulator simulator(scene, seed);
  LabelledLog log{name, simulator.header().sensor, {}};
  ScanRecord record;
  while ((max_frames == 0 || static_cast<int>(log.scans.size()) < max_frames) && simulator.next(record))
    log.scans.push_back(std::move(record.scan));
  return log;
}

}  // namespace scanfilter::sim
