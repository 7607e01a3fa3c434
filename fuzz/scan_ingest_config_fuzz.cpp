// scan_ingest's config (config/scan_ingest.yaml) on arbitrary text.
#include "ingest_settings.hpp"
#include "service_config_fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  scanfilter::fuzz::fuzzServiceConfig(data, size, {"source", "live", "playback"},
                                      [](const auto& config) { scanfilter::ingest::readIngestSettings(config); });
  return 0;
}
