#include "scanfilter/sim/odometry_drift.hpp"

#include <cmath>

namespace scanfilter::sim {

void applyOdometryDrift(std::vector<Scan>& scans, const OdometryDrift& drift) {
  if (scans.empty()) return;
  Pose2 previous_true = scans.front().pose;
  Pose2 odom = previous_true;
  for (auto& scan : scans) {
    const Pose2 now = scan.pose;
    // The step in the previous true pose's frame: what the wheels measured.
    const double dx = now.x - previous_true.x, dy = now.y - previous_true.y;
    const double c = std::cos(previous_true.theta), s = std::sin(previous_true.theta);
    const double forward = c * dx + s * dy, lateral = -s * dx + c * dy;
    const double dtheta = std::remainder(now.theta - previous_true.theta, 2.0 * M_PI);
    const double distance = std::hypot(dx, dy);
    const double k = 1.0 + drift.scale_error;
    const double oc = std::cos(odom.theta), os = std::sin(odom.theta);
    odom.x += k * (oc * forward - os * lateral);
    odom.y += k * (os * forward + oc * lateral);
    odom.theta += dtheta + drift.heading_drift_per_m * distance;
    previous_true = now;
    scan.pose = odom;
  }
}

}  // namespace scanfilter::sim
