// MirrorGhostCheck (Beyond the paper 35): a return beyond a mirror's line is
// a ghost when its mirror image lies on an obstacle the cache holds, and,
// past the remembered stretch, when the cache's returns continue the line
// on both sides of the crossing and are no surface crossing it.
#include <cmath>
#include <cstddef>
#include <vector>

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
MirrorCrossing crossingAt(double x, const Eigen::Vector2d& image, bool within_segment, std::size_t surface = 0,
                          double past_end = 0.0) {
  return {{x, 0.0}, {1.0, 0.0}, image, within_segment, surface, past_end};
}

void addReturns(PenetrationGrid& grid, const Eigen::Vector2d& p, int count) {
  for (int k = 0; k < count; ++k) grid.add(p);
}

TEST(MirrorGhostCheck, AGhostsImageLiesOnAnObstacleTheCacheHolds) {
  const MirrorGhostCheck check({});
  PenetrationGrid grid(kCell, kObstacleThreshold);
  addReturns(grid, {0.5, -1.5}, 3);  // the wall the reflected beam hit
  EXPECT_TRUE(check.isGhost(crossingAt(0.2, {0.52, -1.46}, true), grid));
  // Searched (the cells within image_radius along each axis), but 0.099 m off it.
  EXPECT_FALSE(check.isGhost(crossingAt(0.2, {0.43, -1.57}, true), grid)) << "beyond image_radius";
  PenetrationGrid too_few(kCell, kObstacleThreshold);
  addReturns(too_few, {0.5, -1.5}, 2);
  EXPECT_FALSE(check.isGhost(crossingAt(0.2, {0.5, -1.5}, true), too_few)) << "no obstacle: obs_th returns";
}

// Beyond the paper 44 takes a pane as there a little past its remembered
// stretch too, where neither the stretch nor the line test puts it.
TEST(MirrorGhostCheck, AMirrorIsWithinReachOfItsStretch) {
  const MirrorGhostCheck check({});
  const PenetrationGrid nothing_on_the_line(kCell, kObstacleThreshold);
  const Eigen::Vector2d image{2.0, -1.5};
  constexpr double kReach = 0.3;
  const MirrorCrossing just_past = crossingAt(2.0, image, false, 0, 0.2);
  EXPECT_FALSE(check.mirrorThere(just_past, nothing_on_the_line));
  EXPECT_TRUE(check.mirrorWithin(just_past, nothing_on_the_line, kReach));
  EXPECT_FALSE(check.mirrorWithin(just_past, nothing_on_the_line, 0.1)) << "past a shorter reach";
  EXPECT_FALSE(check.mirrorWithin(crossingAt(2.0, image, false, 0, 0.5), nothing_on_the_line, kReach));
  EXPECT_TRUE(check.mirrorWithin(crossingAt(2.0, image, true, 0, -0.4), nothing_on_the_line, 0.0)) << "on it";
  PenetrationGrid mirror_goes_on(kCell, kObstacleThreshold);  // its diffuse returns either side of the crossing
  addReturns(mirror_goes_on, {1.93, 0.01}, 1);
  addReturns(mirror_goes_on, {2.08, -0.02}, 1);
  EXPECT_TRUE(check.mirrorWithin(crossingAt(2.0, image, false, 0, 1.5), mirror_goes_on, kReach))
      << "far past, where the line test finds it";
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

  // Returns on one side of the crossing only: where the mirror ends.
  PenetrationGrid one_side = withObstacleAtImage();
  addReturns(one_side, {1.75, 0.0}, 1);
  addReturns(one_side, {1.9, 0.0}, 1);
  EXPECT_FALSE(check.isGhost(crossingAt(2.0, image, false), one_side));

  // Returns along the line, but one beyond line_window (0.3 m) of the
  // crossing, and others off the line by more than the crossing band.
  PenetrationGrid elsewhere = withObstacleAtImage();
  addReturns(elsewhere, {1.8, 0.0}, 1);
  addReturns(elsewhere, {2.32, 0.0}, 1);
  addReturns(elsewhere, {2.1, -0.2}, 1);
  EXPECT_FALSE(check.isGhost(crossingAt(2.0, image, false), elsewhere));
}

// A wall through the crossing: on the line it holds returns at one place
// (at right angles) or over a short stretch (at a shallow angle), with
// returns of its own just off the line beside them.
void addWallThrough(PenetrationGrid& grid, const Eigen::Vector2d& at, double angle_deg) {
  const double a = angle_deg * 3.14159265358979 / 180.0;
  const Eigen::Vector2d along(std::cos(a), std::sin(a));
  for (double t = -0.5; t <= 0.5; t += 0.01) addReturns(grid, at + t * along, 3);
}

TEST(MirrorGhostCheck, AWallCrossingTheLineDoesNotContinueTheMirror) {
  const MirrorGhostCheck check({});
  const Eigen::Vector2d image{2.0, -1.5};
  for (double angle : {90.0, 45.0, 20.0}) {
    PenetrationGrid grid(kCell, kObstacleThreshold);
    addReturns(grid, image, 3);
    addWallThrough(grid, {2.0, 0.0}, angle);
    EXPECT_FALSE(check.isGhost(crossingAt(2.0, image, false), grid)) << angle << "°";
  }
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
  addReturns(grid, {2.2, 0.0}, 1);  // -0.07 to 0.2 now
  EXPECT_TRUE(check.isGhost(crossingAt(2.0, {2.0, -1.5}, false), grid));
}

// Beyond the paper 43 asks only whether the mirror is there: a return
// through a pane has no image on anything.
TEST(MirrorGhostCheck, TheMirrorIsThereOnItsStretchAndWhereTheCachesReturnsContinueIt) {
  const Eigen::Vector2d image_on_nothing{2.0, -1.5};
  PenetrationGrid grid(kCell, kObstacleThreshold);
  const MirrorCrossing past_the_stretch = crossingAt(2.0, image_on_nothing, false);
  const MirrorGhostCheck check({});
  EXPECT_TRUE(check.mirrorThere(crossingAt(2.0, image_on_nothing, true), grid)) << "on the stretch";
  EXPECT_FALSE(check.mirrorThere(past_the_stretch, grid)) << "nothing along the line";
  addReturns(grid, {1.93, 0.01}, 1);
  addReturns(grid, {2.08, -0.02}, 1);
  EXPECT_TRUE(check.mirrorThere(past_the_stretch, grid));
}

// The ghost found in one mirror proves that one alone.
TEST(MirrorGhostCheck, ABeamWentThroughAProvenMirrorOnlyWhereThatMirrorIsThere) {
  const MirrorGhostCheck check({});
  const Eigen::Vector2d image_on_nothing{2.0, -1.5};
  PenetrationGrid grid(kCell, kObstacleThreshold);
  const std::vector<bool> second_proven = {false, true};
  EXPECT_TRUE(check.seenThroughProven(crossingAt(2.0, image_on_nothing, true, 1), second_proven, grid));
  EXPECT_FALSE(check.seenThroughProven(crossingAt(2.0, image_on_nothing, true, 0), second_proven, grid))
      << "the first mirror: no ghost found in it";
  EXPECT_FALSE(check.seenThroughProven(crossingAt(2.0, image_on_nothing, true, 2), second_proven, grid))
      << "a mirror the frame did not know";
  EXPECT_FALSE(check.seenThroughProven(crossingAt(2.0, image_on_nothing, false, 1), second_proven, grid))
      << "past its stretch, nothing along the line";
  addReturns(grid, {1.93, 0.01}, 1);
  addReturns(grid, {2.08, -0.02}, 1);
  EXPECT_TRUE(check.seenThroughProven(crossingAt(2.0, image_on_nothing, false, 1), second_proven, grid));
}

TEST(MirrorGhostCheck, MarksBeyondProvenMirrorsOnlyWithTheTestOn) {
  MirrorGhostParams params;
  EXPECT_TRUE(MirrorGhostCheck(params).marksBeyondProvenMirrors());
  params.enabled = false;
  EXPECT_FALSE(MirrorGhostCheck(params).marksBeyondProvenMirrors()) << "no ghost found, none proven";
  params.enabled = true;
  params.beyond_proven_mirrors = false;
  EXPECT_FALSE(MirrorGhostCheck(params).marksBeyondProvenMirrors());
}

}  // namespace
}  // namespace scanfilter
