// The filter config loader (config/filter.yaml) on arbitrary text, then what
// every user of a config does next: resolve it for a sensor and build both
// filters from it.
#include "fuzz_input.hpp"
#include "scanfilter/filter_config.hpp"
#include "scanfilter/jump_filter.hpp"
#include "scanfilter/penetration_filter.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = scanfilter::fuzz::writeInput(data, size, "filter-fuzz.yaml");
  scanfilter::fuzz::expectInputError([&] {
    const scanfilter::FilterConfig config = scanfilter::loadFilterConfig(path);
    scanfilter::SensorInfo sensor;
    sensor.range_min = 0.1;
    sensor.range_max = 30.0;
    sensor.angular_accuracy_deg = 0.25;
    const scanfilter::TwoStepFilterParams params = config.resolve(sensor);
    scanfilter::makeJumpFilter(params.jump, scanfilter::Implementation::kFast);
    scanfilter::makePenetrationFilter(params.penetration, scanfilter::Implementation::kFast);
  });
  return 0;
}
