#include "scanfilter/range_image.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "scanfilter/point_code.hpp"
#include "scanfilter/scan_geometry.hpp"

namespace scanfilter {

RangeImage::RangeImage(const Scan& scan, const SensorInfo& sensor, const Eigen::Isometry2d& correction,
                       std::span<const std::uint8_t> labels)
    : origin_(correction * sensorOrigin(scan.pose, sensor.mount)),
      first_bearing_(beamWorldAngle(scan, sensor, 0) + Eigen::Rotation2Dd(correction.linear()).angle()),
      step_(directionSign(sensor.direction) * scan.angle_increment),
      full_turn_(isFullTurn(scan)),
      ranges_(scan.size(), std::numeric_limits<float>::quiet_NaN()) {
  for (std::size_t i = 0; i < ranges_.size(); ++i)
    if (labels[i] == static_cast<std::uint8_t>(PointCode::kValid)) ranges_[i] = static_cast<float>(scan.ranges[i]);
}

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
  // Angle from beam 0 in the scan's direction, in [0, 2π): a partial turn
  // wider than 180° (a 240° URG) must not see its far end as negative.
  const double turn = 2.0 * std::numbers::pi;
  double angle = std::fmod((std::atan2(v.y(), v.x()) - first_bearing_) * (step_ > 0.0 ? 1.0 : -1.0), turn);
  if (angle < 0.0) angle += turn;
  const auto n = static_cast<std::int64_t>(ranges_.size());
  auto first = static_cast<std::int64_t>(std::floor(angle / std::abs(step_)));
  if (full_turn_) {
    first = std::min(first, n - 1);  // a "full" turn may stop up to half a step short of 360°
  } else if (first + 1 >= n) {
    return std::nullopt;  // beyond the last beam: outside the field of view
  }
  return Bracket{at(first - 1), at(first), at(first + 1), at(first + 2), distance};
}

}  // namespace scanfilter
