// penetration_filter's config (config/penetration_filter.yaml) on arbitrary text.
#include "laser_scan_settings.hpp"
#include "service_config_fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  scanfilter::fuzz::fuzzServiceConfig(data, size, {"filter", "laser_scan"}, [](const auto& config) {
    scanfilter::dds_io::loadStageFilterConfig(config);
    scanfilter::dds_io::readLaserScanSettings(config);
  });
  return 0;
}
