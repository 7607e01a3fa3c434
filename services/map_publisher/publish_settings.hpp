#pragma once
// map_publisher's own `publishing` section (config/map_publisher.yaml
// documents every key; the `map` section is readMapParams), read apart from
// the service so a fuzzer can call it.
#include <string>

#include "scanfilter/dds/service_config.hpp"

namespace scanfilter::map_service {

struct PublishSettings {
  double rate_hz = 1.0;
  std::string frame_id = "map";
  std::string save_path;
  double save_period_s = 30.0;
  bool load_on_start = false;
};

// Reads and validates the section; throws InputError naming file, line and key.
PublishSettings readPublishSettings(const dds_io::ServiceConfigFile& config);

}  // namespace scanfilter::map_service
