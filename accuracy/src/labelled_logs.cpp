#include "scanfilter/accuracy/labelled_logs.hpp"

namespace scanfilter::accuracy {

LabelledLog simulateScene(const std::string& scene_name, std::uint64_t seed, int max_frames,
                          const SceneVariant& variant) {
  sim::Scene scene = sim::findScene(scene_name);
  scene.lidar.noise_sigma_base *= variant.noise_factor;
  scene.lidar.noise_sigma_quadratic *= variant.noise_factor;
  if (variant.beams > 0) scene.lidar.beams = variant.beams;
  auto log = sim::simulateLog(scene, seed, scene_name + " seed " + std::to_string(seed), max_frames);
  if (variant.odometry) sim::applyOdometryDrift(log.scans, *variant.odometry);
  return log;
}

std::vector<LabelledLog> simulateBuiltinScenes(const std::vector<std::uint64_t>& seeds, int max_frames,
                                               const SceneVariant& variant) {
  std::vector<LabelledLog> logs;
  for (const auto& name : sim::builtinSceneNames())
    for (auto seed : seeds) logs.push_back(simulateScene(name, seed, max_frames, variant));
  return logs;
}

}  // namespace scanfilter::accuracy
