#include "scanfilter/accuracy/labelled_logs.hpp"

#include "scanfilter/sim/sensor_preset.hpp"

namespace scanfilter::accuracy {

LabelledLog simulateScene(const std::string& scene_name, std::uint64_t seed, int max_frames,
                          const SceneVariant& variant) {
  sim::Scene scene = sim::sceneWithSensor(scene_name, variant.sensor, variant.beams);
  scene.lidar.noise_sigma_base *= variant.noise_factor;
  scene.lidar.noise_sigma_quadratic *= variant.noise_factor;
  if (variant.odometry) scene.odometry = *variant.odometry;
  if (variant.adjust) variant.adjust(scene);
  const std::string sensor = variant.sensor.empty() ? "" : " " + scene.sensor_preset;
  return sim::simulateLog(scene, seed, scene_name + sensor + " seed " + std::to_string(seed), max_frames);
}

std::vector<LabelledLog> simulateBuiltinScenes(const std::vector<std::uint64_t>& seeds, int max_frames,
                                               const SceneVariant& variant) {
  std::vector<LabelledLog> logs;
  for (const auto& name : sim::builtinSceneNames())
    for (auto seed : seeds) logs.push_back(simulateScene(name, seed, max_frames, variant));
  return logs;
}

}  // namespace scanfilter::accuracy
