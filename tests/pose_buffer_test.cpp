#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "scanfilter/pose_buffer.hpp"

namespace scanfilter {
namespace {

TEST(PoseBuffer, InterpolatesBetweenSamples) {
  PoseBuffer buffer(0.5, 10.0);
  buffer.add(1.0, {0.0, 0.0, 0.0});
  buffer.add(1.2, {1.0, 2.0, 0.4});
  const auto p = buffer.at(1.05);
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->x, 0.25, 1e-12);
  EXPECT_NEAR(p->y, 0.5, 1e-12);
  EXPECT_NEAR(p->theta, 0.1, 1e-12);
}

TEST(PoseBuffer, HeadingTakesTheShorterArc) {
  PoseBuffer buffer(0.5, 10.0);
  buffer.add(0.0, {0, 0, 3.0});
  buffer.add(1.0, {0, 0, -3.0});  // 0.28 rad further on, across ±π
  const auto p = buffer.at(0.5);
  ASSERT_TRUE(p);
  EXPECT_NEAR(std::abs(p->theta), std::numbers::pi, 1e-9);
}

TEST(PoseBuffer, NoPoseOutOfReachOrOutsideTheSamples) {
  PoseBuffer buffer(0.1, 10.0);
  buffer.add(1.0, {0, 0, 0});
  buffer.add(2.0, {1, 0, 0});
  EXPECT_FALSE(buffer.at(1.5)) << "samples 1 s apart, 0.1 s allowed";
  EXPECT_FALSE(buffer.at(0.5)) << "before the first sample";
  EXPECT_FALSE(buffer.at(2.5)) << "after the last sample";
  EXPECT_TRUE(buffer.mayStillPose(2.5));
  EXPECT_FALSE(buffer.mayStillPose(1.5)) << "a later sample exists: the gap is final";
  EXPECT_TRUE(PoseBuffer(0.1, 10.0).mayStillPose(0.0)) << "no odometry yet: wait for it";
  EXPECT_TRUE(buffer.at(2.0));
}

TEST(PoseBuffer, OutOfOrderSamplesAreIgnoredAndOldOnesDropped) {
  PoseBuffer buffer(0.5, 1.0);
  EXPECT_TRUE(buffer.add(1.0, {0, 0, 0}));
  EXPECT_FALSE(buffer.add(0.9, {5, 5, 0}));
  buffer.add(1.5, {1, 0, 0});
  buffer.add(3.0, {2, 0, 0});
  EXPECT_EQ(buffer.size(), 1u) << "samples more than 1 s older than the newest are dropped";
}

}  // namespace
}  // namespace scanfilter
