#pragma once
#include <string>
#include <vector>

#include <Eigen/Core>

#include "scanfilter/sensor_info.hpp"

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

// Sensor noise and artefacts of a triangulation LiDAR; docs/simulator.md says
// where each number comes from.
struct LidarModel {
  int beams = 360;
  double rate_hz = 10.0;
  double range_resolution = 0.001;     // m, ranges are quantised to this
  double noise_sigma_base = 0.003;     // m, σ at zero range
  double noise_sigma_quadratic = 0.001;  // m per m², triangulation error grows with d²
  double spot_width_deg = 1.0;         // beam footprint: straddling an edge mixes ranges
  double edge_gap = 0.15;              // m, depth step across the footprint that mixes
  double mixed_probability = 0.35;     // chance that a straddling beam returns a mixture
  double grazing_angle_deg = 75.0;     // incidence beyond which the spot deforms
  double grazing_probability = 0.25;
  double grazing_error_max = 0.4;      // m, largest displacement at grazing incidence
  double junction_radius = 0.04;       // m, hits this near a corner can be displaced
  double junction_probability = 0.3;
  double junction_error_max = 0.25;    // m
  double jump_min_error = 0.05;        // m, a displaced return off every surface by more than max(this, 4σ) is a jump point
  double smooth_specular_probability = 0.12;
  double glass_specular_probability = 0.25;
  double glass_transmit_probability = 0.15;
  double dropout_probability = 0.003;  // a rough surface returning nothing
};

struct Trajectory {
  std::vector<Eigen::Vector2d> waypoints;
  double speed = 0.3;           // m/s
  double turn_rate_deg = 90.0;  // deg/s, in-place turns at waypoints
};

struct Scene {
  std::string name;
  std::string description;
  SensorInfo sensor;
  LidarModel lidar;
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
