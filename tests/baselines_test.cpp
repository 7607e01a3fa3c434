// The baselines of the accuracy comparison, each on hand-built scans.
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "scan_builder.hpp"
#include "scanfilter/baselines/median_image_filter.hpp"
#include "scanfilter/baselines/optics_filter.hpp"
#include "scanfilter/baselines/radius_outlier_filter.hpp"
#include "scanfilter/baselines/scan_shadows_filter.hpp"
#include "scanfilter/baselines/speckle_filter.hpp"

namespace scanfilter {
namespace {

using namespace baselines;
using test::kDeg;

constexpr auto kValid = static_cast<std::uint8_t>(PointCode::kValid);
constexpr auto kNoReturn = static_cast<std::uint8_t>(PointCode::kNoReturn);

// A partial scan with the given ranges, beam 0 at -90°, `step_deg` apart.
Scan rangesScan(std::vector<double> ranges, double step_deg = 1.0) {
  Scan scan;
  scan.angle_min = -90.0 * kDeg;
  scan.angle_increment = step_deg * kDeg;
  scan.ranges = std::move(ranges);
  return scan;
}

std::vector<std::uint8_t> run(ScanFilter& filter, const Scan& scan) {
  std::vector<std::uint8_t> labels(scan.size(), 99);
  filter.apply(scan, test::simpleSensor(), labels);
  return labels;
}

std::vector<std::size_t> removedBeams(const std::vector<std::uint8_t>& labels) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < labels.size(); ++i)
    if (labels[i] != kValid && labels[i] != kNoReturn) out.push_back(i);
  return out;
}

// A flat wall facing the sensor at `distance`, seen by beams -30°..+30°.
Scan facingWall(double distance, double step_deg = 1.0) {
  std::vector<double> ranges;
  for (double a = -30.0; a <= 30.0 + 1e-9; a += step_deg) ranges.push_back(distance / std::cos(a * kDeg));
  Scan scan = rangesScan(ranges, step_deg);
  scan.angle_min = -30.0 * kDeg;
  return scan;
}

// A foreground object (1 m) in front of a background wall (3 m), with one
// mixed return between them at beam `mixed`.
Scan depthStepWithMixedPoint(std::size_t mixed = 30) {
  std::vector<double> ranges(60, 3.0);
  for (std::size_t i = 0; i < mixed; ++i) ranges[i] = 1.0;
  ranges[mixed] = 2.0;
  return rangesScan(ranges);
}

// --- ScanShadowsFilter --------------------------------------------------------

TEST(ScanShadowsFilter, KeepsAWallSeenHeadOn) {
  ScanShadowsFilter filter({});
  EXPECT_TRUE(removedBeams(run(filter, facingWall(2.0))).empty());
}

TEST(ScanShadowsFilter, RemovesTheVeilingPointBehindAnEdgeButNeverTheForeground) {
  ScanShadowsParams p;
  p.neighbors = 1;
  ScanShadowsFilter filter(p);
  const auto labels = run(filter, depthStepWithMixedPoint(30));
  EXPECT_NE(labels[30], kValid);  // the mixed return
  for (std::size_t i = 0; i < 30; ++i) EXPECT_EQ(labels[i], kValid) << i;
  // Beyond `neighbors` of an edge, background stays.
  for (std::size_t i = 33; i < 60; ++i) EXPECT_EQ(labels[i], kValid) << i;
}

TEST(ScanShadowsFilter, WithoutNeighboursAndStartPointRemovesNothing) {
  // laser_filters' own default (neighbors = 0) compares each point with itself only.
  ScanShadowsParams p;
  p.neighbors = 0;
  ScanShadowsFilter filter(p);
  EXPECT_TRUE(removedBeams(run(filter, depthStepWithMixedPoint())).empty());
  p.remove_shadow_start_point = true;
  ScanShadowsFilter with_start(p);
  EXPECT_FALSE(removedBeams(run(with_start, depthStepWithMixedPoint())).empty());
}

TEST(ScanShadowsFilter, NoReturnIsNeverAnEdge) {
  auto scan = facingWall(2.0);
  scan.ranges[10] = std::numeric_limits<double>::quiet_NaN();
  ScanShadowsFilter filter({});
  const auto labels = run(filter, scan);
  EXPECT_EQ(labels[10], kNoReturn);
  EXPECT_EQ(removedBeams(labels).size(), 0u);
}

// --- SpeckleFilter ------------------------------------------------------------

TEST(SpeckleFilter, DistanceModeRemovesALoneRangeAndKeepsFarOnes) {
  const Scan scan = rangesScan({1, 1, 1, 3, 1, 1, 1});
  SpeckleParams p;
  p.max_range = 10.0;
  SpeckleFilter filter(p);
  EXPECT_EQ(removedBeams(run(filter, scan)), std::vector<std::size_t>{3});
  p.max_range = 2.0;  // beyond max_range: never removed
  SpeckleFilter near_only(p);
  EXPECT_TRUE(removedBeams(run(near_only, scan)).empty());
}

TEST(SpeckleFilter, EuclideanModeCountsNeighboursWithinTheChord) {
  const Scan scan = rangesScan({1, 1, 1, 3, 1, 1, 1});
  SpeckleParams p;
  p.mode = SpeckleMode::kEuclidean;
  p.max_range = 10.0;
  p.filter_window = 1;
  SpeckleFilter filter(p);
  EXPECT_EQ(removedBeams(run(filter, scan)), std::vector<std::size_t>{3});
  // As published, a valid window at i also keeps beams up to i + window - 1:
  // with window 2 the lone return right after a supported one survives.
  p.filter_window = 2;
  SpeckleFilter window2(p);
  EXPECT_TRUE(removedBeams(run(window2, scan)).empty());
  p.filter_window = 1;
  p.max_range_difference = 0.01;  // 1° at 1 m is a 17 mm chord: nobody has neighbours
  SpeckleFilter tight(p);
  EXPECT_EQ(removedBeams(run(tight, scan)).size(), 7u);
}

// --- RadiusOutlierFilter ------------------------------------------------------

TEST(RadiusOutlierFilter, RemovesAnIsolatedReturnAndKeepsASmallTightCluster) {
  std::vector<double> ranges(90, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t i = 0; i < 30; ++i) ranges[i] = 1.0;  // a wall
  ranges[50] = 2.0;                                      // isolated
  ranges[70] = ranges[71] = ranges[72] = 1.5;            // a leg: 3 points 2.6 cm apart
  RadiusOutlierFilter filter({0.1, 2});
  EXPECT_EQ(removedBeams(run(filter, rangesScan(ranges))), std::vector<std::size_t>{50});
  RadiusOutlierFilter strict({0.1, 3});  // the leg's points have only 2 neighbours each
  EXPECT_EQ(removedBeams(run(strict, rangesScan(ranges))), (std::vector<std::size_t>{50, 70, 71, 72}));
}

// --- OpticsFilter -------------------------------------------------------------

TEST(OpticsFilter, OrderingVisitsEveryReturnOnceAndStartsUnreachable) {
  auto scan = facingWall(2.0);
  scan.ranges[5] = std::numeric_limits<double>::quiet_NaN();
  OpticsFilter filter({});
  run(filter, scan);
  auto order = filter.ordering();
  EXPECT_EQ(order.size(), scan.size() - 1);
  std::sort(order.begin(), order.end());
  EXPECT_TRUE(std::adjacent_find(order.begin(), order.end()) == order.end());
  EXPECT_TRUE(std::isinf(filter.reachability()[filter.ordering().front()]));
}

TEST(OpticsFilter, KeepsAWallAndRemovesAnIsolatedReturn) {
  auto scan = facingWall(1.0);
  scan.ranges[40] = 2.0;  // 1 m behind the wall, alone
  OpticsFilter filter({});
  EXPECT_EQ(removedBeams(run(filter, scan)), std::vector<std::size_t>{40});
}

TEST(OpticsFilter, EllipseIsShortInDepth) {
  // Points 0.15 m apart along the scan line are neighbours at eps 0.2; the
  // same spacing along the beams is 0.3 m in the ellipse metric (ratio 0.5).
  OpticsParams p;
  p.eps = 0.2;
  p.eps_cluster = 0.2;
  p.min_pts = 2;
  p.min_cluster_size = 6;
  OpticsFilter filter(p);
  // Tangential: a wall at 2 m, beams 4.3° apart (0.15 m).
  const double step = 2.0 * std::asin(0.075 / 2.0) / kDeg;
  std::vector<double> wall(6, 2.0);
  EXPECT_TRUE(removedBeams(run(filter, rangesScan(wall, step))).empty());
  // Radial: ranges 2.0, 2.15, ... on beams 0.01° apart.
  std::vector<double> depth;
  for (int k = 0; k < 6; ++k) depth.push_back(2.0 + 0.15 * k);
  EXPECT_EQ(removedBeams(run(filter, rangesScan(depth, 0.01))).size(), 6u);
  p.axis_ratio = 1.0;  // a circle: the same points cluster
  OpticsFilter circle(p);
  EXPECT_TRUE(removedBeams(run(circle, rangesScan(depth, 0.01))).empty());
}

TEST(OpticsFilter, ExtractionAgreesWithDbscanOnCorePointsAndNoise) {
  // Ankerst et al.: extracting at eps' gives DBSCAN's clusters at eps' for
  // core points; a point neither core nor within eps' of a core point is noise.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> r(0.5, 4.0);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<double> ranges(180);
    double current = r(rng);
    for (auto& x : ranges) {
      if (rng() % 10 == 0) current = r(rng);  // a new surface
      x = rng() % 15 == 0 ? r(rng) : current + 0.01 * (rng() % 5);
    }
    const Scan scan = rangesScan(ranges);
    OpticsParams p;
    p.axis_ratio = 1.0;
    p.min_cluster_size = 1;
    OpticsFilter filter(p);
    const auto labels = run(filter, scan);
    std::vector<Eigen::Vector2d> pts;
    BeamDirectionTable table;
    sensorFramePoints(scan, test::simpleSensor(), table, pts);
    const auto neighbours = [&](std::size_t i) {
      int count = 0;
      for (auto& q : pts) count += (q - pts[i]).norm() <= p.eps_cluster;
      return count;
    };
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const bool core = neighbours(i) >= p.min_pts;
      bool near_core = false;
      for (std::size_t j = 0; j < pts.size(); ++j)
        near_core |= (pts[j] - pts[i]).norm() <= p.eps_cluster && neighbours(j) >= p.min_pts;
      if (core) {
        EXPECT_EQ(labels[i], kValid) << "trial " << trial << " beam " << i;
      }
      if (!near_core) {
        EXPECT_NE(labels[i], kValid) << "trial " << trial << " beam " << i;
      }
    }
  }
}

// --- MedianImageFilter --------------------------------------------------------

TEST(MedianImageFilter, KeepsAWallSeenRepeatedlyAndDropsAOneOffGhost) {
  MedianImageParams p;
  p.frames = 5;
  p.threshold = 3;
  MedianImageFilter filter(p);
  auto scan = facingWall(2.0, 0.5);
  std::vector<std::uint8_t> labels;
  for (int frame = 0; frame < 5; ++frame) labels = run(filter, scan);
  EXPECT_TRUE(removedBeams(labels).empty());
  scan.ranges[60] = 3.0;  // a ghost 1 m behind the wall, seen once
  labels = run(filter, scan);
  EXPECT_EQ(removedBeams(labels), std::vector<std::size_t>{60});
  EXPECT_EQ(labels[60], static_cast<std::uint8_t>(PointCode::kMisdetected));
}

TEST(MedianImageFilter, AFullWindowMedianErasesOneCellThickWalls) {
  // Why ignore_empty exists: a wall fills 3 of the 9 cells of a 3x3 window.
  MedianImageParams p;
  p.frames = 5;
  p.threshold = 1;
  p.ignore_empty = false;
  MedianImageFilter filter(p);
  std::vector<std::uint8_t> labels;
  // 2.02 m: the wall stays inside one column of 5 cm cells.
  for (int frame = 0; frame < 5; ++frame) labels = run(filter, facingWall(2.02, 0.5));
  EXPECT_GT(removedBeams(labels).size(), labels.size() / 2);
}

TEST(MedianImageFilter, ForgetsFramesOlderThanTheWindow) {
  MedianImageParams p;
  p.frames = 2;
  p.window = 1;  // the grey level of the cell itself
  MedianImageFilter filter(p);
  const Eigen::Vector2d on_wall(2.02, 1e-3);
  const auto wall = facingWall(2.02, 0.5);
  run(filter, wall);
  const int one_frame = filter.smoothedGrey(on_wall);
  EXPECT_GT(one_frame, 0);
  run(filter, wall);
  EXPECT_EQ(filter.smoothedGrey(on_wall), 2 * one_frame);
  const auto elsewhere = facingWall(4.0, 0.5);
  run(filter, elsewhere);
  run(filter, elsewhere);
  EXPECT_EQ(filter.smoothedGrey(on_wall), 0);
}

}  // namespace
}  // namespace scanfilter
