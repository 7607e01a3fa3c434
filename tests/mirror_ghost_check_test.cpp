// MirrorGhostCheck (Beyond the paper 35): a return beyond a mirror's line is
// a ghost when its mirror image lies on an obstacle the cache holds, and,
// past the remembered stretch, when the cache's returns continue the line.
#include <gtest/gtest.h>

#include <Eigen/Core>

#include "scanfilter/mirror_ghost_check.hpp"
#include "scanfilter/penetration_grid.hpp"

namespace scanfilter {
namespace {

constexpr double kCell = 0.05;
constexpr int kObstacleThreshold = 2;  // a cell of 3 returns is an obstacle

// A mirror along the x axis; the beam crossed it at (x, 0), its return
// mirrored to `image`.
MirrorCrossing crossingAt(double x, const Eigen::Vector2d& image, bool within_segment) {
  return {{x, 0.0}, {1.0, 0.0}, image, within_segment};
}

void addReturns(PenetrationGrid& grid, const Eigen::Vector2d& p, int count) {
  for (int k = 0; k < count; ++k) grid.add(p);
}

TEST(MirrorGhostCheck, AGhostsImageLiesOnAnObstacleTheCacheHolds) {
  const MirrorGhostCheck check({});
  PenetrationGrid grid(kCell, kObstacleThreshold);
  addReturns(grid, {0.5, -1.5}, 3);  // the wall the reflected beam hit
  EXPECT_TRUE(check.isGhost(crossingAt(0.2, {0.52, -1.46}, true), grid));
  EXPECT_FALSE(check.isGhost(crossingAt(0.2, {0.5, -1.7}, true), grid)) << "0.2 m off it: beyond image_radius";
  PenetrationGrid too_few(kCell, kObstacleThreshold);
  addReturns(too_few, {0.5, -1.5}, 2);
  EXPECT_FALSE(check.isGhost(crossingAt(0.2, {0.5, -1.5}, true), too_few)) << "no obstacle: obs_th returns";
}

TEST(MirrorGhostCheck, PastTheRememberedStretchTheCachesReturnsMustContinueTheLine) {
  const MirrorGhostCheck check({});
  const Eigen::Vector2d image{2.0, -1.5};
  const auto withObstacleAtImage = [&] {
    PenetrationGrid grid(kCell, kObstacleThreshold);
    addReturns(grid, image, 3);
    return grid;
  };
  PenetrationGrid nothing_on_the_line = withObstacleAtImage();
  EXPECT_FALSE(check.isGhost(crossingAt(2.0, image, false), nothing_on_the_line));
  EXPECT_TRUE(check.isGhost(crossingAt(2.0, image, true), nothing_on_the_line)) << "on the stretch, no evidence needed";

  // A mirror's diffuse returns, single, 0.15 m apart along its line.
  PenetrationGrid mirror_goes_on = withObstacleAtImage();
  addReturns(mirror_goes_on, {1.93, 0.01}, 1);
  addReturns(mirror_goes_on, {2.08, -0.02}, 1);
  EXPECT_TRUE(check.isGhost(crossingAt(2.0, image, false), mirror_goes_on));

  // A wall crossing the line at right angles holds returns at one place on it only.
  PenetrationGrid wall_across = withObstacleAtImage();
  for (double y = -0.3; y <= 0.3; y += 0.02) addReturns(wall_across, {2.01, y}, 3);
  EXPECT_FALSE(check.isGhost(crossingAt(2.0, image, false), wall_across));

  // Returns along the line but too far from the crossing, or off the line.
  PenetrationGrid elsewhere = withObstacleAtImage();
  addReturns(elsewhere, {2.4, 0.0}, 1);
  addReturns(elsewhere, {2.6, 0.0}, 1);
  addReturns(elsewhere, {1.9, 0.1}, 1);
  addReturns(elsewhere, {2.1, -0.1}, 1);
  EXPECT_FALSE(check.isGhost(crossingAt(2.0, image, false), elsewhere));
}

TEST(MirrorGhostCheck, TheLinesSpreadIsAParameter) {
  MirrorGhostParams params;
  params.line_spread = 0.2;
  const MirrorGhostCheck check(params);
  PenetrationGrid grid(kCell, kObstacleThreshold);
  addReturns(grid, {2.0, -1.5}, 3);
  addReturns(grid, {1.93, 0.0}, 1);
  addReturns(grid, {2.08, 0.0}, 1);
  EXPECT_FALSE(check.isGhost(crossingAt(2.0, {2.0, -1.5}, false), grid)) << "0.15 m < 0.2 m";
  addReturns(grid, {2.2, 0.0}, 1);
  EXPECT_TRUE(check.isGhost(crossingAt(2.0, {2.0, -1.5}, false), grid));
}

}  // namespace
}  // namespace scanfilter
