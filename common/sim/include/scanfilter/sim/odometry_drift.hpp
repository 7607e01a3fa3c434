#pragma once
// Odometry drift for robustness tests: the poses a wheel-odometry robot would
// record instead of the true ones. Each step between consecutive true poses
// is replayed with its length scaled by (1 + scale_error) and its heading
// change plus heading_drift_per_m times the distance travelled, accumulated
// from the first pose, as dead reckoning does.
#include <vector>

#include "scanfilter/scan.hpp"

namespace scanfilter::sim {

struct OdometryDrift {
  double scale_error = 0.0;         // relative error of travelled distance (0.02: 2 % long)
  double heading_drift_per_m = 0.0;  // rad of heading error per metre travelled
};

// Rewrites scan.pose of every scan (in order) as drifting odometry.
void applyOdometryDrift(std::vector<Scan>& scans, const OdometryDrift& drift);

}  // namespace scanfilter::sim
