#pragma once
// Labelled logs of the built-in scenes, simulated in memory: what the
// accuracy programs (bench/) and `scanfilter bench-accuracy` score filters on.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "scanfilter/sim/labelled_log.hpp"
#include "scanfilter/sim/odometry_drift.hpp"

namespace scanfilter::accuracy {

using sim::LabelledLog;

// A built-in scene changed as a robustness test asks; the default changes
// nothing.
struct SceneVariant {
  std::string name;
  double noise_factor = 1.0;  // scales both range-noise terms
  int beams = 0;              // 0: the scene's own
  // Set: the poses as dead reckoning with this drift records them (with zero
  // drift they still differ from the true poses by rounding, which can flip
  // a label). Unset: the true poses.
  std::optional<sim::OdometryDrift> odometry;
};

// One built-in scene at one seed, named "SCENE seed N"; max_frames 0 keeps the
// whole trajectory.
LabelledLog simulateScene(const std::string& scene, std::uint64_t seed, int max_frames = 0,
                          const SceneVariant& variant = {});

// Every built-in scene at every seed, scene by scene.
std::vector<LabelledLog> simulateBuiltinScenes(const std::vector<std::uint64_t>& seeds, int max_frames = 0,
                                               const SceneVariant& variant = {});

}  // namespace scanfilter::accuracy
