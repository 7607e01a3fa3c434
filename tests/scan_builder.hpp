#pragma once
// Builds noise-free scans of hand-made geometry for the filter tests.
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "scanfilter/scan.hpp"
#include "scanfilter/scan_geometry.hpp"
#include "scanfilter/sensor_info.hpp"
#include "scanfilter/sim/ray_caster.hpp"
#include "scanfilter/sim/scene.hpp"

namespace scanfilter::test {

inline constexpr double kDeg = std::numbers::pi / 180.0;

// A ccw sensor at the robot centre, 0.15-6 m, 1° accuracy.
inline SensorInfo simpleSensor() {
  SensorInfo s;
  s.direction = BeamDirection::kCcw;
  s.range_min = 0.15;
  s.range_max = 6.0;
  s.angular_accuracy_deg = 1.0;
  return s;
}

// Geometry to cast against: walls and legs in the world frame.
struct World {
  std::vector<sim::Segment> walls;
  std::vector<sim::Leg> legs;

  World& wall(Eigen::Vector2d a, Eigen::Vector2d b) {
    walls.push_back({a, b, sim::Material::kRough});
    return *this;
  }
  World& leg(Eigen::Vector2d c, double radius) {
    legs.push_back({c, radius});
    return *this;
  }
};

// A full-turn scan of `beams` beams from `pose`, exact ranges.
inline Scan castScan(const World& world, const Pose2& pose, const SensorInfo& sensor, int beams = 360,
                     double stamp = 0.0) {
  sim::Scene scene;
  scene.segments = world.walls;
  scene.legs = world.legs;
  const sim::RayCaster caster(scene);
  Scan scan;
  scan.stamp = Stamp::fromSeconds(stamp);
  scan.pose = pose;
  scan.angle_min = 0.0;
  scan.angle_increment = 2.0 * std::numbers::pi / beams;
  scan.ranges.resize(static_cast<std::size_t>(beams));
  const Eigen::Vector2d origin = sensorOrigin(pose, sensor.mount);
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    const double phi = beamWorldAngle(scan, sensor, i);
    const auto hit = caster.cast(origin, {std::cos(phi), std::sin(phi)}, sensor.range_max);
    scan.ranges[i] = hit && hit->range >= sensor.range_min ? hit->range : std::numeric_limits<double>::quiet_NaN();
  }
  return scan;
}

// Index of the beam pointing closest to world angle `phi`.
inline std::size_t beamTowards(const Scan& scan, const SensorInfo& sensor, double phi) {
  std::size_t best = 0;
  double best_err = 1e9;
  for (std::size_t i = 0; i < scan.size(); ++i) {
    const double err = std::abs(std::remainder(beamWorldAngle(scan, sensor, i) - phi, 2 * std::numbers::pi));
    if (err < best_err) best_err = err, best = i;
  }
  return best;
}

}  // namespace scanfilter::test
