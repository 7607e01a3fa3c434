#include <algorithm>

#include <gtest/gtest.h>

#include "scan_builder.hpp"
#include "scanfilter/point_code.hpp"
#include "scanfilter/two_step_filter.hpp"

namespace scanfilter {
namespace {

using test::castScan;
using test::World;

constexpr auto kValid = static_cast<std::uint8_t>(PointCode::kValid);

const World kRoomWithLeg =
    World{}.wall({4, -4}, {4, 4}).wall({-4, -4}, {4, -4}).wall({-4, 4}, {4, 4}).wall({-4, -4}, {-4, 4}).leg({1.0, 0.0}, 0.015);

// The defaults keep a 3 cm leg at 1 m once the robot has seen it for a few
// frames: step 1 deletes its one- or two-beam cluster, the rescue restores it.
TEST(TwoStepFilter, ThinLegAtOneMetreIsKeptAfterWarmUp) {
  const SensorInfo sensor = test::simpleSensor();
  TwoStepFilter filter(TwoStepFilterParams{}, Implementation::kFast);
  std::vector<std::uint8_t> labels;
  std::size_t leg_beams = 0, leg_kept = 0;
  for (int k = 0; k < 30; ++k) {
    const Scan scan = castScan(kRoomWithLeg, {-0.01 * k, 0.005 * k, 0.0}, sensor, 360, 0.1 * k);
    labels.resize(scan.size());
    filter.apply(scan, sensor, labels);
    if (k < 10) continue;  // warm-up and first sightings
    for (std::size_t i = 0; i < scan.size(); ++i) {
      if (!scan.hasReturn(i) || scan.ranges[i] > 1.2) continue;
      ++leg_beams;
      leg_kept += labels[i] == kValid;
    }
  }
  EXPECT_GE(leg_beams, 15u);
  EXPECT_EQ(leg_kept, leg_beams);
}

TEST(TwoStepFilter, BothStepsOffKeepsEveryReturn) {
  const SensorInfo sensor = test::simpleSensor();
  TwoStepFilterParams p;
  p.jump_enabled = false;
  p.penetration_enabled = false;
  TwoStepFilter filter(p, Implementation::kFast);
  Scan scan = castScan(kRoomWithLeg, {}, sensor);
  scan.ranges[100] = 7.5;  // beyond the sensor: stays a no-return in the input
  std::vector<std::uint8_t> labels(scan.size());
  filter.apply(scan, sensor, labels);
  for (std::size_t i = 0; i < scan.size(); ++i)
    EXPECT_EQ(labels[i], scan.hasReturn(i) ? kValid : static_cast<std::uint8_t>(PointCode::kNoReturn));
}

TEST(TwoStepFilter, JumpCodeWinsOverMisdetected) {
  // A lone point far behind a known wall: both steps would remove it; step 1 labels it.
  const SensorInfo sensor = test::simpleSensor();
  TwoStepFilter filter(TwoStepFilterParams{}, Implementation::kFast);
  std::vector<std::uint8_t> labels;
  for (int k = 0; k < 10; ++k) {
    Scan scan = castScan(kRoomWithLeg, {-0.01 * k, 0.0, 0.0}, sensor, 360, 0.1 * k);
    labels.resize(scan.size());
    filter.apply(scan, sensor, labels);
  }
  Scan scan = castScan(kRoomWithLeg, {-0.1, 0.0, 0.0}, sensor, 360, 1.0);
  const std::size_t i = test::beamTowards(scan, sensor, 2.0);
  scan.ranges[i] += 1.5;
  filter.apply(scan, sensor, labels);
  EXPECT_EQ(labels[i], static_cast<std::uint8_t>(PointCode::kJump));
}

}  // namespace
}  // namespace scanfilter
