#pragma once
#include <string>
#include <vector>

#include <Eigen/Core>

#include "scanfilter/sensor_info.hpp"
#include "scanfilter/sim/lidar_model.hpp"
#include "scanfilter/sim/odometry_drift.hpp"

namespace scanfilter::sim {

// How a surface returns light (paper section 3.3.2): rough surfaces scatter,
// smooth ones and glass reflect specularly and produce ghost returns.
enum class Material { kRough, kSmooth, kGlass };

struct Segment {
  Eigen::Vector2d a;
  Eigen::Vector2d b;
  Material material = Material::kRough;
};

// A thin round obstacle: a table or chair leg.
struct Leg {
  Eigen::Vector2d centre;
  double radius = 0.015;
};

struct Trajectory {
  std::vector<Eigen::Vector2d> waypoints;
  double speed = 0.3;           // m/s
  double turn_rate_deg = 90.0;  // deg/s, in-place turns at waypoints
  // m, the robot's body about the pose (a sweeping robot is about 0.35 m
  // across): the tour must keep this far from every wall, box and leg.
  double robot_radius = 0.17;
};

struct Scene {
  std::string name;
  std::string description;
  SensorInfo sensor;
  std::string sensor_preset;  // the preset put on the scene; empty: the scene's own sensor
  LidarModel lidar;
  // The poses the simulated log records: the true ones with this drift.
  OdometryDrift odometry = kDefaultOdometryDrift;
  std::vector<Segment> segments;
  std::vector<Leg> legs;
  Trajectory trajectory;
};

// Loads a scene from YAML text (config/scenes/*.yaml show the format);
// throws InputError naming the file, line and key.
Scene parseScene(const std::string& yaml_text, const std::string& name);
Scene loadScene(const std::string& path);

// The scenes compiled into the binary, by name.
std::vector<std::string> builtinSceneNames();
// A built-in scene by name, or a scene file by path.
Scene findScene(const std::string& name_or_path);

}  // namespace scanfilter::sim
