// map_publisher's config (config/map_publisher.yaml) on arbitrary text, and
// the grid it builds from the `map` section.
#include "publish_settings.hpp"
#include "scanfilter/map_config.hpp"
#include "scanfilter/occupancy_grid.hpp"
#include "service_config_fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  scanfilter::fuzz::fuzzServiceConfig(data, size, {"map", "publishing"}, [](const auto& config) {
    scanfilter::OccupancyGrid grid(scanfilter::readMapParams(config.root, config.path));
    scanfilter::map_service::readPublishSettings(config);
  });
  return 0;
}
