// jump_filter's config (config/jump_filter.yaml) on arbitrary text: the
// common section and the filter config file it names.
#include "service_config_fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  scanfilter::fuzz::fuzzServiceConfig(data, size, {"filter"},
                                      [](const auto& config) { scanfilter::dds_io::loadStageFilterConfig(config); });
  return 0;
}
