#include "scanfilter/scan_geometry.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace scanfilter {

Eigen::Vector2d sensorOrigin(const Pose2& pose, const SensorMount& mount) {
  return pose.isometry() * Eigen::Vector2d(mount.x, mount.y);
}

double beamWorldAngle(const Scan& scan, const SensorInfo& sensor, std::size_t i) {
  return scan.pose.theta + sensor.mount.yaw + directionSign(sensor.direction) * beamAngle(scan, i);
}

Eigen::Vector2d beamToWorld(const Scan& scan, const SensorInfo& sensor, std::size_t i) {
  const double phi = beamWorldAngle(scan, sensor, i);
  return sensorOrigin(scan.pose, sensor.mount) +
         scan.ranges[i] * Eigen::Vector2d(std::cos(phi), std::sin(phi));
}

Eigen::Vector2d paperEquation4(const Pose2& robot, double c, double theta_c, double theta_p,
                               double dis_p) {
  // Sensor centre C behind the robot centre along its heading.
  const double x1 = robot.x - c * std::cos(robot.theta);
  const double y1 = robot.y - c * std::sin(robot.theta);
  // Angles grow clockwise in the sensor frame, so θp enters with a minus sign.
  const double phi = robot.theta + theta_c - theta_p;
  return {x1 + dis_p * std::cos(phi), y1 + dis_p * std::sin(phi)};
}

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void pointsFrom(const Scan& scan, double base_angle, double sign, const Eigen::Vector2d& origin,
                std::vector<Eigen::Vector2d>& out) {
  out.resize(scan.size());
  for (std::size_t i = 0; i < scan.size(); ++i) {
    if (!scan.hasReturn(i)) {
      out[i] = Eigen::Vector2d(kNaN, kNaN);
      continue;
    }
    const double phi = base_angle + sign * beamAngle(scan, i);
    out[i] = origin + scan.ranges[i] * Eigen::Vector2d(std::cos(phi), std::sin(phi));
  }
}
}  // namespace

void sensorFramePoints(const Scan& scan, const SensorInfo& sensor,
                       std::vector<Eigen::Vector2d>& out) {
  pointsFrom(scan, 0.0, directionSign(sensor.direction), Eigen::Vector2d::Zero(), out);
}

void worldPoints(const Scan& scan, const SensorInfo& sensor, std::vector<Eigen::Vector2d>& out) {
  pointsFrom(scan, scan.pose.theta + sensor.mount.yaw, directionSign(sensor.direction),
             sensorOrigin(scan.pose, sensor.mount), out);
}

bool isFullTurn(const Scan& scan) {
  // Half a beam of slack: 360 beams of exactly 1° cover the turn.
  const double covered = static_cast<double>(scan.size()) * std::abs(scan.angle_increment);
  return covered >= 2.0 * std::numbers::pi - 0.5 * std::abs(scan.angle_increment);
}

}  // namespace scanfilter
