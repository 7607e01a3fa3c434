#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "scanfilter/pose_buffer.hpp"

namespace scanfilter {
namespace {

// Stamps a little after a large epoch, where a double would blur nanoseconds.
Stamp t(double seconds_after_epoch) {
  constexpr std::int64_t kEpoch = 1'732'000'000 * Stamp::kNanosPerSecond;
  return Stamp::fromNanoseconds(kEpoch + Stamp::fromSeconds(seconds_after_epoch).nanoseconds());
}

TEST(PoseBuffer, InterpolatesBetweenSamples) {
  PoseBuffer buffer(0.5, 10.0);
  buffer.add(t(1.0), {0.0, 0.0, 0.0});
  buffer.add(t(1.2), {1.0, 2.0, 0.4});
  const auto p = buffer.at(t(1.05));
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->x, 0.25, 1e-12);
  EXPECT_NEAR(p->y, 0.5, 1e-12);
  EXPECT_NEAR(p->theta, 0.1, 1e-12);
}

TEST(PoseBuffer, HeadingTakesTheShorterArc) {
  PoseBuffer buffer(0.5, 10.0);
  buffer.add(t(0.0), {0, 0, 3.0});
  buffer.add(t(1.0), {0, 0, -3.0});  // 0.28 rad further on, across ±π
  const auto p = buffer.at(t(0.5));
  ASSERT_TRUE(p);
  EXPECT_NEAR(std::abs(p->theta), std::numbers::pi, 1e-9);
}

TEST(PoseBuffer, NoPoseOutOfReachOrOutsideTheSamples) {
  PoseBuffer buffer(0.1, 10.0);
  buffer.add(t(1.0), {0, 0, 0});
  buffer.add(t(2.0), {1, 0, 0});
  EXPECT_FALSE(buffer.at(t(1.5))) << "samples 1 s apart, 0.1 s allowed";
  EXPECT_FALSE(buffer.at(t(0.5))) << "before the first sample";
  EXPECT_FALSE(buffer.at(t(2.5))) << "after the last sample";
  EXPECT_TRUE(buffer.mayStillPose(t(2.5)));
  EXPECT_FALSE(buffer.mayStillPose(t(1.5))) << "a later sample exists: the gap is final";
  EXPECT_TRUE(PoseBuffer(0.1, 10.0).mayStillPose(t(0.0))) << "no odometry yet: wait for it";
  EXPECT_TRUE(buffer.at(t(2.0)));
}

TEST(PoseBuffer, AScanAtASampleStampGetsThatSampleExactly) {
  PoseBuffer buffer(0.1, 10.0);
  const Stamp a = Stamp::fromSecNanosec(1'732'000'000, 200'700'000);
  const Stamp b = Stamp::fromSecNanosec(1'732'000'000, 200'700'001);  // 1 ns later
  buffer.add(a, {1, 0, 0});
  buffer.add(b, {2, 0, 0});
  EXPECT_EQ(buffer.at(b)->x, 2.0);
  EXPECT_EQ(buffer.at(a)->x, 1.0);
}

TEST(PoseBuffer, OutOfOrderSamplesAreIgnoredAndOldOnesDropped) {
  PoseBuffer buffer(0.5, 1.0);
  EXPECT_TRUE(buffer.add(t(1.0), {0, 0, 0}));
  EXPECT_FALSE(buffer.add(t(0.9), {5, 5, 0}));
  buffer.add(t(1.5), {1, 0, 0});
  buffer.add(t(3.0), {2, 0, 0});
  EXPECT_EQ(buffer.size(), 1u) << "samples more than 1 s older than the newest are dropped";
}

// A scan that waited while its odometry aged out is told apart from one
// from before the first sample. (After a long gap forgot() is true too: the
// live ingest tells a scan that waited through a hold apart, LiveSource.)
TEST(PoseBuffer, ForgetsOnlyWhatItOnceHeld) {
  PoseBuffer buffer(0.5, 1.0);
  buffer.add(t(1.0), {0, 0, 0});
  EXPECT_FALSE(buffer.forgot(t(0.5))) << "before the first sample: never held";
  buffer.add(t(1.5), {1, 0, 0});
  EXPECT_FALSE(buffer.forgot(t(1.2))) << "still held";
  buffer.add(t(2.0), {2, 0, 0});
  buffer.add(t(2.6), {3, 0, 0});
  EXPECT_FALSE(buffer.at(t(1.2)).has_value());
  EXPECT_TRUE(buffer.forgot(t(1.2))) << "1.0 and 1.5 were dropped as older than 1 s";
  EXPECT_FALSE(buffer.forgot(t(0.5))) << "before the first sample ever";
  EXPECT_FALSE(buffer.forgot(t(2.3))) << "within what is held";
}

// A driver restarted on simulated time: its odometry starts over, and the
// scans of the new clock are posed at once.
TEST(PoseBuffer, AClockThatWentBackStartsOver) {
  PoseBuffer buffer(0.5, 1.0);
  buffer.add(t(199.5), {0, 0, 0});
  buffer.add(t(200.0), {1, 0, 0});
  EXPECT_FALSE(buffer.add(t(199.8), {5, 5, 0})) << "a little back: an old sample, ignored";
  EXPECT_TRUE(buffer.add(t(150.0), {2, 0, 0})) << "far back: a new clock";
  buffer.add(t(150.2), {3, 0, 0});
  ASSERT_TRUE(buffer.at(t(150.1)).has_value());
  EXPECT_DOUBLE_EQ(buffer.at(t(150.1))->x, 2.5);
  EXPECT_FALSE(buffer.forgot(t(149.0))) << "the old clock's samples are not 'forgotten' for the new one";
}

}  // namespace
}  // namespace scanfilter
