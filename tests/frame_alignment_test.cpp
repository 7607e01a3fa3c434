// Step 2's frame alignment: a frame whose odometry pose is off is fitted back
// onto the cached frames before it is judged, so its walls are not taken for
// ghosts; a frame whose pose is right keeps it.
#include "scanfilter/frame_alignment.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "scan_builder.hpp"
#include "scanfilter/penetration_filter.hpp"
#include "scanfilter/point_code.hpp"

namespace scanfilter {
namespace {

using test::castScan;
using test::World;

// A room with a pillar, so that all three degrees of freedom are constrained.
const World kRoom = World{}
                        .wall({3, -2.5}, {3, 2.5})
                        .wall({-3, -2.5}, {3, -2.5})
                        .wall({-3, 2.5}, {3, 2.5})
                        .wall({-3, -2.5}, {-3, 2.5})
                        .wall({1.0, 0.8}, {1.4, 0.8})
                        .wall({1.4, 0.8}, {1.4, 1.2});
const World kCorridor = World{}.wall({-20, -1}, {20, -1}).wall({-20, 1}, {20, 1});

// A grid voted by `frames` noise-free scans from poses along x.
PenetrationGrid cacheOf(const World& world, const SensorInfo& sensor, int frames) {
  PenetrationGrid grid(0.05, 2);
  std::vector<Eigen::Vector2d> points;
  for (int k = 0; k < frames; ++k) {
    const Scan scan = castScan(world, {0.03 * k, 0.0, 0.0}, sensor);
    worldPoints(scan, sensor, points);
    for (const auto& p : points)
      if (!std::isnan(p.x())) grid.add(p);
  }
  return grid;
}

struct Placed {
  std::vector<Eigen::Vector2d> points;
  BeamMask usable;
  Eigen::Vector2d origin;
};

// The frame seen from `truth`, placed where odometry `believed` says it is.
Placed placedFrame(const World& world, const SensorInfo& sensor, const Pose2& truth, const Pose2& believed) {
  Scan scan = castScan(world, truth, sensor);
  scan.pose = believed;
  Placed out;
  worldPoints(scan, sensor, out.points);
  for (const auto& p : out.points) out.usable.push_back(!std::isnan(p.x()));
  out.origin = sensorOrigin(believed, sensor.mount);
  return out;
}

TEST(FrameAligner, TakesOutAPoseError) {
  const SensorInfo sensor = test::simpleSensor();
  const PenetrationGrid grid = cacheOf(kRoom, sensor, 10);
  const Pose2 truth{0.3, 0.1, 0.0};
  const Pose2 believed{0.36, 0.07, 1.5 * test::kDeg};  // 6 cm, 3 cm and 1.5° off
  const Placed frame = placedFrame(kRoom, sensor, truth, believed);
  FrameAligner aligner{FrameAlignmentParams{}};
  const FrameAlignment fit = aligner.align(grid, frame.points, frame.usable, frame.origin);
  ASSERT_TRUE(fit.good) << fit.matches << " of " << fit.candidates << " matched, rms " << fit.rms;
  const Eigen::Vector2d corrected = fit.correction * frame.origin;
  const Eigen::Vector2d true_origin = sensorOrigin(truth, sensor.mount);
  EXPECT_LT((corrected - true_origin).norm(), 0.005);
  EXPECT_NEAR(Eigen::Rotation2Dd(fit.correction.linear()).angle(), -1.5 * test::kDeg, 0.1 * test::kDeg);
  EXPECT_LT(fit.rms, 0.005);
}

TEST(FrameAligner, AFrameThatFitsKeepsItsPose) {
  const SensorInfo sensor = test::simpleSensor();
  const PenetrationGrid grid = cacheOf(kRoom, sensor, 10);
  Placed frame = placedFrame(kRoom, sensor, {0.3, 0.1, 0.0}, {0.3, 0.1, 0.0});
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.01);  // range noise alone must not move it
  for (auto& p : frame.points)
    if (!std::isnan(p.x())) p += (p - frame.origin).normalized() * noise(rng);
  FrameAligner aligner{FrameAlignmentParams{}};
  const FrameAlignment fit = aligner.align(grid, frame.points, frame.usable, frame.origin);
  EXPECT_TRUE(fit.good);
  EXPECT_TRUE(fit.correction.matrix().isIdentity(0.0)) << fit.correction.matrix();
}

TEST(FrameAligner, LeavesTheUnconstrainedDirectionOfACorridorAlone) {
  const SensorInfo sensor = test::simpleSensor();
  const PenetrationGrid grid = cacheOf(kCorridor, sensor, 10);
  // 5 cm off across the corridor (seen) and 20 cm along it (unseen: no wall ends in range).
  const Placed frame = placedFrame(kCorridor, sensor, {0.3, 0.0, 0.0}, {0.5, 0.05, 0.0});
  FrameAligner aligner{FrameAlignmentParams{}};
  const FrameAlignment fit = aligner.align(grid, frame.points, frame.usable, frame.origin);
  ASSERT_TRUE(fit.good);
  const Eigen::Vector2d shift = fit.correction * frame.origin - frame.origin;
  EXPECT_NEAR(shift.y(), -0.05, 0.005) << "across the corridor: corrected";
  EXPECT_NEAR(shift.x(), 0.0, 0.01) << "along it: nothing to go by, left as it was";
}

TEST(FrameAligner, AFrameOfSomewhereElseDoesNotFit) {
  const SensorInfo sensor = test::simpleSensor();
  const PenetrationGrid grid = cacheOf(kRoom, sensor, 10);
  const World elsewhere = World{}.wall({-1.2, -4}, {-1.2, 4}).wall({-4, 1.7}, {4, 1.7});
  const Placed frame = placedFrame(elsewhere, sensor, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0});
  FrameAligner aligner{FrameAlignmentParams{}};
  EXPECT_FALSE(aligner.align(grid, frame.points, frame.usable, frame.origin).good);
}

// A fine scanner's frame is fitted with every k-th point only (the cost of
// the fit stays that of a few hundred points) and still takes out the error.
TEST(FrameAligner, AFineScanIsFittedWithAtMostMaxFitPoints) {
  SensorInfo sensor = test::simpleSensor();
  const PenetrationGrid grid = cacheOf(kRoom, sensor, 10);
  FrameAlignmentParams params;
  params.max_fit_points = 100;
  const Placed frame = placedFrame(kRoom, sensor, {0.3, 0.1, 0.0}, {0.36, 0.07, 1.5 * test::kDeg});
  FrameAligner aligner{params};
  const FrameAlignment fit = aligner.align(grid, frame.points, frame.usable, frame.origin);
  ASSERT_TRUE(fit.good) << fit.matches << " of " << fit.candidates;
  EXPECT_EQ(fit.candidates, 100);
  EXPECT_LT((fit.correction * frame.origin - sensorOrigin({0.3, 0.1, 0.0}, sensor.mount)).norm(), 0.005)
      << "spread over the scan: all three degrees of freedom still constrained";
  params.max_fit_points = 0;  // all
  FrameAligner all{params};
  EXPECT_GT(all.align(grid, frame.points, frame.usable, frame.origin).candidates, 200);
}

// Through step 2: odometry drifting 2 cm and 0.5° per frame makes the walls of
// each new frame lie beside the cached ones, and without alignment step 2
// takes them for points behind walls; with it, none is lost.
TEST(PenetrationFilterAlignment, DriftingOdometryLosesNoWall) {
  const SensorInfo sensor = test::simpleSensor();
  auto misdetectedWith = [&](bool align) {
    PenetrationFilterParams params;
    params.alignment.enabled = align;
    auto filter = makePenetrationFilter(params, Implementation::kFast);
    std::size_t misdetected = 0;
    std::vector<std::uint8_t> labels;
    for (int k = 0; k < 30; ++k) {
      const Pose2 truth{0.05 * k, 0.0, 0.0};
      Scan scan = castScan(kRoom, truth, sensor, 360, 0.1 * k);
      scan.pose = {truth.x + 0.02 * k, truth.y, truth.theta + 0.5 * test::kDeg * k};
      labels.assign(scan.size(), static_cast<std::uint8_t>(PointCode::kValid));
      for (std::size_t i = 0; i < scan.size(); ++i)
        if (!scan.hasReturn(i)) labels[i] = static_cast<std::uint8_t>(PointCode::kNoReturn);
      filter->apply(scan, sensor, labels);
      misdetected += static_cast<std::size_t>(
          std::count(labels.begin(), labels.end(), static_cast<std::uint8_t>(PointCode::kMisdetected)));
    }
    return std::pair{misdetected, filter->unalignedFrames()};
  };
  const auto [without, unused] = misdetectedWith(false);
  const auto [with, unaligned] = misdetectedWith(true);
  EXPECT_GT(without, 100u) << "the drift must hurt, or this test shows nothing";
  EXPECT_EQ(with, 0u);
  EXPECT_EQ(unaligned, 0u);
}

}  // namespace
}  // namespace scanfilter
