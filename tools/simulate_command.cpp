#include <iostream>

#include "commands.hpp"
#include "scanfilter/scan_log_writer.hpp"
#include "scanfilter/sim/scan_simulator.hpp"
#include "scanfilter/sim/sensor_preset.hpp"

namespace scanfilter::cli {

int runSimulate(const SimulateOptions& options) {
  sim::Scene scene = sim::sceneWithSensor(options.scene, options.sensor, options.beams);
  if (options.true_poses) scene.odometry = {};
  sim::ScanSimulator simulator(std::move(scene), options.seed);
  ScanLogWriter writer(options.output, simulator.header());
  ScanRecord record;
  int frames = 0;
  while ((options.max_frames == 0 || frames < options.max_frames) && simulator.next(record)) {
    writer.write(record);
    ++frames;
  }
  writer.close();
  std::cout << "simulated " << frames << " scans (" << simulator.header().source << ") -> " << options.output << "\n";
  return 0;
}

}  // namespace scanfilter::cli
