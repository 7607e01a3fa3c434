#include "scanfilter/sim/odometry_drift.hpp"

#include <cmath>
#include <cstdio>

namespace scanfilter::sim {

std::string describe(const OdometryDrift& drift) {
  if (drift.none()) return "true poses";
  char text[64];
  std::snprintf(text, sizeof text, "odometry drift %g %%, %g°/m", 100.0 * drift.scale_error,
                drift.heading_drift_per_m * 180.0 / std::numbers::pi);
  return text;
}

Pose2 DeadReckoning::next(const Pose2& now) {
  if (!previous_true_) {
    previous_true_ = now;
    odometry_ = now;
    return odometry_;
  }
  const Pose2& before = *previous_true_;
  // The step in the previous true pose's frame: what the wheels measured.
  const double dx = now.x - before.x, dy = now.y - before.y;
  const double c = std::cos(before.theta), s = std::sin(before.theta);
  const double forward = c * dx + s * dy, lateral = -s * dx + c * dy;
  const double dtheta = std::remainder(now.theta - before.theta, 2.0 * std::numbers::pi);
  const double distance = std::hypot(dx, dy);
  const double k = 1.0 + drift_.scale_error;
  const double oc = std::cos(odometry_.theta), os = std::sin(odometry_.theta);
  odometry_.x += k * (oc * forward - os * lateral);
  odometry_.y += k * (os * forward + oc * lateral);
  odometry_.theta += dtheta + drift_.heading_drift_per_m * distance;
  previous_true_ = now;
  return odometry_;
}

void applyOdometryDrift(std::vector<Scan>& scans, const OdometryDrift& drift) {
  DeadReckoning odometry(drift);
  for (auto& scan : scans) scan.pose = odometry.next(scan.pose);
}

}  // namespace scanfilter::sim
