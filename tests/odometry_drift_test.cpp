#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "scanfilter/sim/odometry_drift.hpp"

namespace scanfilter::sim {
namespace {

std::vector<Scan> straightLine(int steps, double step, double heading) {
  std::vector<Scan> scans(static_cast<std::size_t>(steps + 1));
  for (int k = 0; k <= steps; ++k)
    scans[static_cast<std::size_t>(k)].pose = {1.0 + k * step * std::cos(heading), 2.0 + k * step * std::sin(heading), heading};
  return scans;
}

TEST(OdometryDrift, NoDriftKeepsEveryPose) {
  auto scans = straightLine(10, 0.1, 0.3);
  scans[5].pose.theta += 1.0;  // a turn on the way
  const auto truth = scans;
  applyOdometryDrift(scans, {});
  for (std::size_t k = 0; k < scans.size(); ++k) {
    EXPECT_NEAR(scans[k].pose.x, truth[k].pose.x, 1e-12);
    EXPECT_NEAR(scans[k].pose.y, truth[k].pose.y, 1e-12);
    EXPECT_NEAR(std::remainder(scans[k].pose.theta - truth[k].pose.theta, 2 * std::numbers::pi), 0.0, 1e-12);
  }
}

TEST(OdometryDrift, ScaleErrorLengthensTheTripAndHeadingDriftGrowsWithDistance) {
  auto scaled = straightLine(10, 0.1, 0.0);
  applyOdometryDrift(scaled, {0.02, 0.0});
  EXPECT_NEAR(scaled.back().pose.x - scaled.front().pose.x, 1.02, 1e-12);
  auto turned = straightLine(10, 0.1, 0.0);
  applyOdometryDrift(turned, {0.0, 0.05});
  EXPECT_NEAR(turned.back().pose.theta, 0.05 * 1.0, 1e-12);
  EXPECT_GT(turned.back().pose.y, 0.0) << "a heading error bends the path";
  EXPECT_DOUBLE_EQ(turned.front().pose.x, 1.0) << "dead reckoning starts at the true pose";
}

}  // namespace
}  // namespace scanfilter::sim
