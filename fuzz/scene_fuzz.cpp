// The scene loader (config/scenes/*.yaml) on arbitrary text.
#include "fuzz_input.hpp"
#include "scanfilter/sim/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = scanfilter::fuzz::writeInput(data, size, "scene-fuzz.yaml");
  scanfilter::fuzz::expectInputError([&] { scanfilter::sim::loadScene(path); });
  return 0;
}
