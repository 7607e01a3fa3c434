#pragma once
// Odometry drift: the poses a wheel-odometry robot would record instead of
// the true ones. Each step between consecutive true poses is replayed with its
// length scaled by (1 + scale_error) and its heading change plus
// heading_drift_per_m times the distance travelled, accumulated from the
// first pose, as dead reckoning does.
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "scanfilter/scan.hpp"

namespace scanfilter::sim {

struct OdometryDrift {
  double scale_error = 0.0;          // relative error of travelled distance (0.02: 2 % long)
  double heading_drift_per_m = 0.0;  // rad of heading error per metre travelled
  bool none() const { return scale_error == 0.0 && heading_drift_per_m == 0.0; }
};

// The simulated logs' odometry unless a scene or command says otherwise:
// 1 % of distance and 0.5° of heading per metre, the order of an uncalibrated
// differential-drive robot's wheel odometry (docs/simulator.md).
inline constexpr OdometryDrift kDefaultOdometryDrift{0.01, 0.5 * std::numbers::pi / 180.0};

// "odometry drift 1 %, 0.5°/m" or "true poses".
std::string describe(const OdometryDrift& drift);

// Dead reckoning one true pose at a time: the first pose is taken as it is.
class DeadReckoning {
 public:
  explicit DeadReckoning(const OdometryDrift& drift) : drift_(drift) {}
  Pose2 next(const Pose2& true_pose);

 private:
  OdometryDrift drift_;
  std::optional<Pose2> previous_true_;
  Pose2 odometry_;
};

// Rewrites scan.pose of every scan (in order) as drifting odometry.
void applyOdometryDrift(std::vector<Scan>& scans, const OdometryDrift& drift);

}  // namespace scanfilter::sim
