#pragma once
// Sensor presets: one LiDAR's numbers and physics (config/sensors/*.yaml,
// compiled in; docs/simulator.md gives their sources), to put on any scene
// in place of the scene's own sensor.
#include <string>
#include <vector>

#include "scanfilter/sim/scene.hpp"

namespace scanfilter::sim {

std::vector<std::string> builtinSensorNames();

// Puts a built-in preset (by name) or a preset file (by path) on the scene:
// its range limits, beams, rate, angular accuracy and LiDAR model replace the
// scene's (a scene's own `lidar` settings too); the mount and beam direction
// stay the robot's. Throws InputError naming the file, line and key.
void applySensor(Scene& scene, const std::string& name_or_path);

// Another angular step: `beams` a turn, with the header's angular accuracy
// (the Δθ the filter reads) set to that step.
void setBeams(Scene& scene, int beams);

// A built-in scene (or scene file) with a sensor preset (empty: the scene's
// own sensor) at `beams` a turn (0: the sensor's own).
Scene sceneWithSensor(const std::string& scene, const std::string& sensor, int beams = 0);

}  // namespace scanfilter::sim
