#include "scanfilter/range_image.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "scanfilter/scan_geometry.hpp"

namespace scanfilter {

RangeImage::RangeImage(const Scan& scan, const SensorInfo& sensor, const Eigen::Isometry2d& correction)
    : origin_(correction * sensorOrigin(scan.pose, sensor.mount)),
      first_bearing_(beamWorldAngle(scan, sensor, 0) + Eigen::Rotation2Dd(correction.linear()).angle()),
      step_(directionSign(sensor.direction) * scan.angle_increment),
      full_turn_(isFullTurn(scan)),
      ranges_(scan.ranges.begin(), scan.ranges.end()) {}

float RangeImage::at(std::int64_t i) const {
  const auto n = static_cast<std::int64_t>(ranges_.size());
  if (full_turn_) return ranges_[static_cast<std::size_t>(((i % n) + n) % n)];
  if (i < 0 || i >= n) return std::numeric_limits<float>::quiet_NaN();
  return ranges_[static_cast<std::size_t>(i)];
}

std::optional<RangeImage::Bracket> RangeImage::bracket(const Eigen::Vector2d& p) const {
  const Eigen::Vector2d v = p - origin_;
  const double distance = v.norm();
  if (!(distance > 0.0) || step_ == 0.0 || ranges_.empty()) return std::nullopt;
  // Beam index (fractional) of p's bearing, counted in the scan's direction.
  const double turn = 2.0 * std::numbers::pi;
  double index = std::remainder(std::atan2(v.y(), v.x()) - first_bearing_, turn) / step_;
  if (full_turn_ && index < 0.0) index += turn / std::abs(step_);
  const auto first = static_cast<std::int64_t>(std::floor(index));
  if (!full_turn_ && (first < 0 || first + 1 >= static_cast<std::int64_t>(ranges_.size()))) return std::nullopt;
  return Bracket{at(first - 1), at(first), at(first + 1), at(first + 2), distance};
}

}  // namespace scanfilter
