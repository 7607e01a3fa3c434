#include <algorithm>
#include <limits>
#include <numbers>

#include <random>

#include <gtest/gtest.h>

#include "scan_builder.hpp"
#include "scanfilter/jump_filter.hpp"
#include "scanfilter/point_code.hpp"

namespace scanfilter {
namespace {

using test::castScan;
using test::kDeg;
using test::World;

std::vector<std::uint8_t> label(const Scan& scan, const SensorInfo& sensor,
                                const JumpFilterParams& params = JumpFilterParams{}) {
  std::vector<std::uint8_t> out(scan.size());
  for (auto impl : {Implementation::kReference, Implementation::kFast}) {
    std::vector<std::uint8_t> labels(scan.size());
    makeJumpFilter(params, impl)->apply(scan, sensor, labels);
    if (impl == Implementation::kReference) out = labels;
    else EXPECT_EQ(labels, out) << "fast and reference disagree";
  }
  return out;
}

std::size_t countCode(const std::vector<std::uint8_t>& labels, PointCode code) {
  return static_cast<std::size_t>(std::count(labels.begin(), labels.end(), static_cast<std::uint8_t>(code)));
}

TEST(JumpFilter, StraightWallKeepsEveryPoint) {
  const SensorInfo sensor = test::simpleSensor();
  const Scan scan = castScan(World{}.wall({2, -3}, {2, 3}), {}, sensor);
  const auto labels = label(scan, sensor);
  EXPECT_GT(countCode(labels, PointCode::kValid), 100u);
  EXPECT_EQ(countCode(labels, PointCode::kJump), 0u);
}

TEST(JumpFilter, NoReturnBeamsAreLabelledNoReturn) {
  const SensorInfo sensor = test::simpleSensor();
  const Scan scan = castScan(World{}.wall({2, -3}, {2, 3}), {}, sensor);
  const auto labels = label(scan, sensor);
  for (std::size_t i = 0; i < scan.size(); ++i)
    EXPECT_EQ(labels[i] == static_cast<std::uint8_t>(PointCode::kNoReturn), !scan.hasReturn(i));
}

TEST(JumpFilter, MixedReturnTrailBetweenEdgeAndWallIsRemoved) {
  // A box edge at 1.5 m in front of a wall at 4 m; the three beams past the
  // edge return ranges between the two: the mixed-pixel trail. It stands in
  // front of the wall's side only, so keep_foreground_clusters (on by
  // default) does not keep it.
  const SensorInfo sensor = test::simpleSensor();
  // The robot faces -1 rad so the edge is far from the scan's seam at beam 0.
  Scan scan = castScan(World{}.wall({1.5, -1.5}, {1.5, 0.0}).wall({4, -4}, {4, 4}), {0, 0, -1.0}, sensor);
  const std::size_t edge = test::beamTowards(scan, sensor, 0.0);
  ASSERT_NEAR(scan.ranges[edge - 1], 1.5, 0.01);
  const std::size_t trail[] = {edge + 1, edge + 2, edge + 3};
  scan.ranges[trail[0]] = 2.1;
  scan.ranges[trail[1]] = 2.8;
  scan.ranges[trail[2]] = 3.5;
  const auto labels = label(scan, sensor);
  for (std::size_t i : trail) EXPECT_EQ(labels[i], static_cast<std::uint8_t>(PointCode::kJump)) << "beam " << i;
  EXPECT_EQ(countCode(labels, PointCode::kJump), 3u);
}

TEST(JumpFilter, TwoPointTrailIsRemoved) {
  const SensorInfo sensor = test::simpleSensor();
  Scan scan = castScan(World{}.wall({1.0, -1.0}, {1.0, 0.0}).wall({3, -4}, {3, 4}), {0, 0, -1.0}, sensor);
  const std::size_t edge = test::beamTowards(scan, sensor, 0.0);
  scan.ranges[edge + 1] = 1.6;
  scan.ranges[edge + 2] = 2.3;
  const auto labels = label(scan, sensor);
  EXPECT_EQ(labels[edge + 1], static_cast<std::uint8_t>(PointCode::kJump));
  EXPECT_EQ(labels[edge + 2], static_cast<std::uint8_t>(PointCode::kJump));
}

TEST(JumpFilter, SparseWallAtFiveAndAHalfMetresIsKept) {
  // At 5.5 m neighbouring returns are 9.6 cm apart; with ±3 cm of noise the
  // range-scaled radius of eq. 5 must still join them.
  const SensorInfo sensor = test::simpleSensor();
  Scan scan = castScan(World{}.wall({5.5, -1.5}, {5.5, 1.5}), {}, sensor);
  for (std::size_t i = 0; i < scan.size(); ++i)
    if (scan.hasReturn(i)) scan.ranges[i] += (i % 2 ? 0.03 : -0.03);
  const auto labels = label(scan, sensor);
  EXPECT_GT(countCode(labels, PointCode::kValid), 25u);
  EXPECT_EQ(countCode(labels, PointCode::kJump), 0u);
}

TEST(JumpFilter, ThinLegAtOneMetreIsKeptWhenEq7Allows) {
  // A 3 cm leg at 1 m spans 1.7°: two beams, a span of 1°. It passes eq. 7
  // with a short minimum tangential length (the defaults delete it in step 1
  // and restore it in step 2's rescue: two_step_filter_test.cpp).
  const SensorInfo sensor = test::simpleSensor();
  const Scan scan = castScan(World{}.leg({1.0, 0.5 * kDeg}, 0.015).wall({4, -4}, {4, 4}), {}, sensor);
  JumpFilterParams params;
  params.l_min = 0.005;
  params.l_max = 0.05;
  const auto labels = label(scan, sensor, params);
  std::size_t leg_beams = 0;
  for (std::size_t i = 0; i < scan.size(); ++i) {
    if (scan.hasReturn(i) && scan.ranges[i] < 1.1) {
      ++leg_beams;
      EXPECT_EQ(labels[i], static_cast<std::uint8_t>(PointCode::kValid)) << "leg beam " << i;
    }
  }
  EXPECT_EQ(leg_beams, 2u);
}

TEST(JumpFilter, SingleIsolatedReturnIsRemovedByEquation7) {
  const SensorInfo sensor = test::simpleSensor();
  Scan scan = castScan(World{}.wall({4, -4}, {4, 4}), {}, sensor);
  const std::size_t i = test::beamTowards(scan, sensor, 0.0);
  scan.ranges[i] = 2.0;  // a lone point in free space
  JumpFilterParams paper;  // a lone return spans no angle: eq. 7 always deletes it
  paper.keep_foreground_clusters = false;
  const auto labels = label(scan, sensor, paper);
  EXPECT_EQ(labels[i], static_cast<std::uint8_t>(PointCode::kJump));
  EXPECT_EQ(countCode(labels, PointCode::kJump), 1u);
}

TEST(JumpFilter, ClusterAcrossTheSeamIsOneCluster) {
  // A short wall straddling beam 0 of a full-turn scan: its beams sit at both
  // ends of the index range. Its span must wrap, not cover the whole turn,
  // and it must be judged as one cluster.
  const SensorInfo sensor = test::simpleSensor();
  Scan scan = castScan(World{}.wall({2.0, -0.035}, {2.0, 0.035}), {}, sensor);
  ASSERT_TRUE(scan.hasReturn(0));
  ASSERT_TRUE(scan.hasReturn(scan.size() - 1));
  const auto labels = label(scan, sensor);
  // Two beams spanning 1° at 2 m: span 1° against θ_th; both get one verdict.
  EXPECT_EQ(labels[0], labels[scan.size() - 1]);
  EXPECT_EQ(JumpClusterRule::spanInBeams(std::vector<std::uint32_t>{0, 359}, 360, true), 1u);
  EXPECT_EQ(JumpClusterRule::spanInBeams(std::vector<std::uint32_t>{0, 359}, 360, false), 359u);
  EXPECT_EQ(JumpClusterRule::spanInBeams(std::vector<std::uint32_t>{0, 120, 240}, 360, true), 240u);
}

// --- The off-surface check (beyond the paper) --------------------------------

TEST(OffSurfaceCheck, CatchesAReturnDisplacedAlongItsBeamThatJoinedTheWallCluster) {
  const SensorInfo sensor = test::simpleSensor();
  Scan scan = castScan(World{}.wall({2, -3}, {2, 3}), {}, sensor);
  const std::size_t i = test::beamTowards(scan, sensor, 10 * kDeg);
  scan.ranges[i] -= 0.10;  // 10 cm in front of the wall: within eq. 5's radius of its neighbours
  JumpFilterParams paper;
  paper.off_surface_check = false;
  EXPECT_EQ(countCode(label(scan, sensor, paper), PointCode::kJump), 0u) << "the cluster rule alone keeps it";
  const auto labels = label(scan, sensor);
  EXPECT_EQ(labels[i], static_cast<std::uint8_t>(PointCode::kJump));
  EXPECT_EQ(countCode(labels, PointCode::kJump), 1u) << "its neighbours stay: each lies on its other side's line";
}

TEST(OffSurfaceCheck, KeepsCornersAndNoiseWithinTolerance) {
  const SensorInfo sensor = test::simpleSensor();
  Scan scan = castScan(World{}.wall({2, -3}, {2, 2}).wall({2, 2}, {-3, 2}), {}, sensor);
  for (std::size_t i = 0; i < scan.size(); ++i)
    if (scan.hasReturn(i)) scan.ranges[i] += (i % 2 ? 0.012 : -0.012);  // about 2σ at 2-3 m
  const auto labels = label(scan, sensor);
  EXPECT_EQ(countCode(labels, PointCode::kJump), 0u);
}

TEST(JumpClusterRule, Equation5ScalesWithRange) {
  JumpFilterParams p;
  p.angular_accuracy_deg = 1.0;
  p.alpha = 2.0;
  p.theta_k_deg = 60.0;
  p.radius_noise_sigmas = 0.0;  // the paper's radius alone
  const JumpClusterRule rule(p);
  const double expected = 2.0 * 3.0 * std::sin(kDeg) * 2.0 / std::cos(60.0 * kDeg);
  EXPECT_NEAR(rule.neighbourRadius(3.0), expected, 1e-12);
}

TEST(JumpClusterRule, RangeNoiseWidensTheRadius) {
  JumpFilterParams p;
  p.radius_noise_sigmas = 3.0;
  p.noise_sigma_base = 0.003;
  p.noise_sigma_quadratic = 0.001;
  JumpFilterParams paper = p;
  paper.radius_noise_sigmas = 0.0;
  const JumpClusterRule widened(p), literal(paper);
  EXPECT_NEAR(widened.neighbourRadius(3.0) - literal.neighbourRadius(3.0), 3.0 * (0.003 + 0.001 * 9.0), 1e-12);
  // The window bound covers the radius at every range in the interval.
  const double bound = widened.maxRadiusPerMetre(0.15, 6.0);
  for (double d = 0.15; d <= 6.0; d += 0.01) EXPECT_LE(widened.neighbourRadius(d), bound * d + 1e-12) << d;
}

// At 0.1° steps range noise (σ 1.2 cm at 3 m) exceeds eq. 5's radius (1.8 cm at
// 3 m): a plain wall falls apart into clusters eq. 7 deletes unless the radius
// allows for the noise.
TEST(JumpFilter, ANoisyWallAtFineStepsStaysWhole) {
  const SensorInfo sensor = test::simpleSensor();
  Scan scan = castScan(World{}.wall({3, -4}, {3, 4}), {0, 0, 0}, sensor, 3600);
  std::mt19937 rng(3);
  for (auto& r : scan.ranges)
    if (r == r) r += std::normal_distribution<double>(0.0, 0.003 + 0.001 * r * r)(rng);
  auto jumpPoints = [&](double sigmas) {
    JumpFilterParams p;
    p.angular_accuracy_deg = 0.1;
    p.radius_noise_sigmas = sigmas;
    std::vector<std::uint8_t> labels(scan.size());
    makeJumpFilter(p, Implementation::kFast)->apply(scan, sensor, labels);
    return countCode(labels, PointCode::kJump);
  };
  const std::size_t returns = static_cast<std::size_t>(std::count_if(scan.ranges.begin(), scan.ranges.end(),
                                                                     [](double r) { return r == r; }));
  EXPECT_GT(jumpPoints(0.0), returns / 10) << "without the widening the wall falls apart, or this shows nothing";
  EXPECT_LT(jumpPoints(3.0), returns / 100);
}

TEST(JumpClusterRule, Equation7InterpolatesTheMinimumLength) {
  JumpFilterParams p;
  p.l_min = 0.02;
  p.l_max = 0.10;
  p.d_min = 0.0;
  p.d_max = 4.0;
  const JumpClusterRule rule(p);
  EXPECT_NEAR(rule.spanThreshold(2.0, 2.0), 2.0 * std::atan(0.06 / 4.0), 1e-12);
  EXPECT_NEAR(rule.spanThreshold(8.0, 8.0), 2.0 * std::atan(0.10 / 16.0), 1e-12);  // clamped at l_max
  p.span_range = SpanRange::kSeed;
  const JumpClusterRule seed_rule(p);
  EXPECT_NEAR(seed_rule.spanThreshold(2.0, 0.0), 2.0 * std::atan(0.02 / 4.0), 1e-12);
}

}  // namespace
}  // namespace scanfilter

namespace scanfilter {
namespace {

// A long wall seen at grazing incidence from 0.5 m beside it: with 1° beams its
// returns lie far apart (range·Δθ / cos incidence, 0.3 m at 4 m), farther than
// eq. 5's radius, so eq. 7 would delete them cluster by cluster. One straight
// run of them is one surface and joins one cluster.
std::size_t jumpPointsOnAGrazingWall(bool straight_runs) {
  const SensorInfo sensor = test::simpleSensor();
  const Scan scan = castScan(World{}.wall({-1, 0.5}, {8, 0.5}), {0, 0, 0}, sensor);
  JumpFilterParams params;
  params.straight_runs = straight_runs;
  std::vector<std::uint8_t> labels(scan.size());
  makeJumpFilter(params, Implementation::kFast)->apply(scan, sensor, labels);
  return static_cast<std::size_t>(std::count(labels.begin(), labels.end(), static_cast<std::uint8_t>(PointCode::kJump)));
}

TEST(StraightRuns, KeepAWallSeenAtGrazingIncidence) {
  EXPECT_GT(jumpPointsOnAGrazingWall(false), 3u) << "without the join the wall falls apart, or this shows nothing";
  EXPECT_EQ(jumpPointsOnAGrazingWall(true), 0u);
}

}  // namespace
}  // namespace scanfilter

namespace scanfilter {
namespace {

// keep_foreground_clusters (on by default): a cluster too short for eq. 7
// that stands in front of what the sensor sees on both sides of it is kept.
JumpFilterParams keepingForeground(bool keep = true) {
  JumpFilterParams params;
  params.keep_foreground_clusters = keep;
  return params;
}

// A wall at 4 m with one beam returning at 2 m: a leg, a pole.
Scan wallWithALoneReturnInFront(std::size_t* beam) {
  const SensorInfo sensor = test::simpleSensor();
  Scan scan = castScan(World{}.wall({4, -4}, {4, 4}), {}, sensor);
  *beam = test::beamTowards(scan, sensor, 0.0);
  scan.ranges[*beam] = 2.0;
  return scan;
}

TEST(ForegroundClusters, ALoneReturnInFrontOfAWallIsKept) {
  const SensorInfo sensor = test::simpleSensor();
  std::size_t i = 0;
  const Scan scan = wallWithALoneReturnInFront(&i);
  EXPECT_EQ(label(scan, sensor, keepingForeground(false))[i], static_cast<std::uint8_t>(PointCode::kJump))
      << "without the option eq. 7 deletes it";
  EXPECT_EQ(JumpFilterParams{}.keep_foreground_clusters, true) << "config/filter.yaml ships it on";
  const auto labels = label(scan, sensor, keepingForeground());
  EXPECT_EQ(labels[i], static_cast<std::uint8_t>(PointCode::kValid));
  EXPECT_EQ(countCode(labels, PointCode::kJump), 0u);
}

TEST(ForegroundClusters, ABeamWithoutAReturnBesideItCountsAsFarther) {
  const SensorInfo sensor = test::simpleSensor();
  std::size_t i = 0;
  Scan scan = wallWithALoneReturnInFront(&i);
  scan.ranges[i + 1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(label(scan, sensor, keepingForeground())[i], static_cast<std::uint8_t>(PointCode::kValid));
}

TEST(ForegroundClusters, AReturnBetweenItsNeighboursIsStillRemoved) {
  // Beside the lone return at 2 m, one at 3 m: in front of the wall, but
  // behind its other neighbour, as a mixed return between the two is.
  const SensorInfo sensor = test::simpleSensor();
  std::size_t i = 0;
  Scan scan = wallWithALoneReturnInFront(&i);
  scan.ranges[i + 1] = 3.0;
  const auto labels = label(scan, sensor, keepingForeground());
  EXPECT_EQ(labels[i], static_cast<std::uint8_t>(PointCode::kValid));
  EXPECT_EQ(labels[i + 1], static_cast<std::uint8_t>(PointCode::kJump));
}

TEST(ForegroundClusters, TheEndOfAPartialScanIsNoBackground) {
  // A half-turn scan whose first beam returns at 2 m in front of the wall:
  // nothing is known beyond the field of view, so eq. 7 decides.
  const SensorInfo sensor = test::simpleSensor();
  Scan scan = castScan(World{}.wall({4, -4}, {4, 4}), {0, 0, -0.5}, sensor);
  scan.ranges.resize(180);
  ASSERT_TRUE(scan.hasReturn(1));
  scan.ranges[0] = 0.5 * scan.ranges[1];
  EXPECT_EQ(label(scan, sensor, keepingForeground())[0], static_cast<std::uint8_t>(PointCode::kJump));
}

TEST(ForegroundClusters, AClusterAcrossTheSeamIsJudgedByTheBeamsOutsideIt) {
  // Two beams at 2 m, the last and the first of a full turn, in front of a
  // wall at 4 m: the beams outside the cluster are n-2 and 1, not 0-1 and n.
  const SensorInfo sensor = test::simpleSensor();
  Scan scan = castScan(World{}.wall({4, -4}, {4, 4}), {}, sensor);
  const std::size_t n = scan.size();
  ASSERT_TRUE(scan.hasReturn(0) && scan.hasReturn(n - 1) && scan.hasReturn(1) && scan.hasReturn(n - 2));
  scan.ranges[0] = scan.ranges[n - 1] = 2.0;
  auto labels = label(scan, sensor, keepingForeground());
  EXPECT_EQ(labels[0], static_cast<std::uint8_t>(PointCode::kValid));
  EXPECT_EQ(labels[n - 1], static_cast<std::uint8_t>(PointCode::kValid));
  scan.ranges[1] = 2.01;  // the side beyond beam 0 is no farther: nothing stands in front of it there
  scan.ranges[2] = 2.02;
  labels = label(scan, sensor, keepingForeground());
  EXPECT_EQ(labels[n - 1], labels[0]);
}

}  // namespace
}  // namespace scanfilter

namespace scanfilter {
namespace {

// keep_unresolved_returns: a lone return where the beams lie l_max apart or
// more is kept; a nearer one is still eq. 7's to delete.
std::uint8_t lonePointLabel(double wall_range, double lone_range, bool keep_unresolved) {
  SensorInfo sensor = test::simpleSensor();
  sensor.range_max = 12.0;
  // Facing -1 rad: the beam towards the wall is far from the seam at beam 0.
  Scan scan = castScan(World{}.wall({wall_range, -8}, {wall_range, 8}), {0, 0, -1.0}, sensor);
  const std::size_t i = test::beamTowards(scan, sensor, 0.0);
  scan.ranges[i - 1] = scan.ranges[i + 1] = std::numeric_limits<double>::quiet_NaN();  // nothing beside it
  scan.ranges[i] = lone_range;
  JumpFilterParams params;
  params.keep_foreground_clusters = false;  // judge eq. 7 alone
  params.keep_unresolved_returns = keep_unresolved;
  params.d_max = sensor.range_max;
  return label(scan, sensor, params)[i];
}

TEST(UnresolvedReturns, ALoneReturnBeyondTheResolvableRangeIsKept) {
  // At 1° the beams lie l_max = 0.1 m apart at 5.73 m.
  EXPECT_EQ(lonePointLabel(9.0, 6.0, true), static_cast<std::uint8_t>(PointCode::kValid));
  EXPECT_EQ(lonePointLabel(9.0, 6.0, false), static_cast<std::uint8_t>(PointCode::kJump));
}

TEST(UnresolvedReturns, ANearerLoneReturnIsStillDeleted) {
  EXPECT_EQ(lonePointLabel(9.0, 5.5, true), static_cast<std::uint8_t>(PointCode::kJump));
}

}  // namespace
}  // namespace scanfilter
