#pragma once
// scan_ingest's own config sections (source, live, playback; config/scan_ingest.yaml
// documents every key), read apart from the service so a fuzzer can call it.
#include <cstdint>
#include <string>

#include "live_source.hpp"
#include "scan_player.hpp"
#include "scanfilter/dds/service_config.hpp"

namespace scanfilter::ingest {

struct IngestSettings {
  std::string kind = "simulator";
  std::string path;
  std::string scene = "hall";
  std::uint64_t seed = 1;
  double carmen_range_max = 80.0;
  PlaybackRate rate;
  LiveSettings live;
  int wait_for_subscribers = 1;
  double wait_timeout_s = 30.0;
  bool exit_at_end = true;
  std::string progress_path;
  double wait_notice_s = 5.0;
};

// Reads and validates the sections; throws InputError naming file, line and key.
IngestSettings readIngestSettings(const dds_io::ServiceConfigFile& config);

}  // namespace scanfilter::ingest
