#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "scanfilter/cell_key.hpp"
#include "scanfilter/scan_geometry.hpp"

namespace scanfilter {
namespace {

constexpr double kPi = std::numbers::pi;

Scan oneBeam(double angle, double range, Pose2 pose) {
  Scan s;
  s.pose = pose;
  s.angle_min = angle;
  s.angle_increment = 0.01;
  s.ranges = {range};
  return s;
}

TEST(Geometry, CcwSensorAtOriginPointsAlongBeam) {
  SensorInfo sensor;
  const Eigen::Vector2d p = beamToWorld(oneBeam(kPi / 2, 2.0, {}), sensor, 0);
  EXPECT_NEAR(p.x(), 0.0, 1e-12);
  EXPECT_NEAR(p.y(), 2.0, 1e-12);
}

TEST(Geometry, ClockwiseDirectionMirrorsTheBeamAngle) {
  SensorInfo sensor;
  sensor.direction = BeamDirection::kCw;
  const Eigen::Vector2d p = beamToWorld(oneBeam(kPi / 2, 2.0, {}), sensor, 0);
  EXPECT_NEAR(p.y(), -2.0, 1e-12);
}

TEST(Geometry, MountOffsetRotatesWithTheRobot) {
  SensorInfo sensor;
  sensor.mount = {0.1, 0.0, 0.0};
  const Pose2 pose{1.0, 2.0, kPi / 2};
  const Eigen::Vector2d origin = sensorOrigin(pose, sensor.mount);
  EXPECT_NEAR(origin.x(), 1.0, 1e-12);
  EXPECT_NEAR(origin.y(), 2.1, 1e-12);
  // Beam angle 0 looks along the robot's heading (+y here).
  const Eigen::Vector2d p = beamToWorld(oneBeam(0.0, 1.0, pose), sensor, 0);
  EXPECT_NEAR(p.x(), 1.0, 1e-12);
  EXPECT_NEAR(p.y(), 3.1, 1e-12);
}

TEST(Geometry, FormatFormulaOnEveryBeam) {
  SensorInfo sensor;
  sensor.mount = {0.2, -0.1, 0.3};
  sensor.direction = BeamDirection::kCw;
  Scan s;
  s.pose = {-1.0, 0.5, 2.0};
  s.angle_min = -1.0;
  s.angle_increment = 0.25;
  s.ranges = {1.0, 2.0, 3.0, 4.0};
  std::vector<Eigen::Vector2d> world;
  worldPoints(s, sensor, world);
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double ox = s.pose.x + std::cos(s.pose.theta) * 0.2 - std::sin(s.pose.theta) * -0.1;
    const double oy = s.pose.y + std::sin(s.pose.theta) * 0.2 + std::cos(s.pose.theta) * -0.1;
    const double phi = s.pose.theta + 0.3 - (s.angle_min + i * s.angle_increment);
    EXPECT_NEAR(world[i].x(), ox + s.ranges[i] * std::cos(phi), 1e-12);
    EXPECT_NEAR(world[i].y(), oy + s.ranges[i] * std::sin(phi), 1e-12);
    EXPECT_NEAR((world[i] - beamToWorld(s, sensor, i)).norm(), 0.0, 1e-12);
  }
}

// The paper's robot: sensor C behind the centre, θc = 180°, angles clockwise,
// is mount [-C, 0, π] with direction cw (docs/algorithm.md).
TEST(Geometry, PaperEquation4IsTheSpecialCase) {
  const double c = 0.05;
  SensorInfo sensor;
  sensor.mount = {-c, 0.0, kPi};
  sensor.direction = BeamDirection::kCw;
  for (double theta0 : {0.0, 0.7, -2.5}) {
    for (double theta_p : {0.0, 0.4, 3.0, 5.5}) {
      const Pose2 robot{1.5, -0.5, theta0};
      const Eigen::Vector2d expected = paperEquation4(robot, c, kPi, theta_p, 2.5);
      const Eigen::Vector2d got = beamToWorld(oneBeam(theta_p, 2.5, robot), sensor, 0);
      EXPECT_NEAR((got - expected).norm(), 0.0, 1e-12) << "theta0 " << theta0 << " theta_p " << theta_p;
    }
  }
  // Beam 0 of the paper's sensor looks backwards from the robot.
  const Eigen::Vector2d back = paperEquation4({0, 0, 0}, c, kPi, 0.0, 1.0);
  EXPECT_NEAR(back.x(), -1.05, 1e-12);
}

TEST(Geometry, NoReturnBeamsGiveNaNPoints) {
  Scan s = oneBeam(0.0, std::nan(""), {});
  std::vector<Eigen::Vector2d> world;
  worldPoints(s, SensorInfo{}, world);
  EXPECT_TRUE(std::isnan(world[0].x()));
}

TEST(Geometry, FullTurnDetection) {
  Scan s;
  s.angle_increment = 2 * kPi / 360;
  s.ranges.assign(360, 1.0);
  EXPECT_TRUE(isFullTurn(s));
  s.ranges.assign(359, 1.0);
  EXPECT_FALSE(isFullTurn(s));
  s.angle_increment = -2 * kPi / 360;
  s.ranges.assign(360, 1.0);
  EXPECT_TRUE(isFullTurn(s));
}

TEST(Geometry, LocalSurfaceDirectionNeedsThreeReturnsOnOneLine) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  constexpr double kTolerance = 0.05;
  std::vector<Eigen::Vector2d> points = {{0.0, 1.0}, {0.1, 1.01}, {0.2, 1.0}, {0.3, 1.5}, {nan, nan}, {0.5, 1.0}};
  const auto flat = localSurfaceDirection(points, 1, kTolerance);
  ASSERT_TRUE(flat.has_value());
  EXPECT_NEAR(flat->x(), 0.2, 1e-12);
  EXPECT_NEAR(flat->y(), 0.0, 1e-12);
  EXPECT_FALSE(localSurfaceDirection(points, 2, kTolerance)) << "a bend: point 3 lies 0.5 m off";
  EXPECT_FALSE(localSurfaceDirection(points, 3, kTolerance)) << "a missing neighbour";
  EXPECT_FALSE(localSurfaceDirection(points, 0, kTolerance)) << "the first beam has one neighbour";
  EXPECT_FALSE(localSurfaceDirection(points, 5, kTolerance)) << "the last beam has one neighbour";
  EXPECT_TRUE(localSurfaceDirection(points, 2, 0.3)) << "within a looser tolerance";
  // Over two beams either side: point 2 between points 0 and 4 (no return),
  // point 3 between 1 and 5 (0.5 m off their chord), point 1 too near the start.
  const std::vector<Eigen::Vector2d> wall = {{0.0, 1.0}, {0.1, 1.0}, {0.2, 1.01}, {0.3, 1.0}, {0.4, 1.0}};
  const auto wide = localSurfaceDirection(wall, 2, kTolerance, 2);
  ASSERT_TRUE(wide.has_value());
  EXPECT_NEAR(wide->x(), 0.4, 1e-12) << "the chord from point 0 to point 4";
  EXPECT_FALSE(localSurfaceDirection(points, 2, kTolerance, 2)) << "point 4 is no return";
  EXPECT_FALSE(localSurfaceDirection(points, 3, kTolerance, 2)) << "point 3 lies off the chord of 1 and 5";
  EXPECT_FALSE(localSurfaceDirection(wall, 1, kTolerance, 2)) << "one beam before it, not two";
  EXPECT_FALSE(localSurfaceDirection(wall, 2, kTolerance, 0)) << "no span, no chord";
}

TEST(Geometry, DistanceFromTheLineThroughTwoPoints) {
  EXPECT_DOUBLE_EQ(distanceToLine({1, 2}, {0, 0}, {5, 0}), 2.0);
  EXPECT_DOUBLE_EQ(distanceToLine({-4, -3}, {0, 0}, {1, 0}), 3.0) << "the line, not the segment";
  EXPECT_DOUBLE_EQ(distanceToLine({3, 4}, {0, 0}, {0, 0}), 5.0) << "coincident points: the distance";
  EXPECT_TRUE(isFartherFromLineThan({1, 2}, {0, 0}, {5, 0}, 1.99));
  EXPECT_FALSE(isFartherFromLineThan({1, 2}, {0, 0}, {5, 0}, 2.01));
  EXPECT_TRUE(isFartherFromLineThan({3, 4}, {0, 0}, {0, 0}, 4.99));
  EXPECT_FALSE(isFartherFromLineThan({3, 4}, {0, 0}, {0, 0}, 5.01));
  EXPECT_FALSE(isFartherFromLineThan({1, 2}, {0, 0}, {5, 0}, 2.0)) << "exactly at the tolerance: not farther";
  // On squares it decides as the distance does wherever the two are more
  // than a rounding error apart (within a few ulp each rounds its own way).
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> coordinate(-10.0, 10.0), tolerance(0.0, 0.5);
  for (int k = 0; k < 100000; ++k) {
    const Eigen::Vector2d a(coordinate(rng), coordinate(rng));
    const Eigen::Vector2d b = a + Eigen::Vector2d(coordinate(rng), coordinate(rng)) * 0.05;
    const Eigen::Vector2d p = (a + b) / 2 + Eigen::Vector2d(coordinate(rng), coordinate(rng)) * 0.05;
    const double tol = tolerance(rng);
    const double distance = distanceToLine(p, a, b);
    if (std::abs(distance - tol) < 1e-9) continue;
    ASSERT_EQ(isFartherFromLineThan(p, a, b, tol), distance > tol) << "case " << k;
  }
}

TEST(Geometry, BeamsSpanningAnAngleRoundUpWithinTheScan) {
  const double one_degree = std::numbers::pi / 180.0;
  EXPECT_EQ(beamsSpanning(3.0, one_degree, 360), 3u) << "a whole number of steps, up to rounding";
  EXPECT_EQ(beamsSpanning(3.0 * (1.0 + 1e-12), one_degree, 360), 3u);
  EXPECT_EQ(beamsSpanning(3.1, one_degree, 360), 4u) << "part of a step counts as one";
  EXPECT_EQ(beamsSpanning(1.0, 0.1 * one_degree, 3600), 10u);
  EXPECT_EQ(beamsSpanning(1.0, -0.1 * one_degree, 3600), 10u) << "a clockwise scan's step is negative";
  EXPECT_EQ(beamsSpanning(0.01, one_degree, 360), 1u) << "at least one beam";
  EXPECT_EQ(beamsSpanning(45.0, 1e-300, 360), 360u) << "at most the scan, for any step";
}

TEST(Geometry, CellKeysOfDifferentCellsDiffer) {
  // Around the origin and at the int32 limits, where a sign or a carry
  // could fold one coordinate into the other.
  const std::int32_t max = std::numeric_limits<std::int32_t>::max();
  const std::int32_t min = std::numeric_limits<std::int32_t>::min();
  const std::vector<std::int32_t> values{min, -1, 0, 1, max};
  std::vector<std::uint64_t> keys;
  for (std::int32_t x : values)
    for (std::int32_t y : values) keys.push_back(cellKey(x, y));
  std::sort(keys.begin(), keys.end());
  EXPECT_EQ(std::adjacent_find(keys.begin(), keys.end()), keys.end());
}


}  // namespace
}  // namespace scanfilter
