#include "scanfilter/scan_geometry.hpp"

#include <algorithm>
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
}  // namespace

const std::vector<Eigen::Vector2d>& BeamDirectionTable::directions(const Scan& scan,
                                                                   const SensorInfo& sensor) {
  const double sign = directionSign(sensor.direction);
  if (directions_.size() != scan.size() || angle_min_ != scan.angle_min ||
      angle_increment_ != scan.angle_increment || sign_ != sign) {
    directions_.resize(scan.size());
    for (std::size_t i = 0; i < scan.size(); ++i) {
      const double a = sign * beamAngle(scan, i);
      directions_[i] = {std::cos(a), std::sin(a)};
    }
    angle_min_ = scan.angle_min;
    angle_increment_ = scan.angle_increment;
    sign_ = sign;
  }
  return directions_;
}

void sensorFramePoints(const Scan& scan, const SensorInfo& sensor, BeamDirectionTable& table,
                       std::vector<Eigen::Vector2d>& out) {
  const auto& dirs = table.directions(scan, sensor);
  out.resize(scan.size());
  for (std::size_t i = 0; i < scan.size(); ++i)
    out[i] = scan.hasReturn(i) ? Eigen::Vector2d(scan.ranges[i] * dirs[i]) : Eigen::Vector2d(kNaN, kNaN);
}

void worldPoints(const Scan& scan, const SensorInfo& sensor, BeamDirectionTable& table,
                 std::vector<Eigen::Vector2d>& out) {
  const auto& dirs = table.directions(scan, sensor);
  const Eigen::Rotation2Dd rotation(scan.pose.theta + sensor.mount.yaw);
  const Eigen::Matrix2d r = rotation.toRotationMatrix();
  const Eigen::Vector2d origin = sensorOrigin(scan.pose, sensor.mount);
  out.resize(scan.size());
  for (std::size_t i = 0; i < scan.size(); ++i)
    out[i] = scan.hasReturn(i) ? Eigen::Vector2d(origin + scan.ranges[i] * (r * dirs[i]))
                               : Eigen::Vector2d(kNaN, kNaN);
}

void worldPoints(const Scan& scan, const SensorInfo& sensor, std::vector<Eigen::Vector2d>& out) {
  BeamDirectionTable table;
  worldPoints(scan, sensor, table, out);
}

std::optional<Eigen::Vector2d> localSurfaceDirection(const std::vector<Eigen::Vector2d>& points, std::size_t i,
                                                     double tolerance, std::size_t span) {
  if (span == 0 || i < span || i + span >= points.size()) return std::nullopt;
  const Eigen::Vector2d& a = points[i - span];
  const Eigen::Vector2d& b = points[i + span];
  if (std::isnan(a.x()) || std::isnan(b.x()) || std::isnan(points[i].x())) return std::nullopt;
  const Eigen::Vector2d chord = b - a;
  if (chord.squaredNorm() == 0.0 || isFartherFromLineThan(points[i], a, b, tolerance)) return std::nullopt;
  return chord;
}

std::size_t beamsSpanning(double degrees, double angle_step, std::size_t beams) {
  constexpr double kWholeStepSlack = 1e-9;  // in steps: 3 steps of 1° span 3°, not 4
  const double step_deg = std::abs(angle_step) * 180.0 / std::numbers::pi;
  const double spanned = std::ceil(degrees / step_deg - kWholeStepSlack);
  return static_cast<std::size_t>(std::clamp(spanned, 1.0, static_cast<double>(std::max<std::size_t>(beams, 1))));
}

bool isFullTurn(const Scan& scan) {
  // Half a beam of slack: 360 beams of exactly 1° cover the turn.
  const double covered = static_cast<double>(scan.size()) * std::abs(scan.angle_increment);
  return covered >= 2.0 * std::numbers::pi - 0.5 * std::abs(scan.angle_increment);
}

double distanceToLine(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = b - a;
  const double length = d.norm();
  if (length == 0.0) return (p - a).norm();
  return std::abs(d.x() * (p.y() - a.y()) - d.y() * (p.x() - a.x())) / length;
}

double distanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = b - a;
  const double length_sq = d.squaredNorm();
  const double t = length_sq == 0.0 ? 0.0 : std::clamp((p - a).dot(d) / length_sq, 0.0, 1.0);
  return (a + t * d - p).norm();
}

Eigen::AlignedBox2d returnBounds(std::span<const Eigen::Vector2d> points) {
  Eigen::AlignedBox2d box;  // empty
  for (const auto& p : points)
    if (!std::isnan(p.x())) box.extend(p);
  return box;
}

}  // namespace scanfilter
