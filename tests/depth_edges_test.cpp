// Step 2's cache takes no votes from returns at the near side of a depth
// edge (mixed returns smear an edge outwards), where the far side is a
// background the caller vouches for (step 2: returns it keeps, so that a
// pane's own returns next to ghosts it has marked still vote).
#include "scanfilter/depth_edges.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
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

BeamMask expected(std::initializer_list<int> flagged, std::size_t n) {
  BeamMask out(n);
  for (int i : flagged) out.set(static_cast<std::size_t>(i), true);
  return out;
}

TEST(DepthEdges, TheNearSideWithinTheMarginIsFlagged) {
  const Scan scan = boxBeforeAWall();
  const BeamMask background(scan.size(), true);
  EXPECT_EQ(nearSideOfDepthEdge(scan, background, 1, 0.15), expected({4}, scan.size()));
  EXPECT_EQ(nearSideOfDepthEdge(scan, background, 2, 0.15), expected({3, 4}, scan.size()));
  EXPECT_EQ(nearSideOfDepthEdge(scan, background, 0, 0.15), expected({}, scan.size())) << "0: off";
  EXPECT_EQ(nearSideOfDepthEdge(scan, background, 2, 1.5), expected({}, scan.size())) << "a step below depth_step";
}

TEST(DepthEdges, AFarSideThatIsNoBackgroundOrNoReturnIsNoEdge) {
  Scan scan = boxBeforeAWall();
  BeamMask background(scan.size(), true);
  for (std::size_t i = 5; i < scan.size(); ++i) background.set(i, false);  // ghosts behind a mirror
  EXPECT_EQ(nearSideOfDepthEdge(scan, background, 2, 0.15), expected({}, scan.size()));
  background.assign(scan.size(), true);
  for (std::size_t i = 5; i < scan.size(); ++i) scan.ranges[i] = kNaN;
  EXPECT_EQ(nearSideOfDepthEdge(scan, background, 2, 0.15), expected({}, scan.size()));
}

TEST(DepthEdges, TheFarSideIsNeverFlagged) {
  Scan scan = boxBeforeAWall();
  std::reverse(scan.ranges.begin(), scan.ranges.end());  // wall first, then the box
  const BeamMask background(scan.size(), true);
  EXPECT_EQ(nearSideOfDepthEdge(scan, background, 1, 0.15), expected({5}, scan.size()));
}

// The definition, beam by beam: the running maximum must give its answer.
BeamMask literalNearSide(const Scan& scan, const BeamMask& background, int half_width, double depth_step) {
  const int n = static_cast<int>(scan.size());
  BeamMask edge(scan.size());
  for (int i = 0; i < n && half_width > 0; ++i) {
    if (!scan.hasReturn(static_cast<std::size_t>(i))) continue;
    for (int j = std::max(0, i - half_width); j <= std::min(n - 1, i + half_width); ++j) {
      const auto k = static_cast<std::size_t>(j);
      if (background[k] && scan.ranges[k] > scan.ranges[static_cast<std::size_t>(i)] + depth_step)
        edge.set(static_cast<std::size_t>(i), true);
    }
  }
  return edge;
}

TEST(DepthEdges, AnyWidthGivesTheAnswerOfTestingEachBeamInTheWindow) {
  // Widths on both sides of the switch from the direct maximum to the blocks
  // (window 5), and wider than the scan; scans short and long.
  constexpr int kMaxHalfWidth = 25;
  constexpr int kMaxBeams = 120;
  constexpr double kNoReturnShare = 0.05, kInfiniteShare = 0.05, kBackgroundShare = 0.8;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> range(0.1, 8.0), share(0.0, 1.0);
  std::uniform_int_distribution<int> beams(1, kMaxBeams), half_widths(1, kMaxHalfWidth);
  for (int trial = 0; trial < 400; ++trial) {
    Scan scan;
    scan.angle_increment = 0.01;
    const auto n = static_cast<std::size_t>(beams(rng));
    BeamMask background(n);
    for (std::size_t k = 0; k < n; ++k) {
      const double what = share(rng);
      scan.ranges.push_back(what < kNoReturnShare                    ? kNaN
                            : what < kNoReturnShare + kInfiniteShare ? std::numeric_limits<double>::infinity()
                                                                      : range(rng));
      background.set(k, share(rng) < kBackgroundShare);
    }
    const int half_width = half_widths(rng);
    for (const double step : {0.0, 0.15, 1.0})
      ASSERT_EQ(nearSideOfDepthEdge(scan, background, half_width, step),
                literalNearSide(scan, background, half_width, step))
          << "trial " << trial << ", " << n << " beams, half width " << half_width << ", step " << step;
  }
}

}  // namespace
}  // namespace scanfilter
