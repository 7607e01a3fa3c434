#pragma once
// penetration_filter's own `laser_scan` section (config/penetration_filter.yaml
// documents every key), read apart from the service so a fuzzer can call it.
#include <string>

#include "scanfilter/dds/scan_message.hpp"
#include "scanfilter/dds/service_config.hpp"

namespace scanfilter::dds_io {

// rt/<ns>/scan_filtered: the frame for scans from a log, and what a removed beam becomes.
struct LaserScanSettings {
  std::string frame_id = "laser";
  RemovedBeamValue removed = RemovedBeamValue::kNaN;
};

// Reads and validates the section; throws InputError naming file, line and key.
LaserScanSettings readLaserScanSettings(const ServiceConfigFile& config);

}  // namespace scanfilter::dds_io
