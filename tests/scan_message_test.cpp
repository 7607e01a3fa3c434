// The conversions between the wire types and Scan: what a ROS 2 consumer of
// rt/scan_filtered gets back (REP 117, exact stamps, its own frame and angles)
// and how an upside-down sensor's scan is placed in the world.
#include "scanfilter/dds/scan_message.hpp"

#include <cmath>
#include <cstring>
#include <limits>

#include <gtest/gtest.h>

#include "scanfilter/point_code.hpp"
#include "scanfilter/scan_geometry.hpp"

namespace scanfilter::dds_io {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

std::uint32_t bitsOf(float x) {
  std::uint32_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  return bits;
}

// A driver's scan with a stamp a double cannot hold and every kind of beam:
// returns, +inf (no return), NaN (error), 0, below range_min, above range_max.
LaserScanMsg driverScan() {
  LaserScanMsg msg;
  msg.header().stamp().sec(1'732'000'000);
  msg.header().stamp().nanosec(200'700'001);
  msg.header().frame_id("base_laser_flipped");
  msg.angle_min(-1.5707964f);
  msg.angle_increment(0.0043633231f);
  msg.angle_max(msg.angle_min() + 7 * msg.angle_increment() + 1e-7f);  // as a driver rounds it, not recomputable
  msg.time_increment(1.7361111e-05f);
  msg.scan_time(0.025f);
  msg.range_min(0.05f);
  msg.range_max(25.0f);
  msg.ranges() = {1.2345679f, kInf, kNaN, 0.0f, 0.01f, 31.5f, 2.5f, 2.4999998f};
  msg.intensities() = {100.f, 0.f, 0.f, 0.f, 3.f, 1.f, 77.f, 78.f};
  return msg;
}

LabeledScanMsg throughTheFilter(const LaserScanMsg& in, const LaserMount& mount, std::vector<std::uint8_t> labels) {
  Scan scan;
  SensorInfo sensor;
  fromLaserScan(in, mount, scan, sensor);
  scan.labels = std::move(labels);
  LabeledScanMsg msg;
  toMessage(scan, sensor, 1, msg);
  msg.source_scan(sourceScanOf(in));
  return msg;
}

const std::vector<std::uint8_t> kLabels = {0, 3, 3, 3, 3, 3, 1, 2};  // beam 6 jump, beam 7 misdetected

TEST(FilteredLaserScan, KeepsStampFrameAnglesAndEveryKeptBeamExactly) {
  const LaserScanMsg in = driverScan();
  LaserScanMsg out;
  toFilteredLaserScan(throughTheFilter(in, {}, kLabels), "unused", RemovedBeamValue::kNaN, out);
  EXPECT_EQ(out.header().stamp().sec(), in.header().stamp().sec());
  EXPECT_EQ(out.header().stamp().nanosec(), in.header().stamp().nanosec());
  EXPECT_EQ(out.header().frame_id(), in.header().frame_id());
  EXPECT_EQ(bitsOf(out.angle_min()), bitsOf(in.angle_min()));
  EXPECT_EQ(bitsOf(out.angle_max()), bitsOf(in.angle_max()));
  EXPECT_EQ(bitsOf(out.angle_increment()), bitsOf(in.angle_increment()));
  EXPECT_EQ(bitsOf(out.time_increment()), bitsOf(in.time_increment()));
  EXPECT_EQ(bitsOf(out.scan_time()), bitsOf(in.scan_time()));
  EXPECT_EQ(bitsOf(out.range_min()), bitsOf(in.range_min()));
  EXPECT_EQ(bitsOf(out.range_max()), bitsOf(in.range_max()));
  ASSERT_EQ(out.ranges().size(), in.ranges().size());
  for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(bitsOf(out.ranges()[i]), bitsOf(in.ranges()[i])) << "kept beam " << i;
  EXPECT_TRUE(std::isnan(out.ranges()[6])) << "removed beams are NaN by default";
  EXPECT_TRUE(std::isnan(out.ranges()[7]));
  EXPECT_EQ(out.intensities(), in.intensities());
}

TEST(FilteredLaserScan, RemovedBeamsCanBeInfinity) {
  LaserScanMsg out;
  toFilteredLaserScan(throughTheFilter(driverScan(), {}, kLabels), "unused", RemovedBeamValue::kInfinity, out);
  EXPECT_EQ(out.ranges()[6], kInf);
  EXPECT_EQ(out.ranges()[7], kInf);
  EXPECT_EQ(out.ranges()[1], kInf) << "a no-return stays a no-return";
  EXPECT_TRUE(std::isnan(out.ranges()[2])) << "an error stays an error";
}

TEST(FilteredLaserScan, ALogScanGetsTheConfiguredFrameAndCounterClockwiseAngles) {
  Scan scan;
  scan.stamp = Stamp::fromSecNanosec(5, 7);
  scan.angle_min = 0.1;
  scan.angle_increment = 0.01;
  scan.ranges = {1.0, std::nan(""), 2.0};
  scan.recorded_ranges = {1.0, std::numeric_limits<double>::infinity(), 2.0};
  scan.labels = {0, 3, 1};
  SensorInfo sensor;
  sensor.direction = BeamDirection::kCw;
  sensor.range_min = 0.1;
  sensor.range_max = 10;
  LabeledScanMsg msg;
  toMessage(scan, sensor, 0, msg);
  LaserScanMsg out;
  toFilteredLaserScan(msg, "laser", RemovedBeamValue::kNaN, out);
  EXPECT_EQ(out.header().frame_id(), "laser");
  EXPECT_EQ(out.header().stamp().nanosec(), 7u);
  EXPECT_FLOAT_EQ(out.angle_min(), -0.1f);
  EXPECT_FLOAT_EQ(out.angle_increment(), -0.01f);
  EXPECT_EQ(out.ranges()[1], kInf) << "the log's +inf is kept";
  EXPECT_TRUE(std::isnan(out.ranges()[2]));
}

TEST(LabeledScanMessage, CarriesTheStampExactly) {
  Scan scan;
  scan.stamp = *Stamp::parseDecimal("1732000000.200700045");
  scan.ranges = {1.0};
  SensorInfo sensor_out;
  sensor_out.range_max = 5;
  LabeledScanMsg msg;
  toMessage(scan, sensor_out, 0, msg);
  EXPECT_EQ(msg.header().stamp().sec(), 1'732'000'000);
  EXPECT_EQ(msg.header().stamp().nanosec(), 200'700'045u);
  Scan back;
  SensorInfo sensor;
  fromMessage(msg, back, sensor);
  EXPECT_EQ(back.stamp, scan.stamp);
}

TEST(LabeledScanMessage, RejectsATimeWithTooManyNanoseconds) {
  Scan scan;
  scan.ranges = {1.0};
  SensorInfo sensor;
  sensor.range_min = 0.1;
  sensor.range_max = 5;
  LabeledScanMsg msg;
  toMessage(scan, sensor, 0, msg);
  msg.angle_increment(0.01);
  EXPECT_FALSE(rejectionReason(msg));
  msg.header().stamp().nanosec(1'000'000'000);
  EXPECT_EQ(rejectionReason(msg), "bad_stamp");
}

// Upside down (roll π) the sensor's counter-clockwise beams turn clockwise
// about the base: each beam lands where the same log with direction cw puts it.
TEST(UpsideDownMount, PlacesBeamsAsTheEquivalentClockwiseLog) {
  const LaserScanMsg in = driverScan();
  const LaserMount mount{.pose = {0.2, -0.1, 3.141592653589793}, .upside_down = true};
  Scan scan;
  SensorInfo sensor;
  fromLaserScan(in, mount, scan, sensor);
  scan.pose = {1.0, 2.0, 0.3};
  EXPECT_EQ(sensor.direction, BeamDirection::kCw);
  for (std::size_t i = 0; i < scan.size(); ++i) {
    // Base frame: yaw - a for a beam at sensor angle a under roll π.
    const double a = static_cast<double>(in.angle_min()) + static_cast<double>(i) * static_cast<double>(in.angle_increment());
    const double expected = scan.pose.theta + mount.pose.yaw - a;
    EXPECT_NEAR(std::remainder(beamWorldAngle(scan, sensor, i) - expected, 2 * M_PI), 0.0, 1e-12) << "beam " << i;
  }
  Scan upright;
  SensorInfo upright_sensor;
  fromLaserScan(in, {.pose = mount.pose}, upright, upright_sensor);
  EXPECT_EQ(upright_sensor.direction, BeamDirection::kCcw);
}

}  // namespace
}  // namespace scanfilter::dds_io
