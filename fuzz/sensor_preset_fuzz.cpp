// The sensor preset loader (config/sensors/*.yaml) on arbitrary text, put on
// a built-in scene as `scanfilter simulate --sensor FILE` does.
#include "fuzz_input.hpp"
#include "scanfilter/sim/scene.hpp"
#include "scanfilter/sim/sensor_preset.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const scanfilter::sim::Scene base = scanfilter::sim::findScene("hall");
  const std::string path = scanfilter::fuzz::writeInput(data, size, "sensor-fuzz.yaml");
  scanfilter::fuzz::expectInputError([&] {
    scanfilter::sim::Scene scene = base;
    scanfilter::sim::applySensor(scene, path);
  });
  return 0;
}
