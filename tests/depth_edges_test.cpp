// Step 2's cache takes no votes from returns at the near side of a depth
// edge (mixed returns smear an edge outwards), where the far side is a
// background the caller vouches for (step 2: returns it keeps, so that a
// pane's own returns next to ghosts it has marked still vote).
#include "scanfilter/depth_edges.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace scanfilter {
namespace {

constexpr double kNaN = std::nan("");

// Beams 0-4 on a box 1 m away, beams 5-9 on a wall 2 m away.
Scan boxBeforeAWall() {
  Scan scan;
  scan.angle_increment = 0.01;
  scan.ranges = {1.0, 1.0, 1.0, 1.0, 1.0, 2.0, 2.0, 2.0, 2.0, 2.0};
  return scan;
}

std::vector<bool> expected(std::initializer_list<int> flagged, std::size_t n) {
  std::vector<bool> out(n, false);
  for (int i : flagged) out[static_cast<std::size_t>(i)] = true;
  return out;
}

TEST(DepthEdges, TheNearSideWithinTheMarginIsFlagged) {
  const Scan scan = boxBeforeAWall();
  const std::vector<bool> background(scan.size(), true);
  EXPECT_EQ(nearSideOfDepthEdge(scan, background, 1, 0.15), expected({4}, scan.size()));
  EXPECT_EQ(nearSideOfDepthEdge(scan, background, 2, 0.15), expected({3, 4}, scan.size()));
  EXPECT_EQ(nearSideOfDepthEdge(scan, background, 0, 0.15), expected({}, scan.size())) << "0: off";
  EXPECT_EQ(nearSideOfDepthEdge(scan, background, 2, 1.5), expected({}, scan.size())) << "a step below depth_step";
}

TEST(DepthEdges, AFarSideThatIsNoBackgroundOrNoReturnIsNoEdge) {
  Scan scan = boxBeforeAWall();
  std::vector<bool> background(scan.size(), true);
  for (std::size_t i = 5; i < scan.size(); ++i) background[i] = false;  // ghosts behind a mirror
  EXPECT_EQ(nearSideOfDepthEdge(scan, background, 2, 0.15), expected({}, scan.size()));
  background.assign(scan.size(), true);
  for (std::size_t i = 5; i < scan.size(); ++i) scan.ranges[i] = kNaN;
  EXPECT_EQ(nearSideOfDepthEdge(scan, background, 2, 0.15), expected({}, scan.size()));
}

TEST(DepthEdges, TheFarSideIsNeverFlagged) {
  Scan scan = boxBeforeAWall();
  std::reverse(scan.ranges.begin(), scan.ranges.end());  // wall first, then the box
  const std::vector<bool> background(scan.size(), true);
  EXPECT_EQ(nearSideOfDepthEdge(scan, background, 1, 0.15), expected({5}, scan.size()));
}

}  // namespace
}  // namespace scanfilter
