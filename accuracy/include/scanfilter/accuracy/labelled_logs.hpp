#pragma once
// Labelled logs of the built-in scenes, simulated in memory: what the
// accuracy programs (bench/) and `scanfilter bench-accuracy` score filters on.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "scanfilter/sim/labelled_log.hpp"
#include "scanfilter/sim/odometry_drift.hpp"
#include "scanfilter/sim/scene.hpp"

namespace scanfilter::accuracy {

using sim::LabelledLog;

// A built-in scene changed as a robustness test asks, or seen by another
// sensor; the default changes nothing.
struct SceneVariant {
  std::string name;
  double noise_factor = 1.0;  // scales both range-noise terms
  int beams = 0;              // 0: the sensor's own
  // Set: the odometry drift the logged poses carry in place of the scene's
  // own (sim::OdometryDrift{}: the true poses). Unset: the scene's own,
  // sim::kDefaultOdometryDrift unless the scene file says otherwise.
  std::optional<sim::OdometryDrift> odometry;
  std::string sensor;  // sensor preset (config/sensors) or file; empty: the scene's own
  // Any other change, made last: a sensor's range, receiver or surfaces
  // (bench/sensor_robustness). Empty: none.
  std::function<void(sim::Scene&)> adjust;
};

// One built-in scene at one seed, named "SCENE seed N" ("SCENE SENSOR seed N"
// with a sensor preset); max_frames 0 keeps the whole trajectory.
LabelledLog simulateScene(const std::string& scene, std::uint64_t seed, int max_frames = 0,
                          const SceneVariant& variant = {});

// Every built-in scene at every seed, scene by scene.
std::vector<LabelledLog> simulateBuiltinScenes(const std::vector<std::uint64_t>& seeds, int max_frames = 0,
                                               const SceneVariant& variant = {});

}  // namespace scanfilter::accuracy
