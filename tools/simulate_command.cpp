#include <iostream>

#include "commands.hpp"
#include "scanfilter/scan_log_writer.hpp"
#include "scanfilter/sim/scan_simulator.hpp"

namespace scanfilter::cli {

int runSimulate(const SimulateOptions& options) {
  sim::ScanSimulator simulator(sim::findScene(options.scene), options.seed);
  ScanLogWriter writer(options.output, simulator.header());
  ScanRecord record;
  int frames = 0;
  while ((options.max_frames == 0 || frames < options.max_frames) && simulator.next(record)) {
    writer.write(record);
    ++frames;
  }
  writer.close();
  std::cout << "simulated " << frames << " scans of scene '" << simulator.scene().name << "' (seed "
            << options.seed << ") -> " << options.output << "\n";
  return 0;
}

}  // namespace scanfilter::cli
