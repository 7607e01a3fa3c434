#include "laser_scan_settings.hpp"

#include "scanfilter/yaml_section.hpp"

namespace scanfilter::dds_io {

LaserScanSettings readLaserScanSettings(const ServiceConfigFile& config) {
  LaserScanSettings s;
  YamlSection section(config.root, "laser_scan", config.path);
  section.read("frame_id", s.frame_id);
  std::string removed_beams = "nan";
  section.readChoice("removed_beams", removed_beams, {"nan", "inf"});
  s.removed = removed_beams == "nan" ? RemovedBeamValue::kNaN : RemovedBeamValue::kInfinity;
  section.rejectUnknownKeys();
  return s;
}

}  // namespace scanfilter::dds_io
