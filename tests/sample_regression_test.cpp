// Regression tests for what the sample fuzzers (fuzz/*_sample_fuzz) found in
// the services' handling of samples from the wire. The crashing inputs are
// also in fuzz/corpus/<target>/regression-*.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scanfilter/dds/checked_type_support.hpp"
#include "scanfilter/dds/scan_message.hpp"
#include "scanfilter/dds/service_config.hpp"
#include "scanfilter/input_error.hpp"
#include "scanfilter_typesPubSubTypes.h"

namespace scanfilter::dds_io {
namespace {

template <typename PubSubType>
bool deserializeBytes(PubSubType& type, const std::vector<unsigned char>& bytes, typename PubSubType::type& sample) {
  eprosima::fastrtps::rtps::SerializedPayload_t payload(static_cast<std::uint32_t>(bytes.size()));
  std::copy(bytes.begin(), bytes.end(), payload.data);
  payload.length = static_cast<std::uint32_t>(bytes.size());
  return type.deserialize(&payload, &sample);
}

// A sample whose encapsulation header starts with a non-zero byte: Fast CDR
// throws BadParamException, which fastddsgen's deserialize() lets escape; in
// a service it ended the reader's thread (std::terminate).
const std::vector<unsigned char> kBadEncapsulation = {0x58, 0x02, 0x00, 0x01, 0, 0, 0, 0, 0, 0, 0, 0, 4, 0, 0, 0};

TEST(SampleRegression, GeneratedTypeThrowsOnBadEncapsulation) {
  sensor_msgs::msg::dds_::LaserScan_PubSubType plain;
  LaserScanMsg msg;
  EXPECT_ANY_THROW(deserializeBytes(plain, kBadEncapsulation, msg));
}

TEST(SampleRegression, CheckedTypeDropsBadEncapsulation) {
  CheckedPubSubType<sensor_msgs::msg::dds_::LaserScan_PubSubType> laser;
  LaserScanMsg laser_msg;
  EXPECT_FALSE(deserializeBytes(laser, kBadEncapsulation, laser_msg));
  CheckedPubSubType<nav_msgs::msg::dds_::Odometry_PubSubType> odom;
  OdometryMsg odom_msg;
  EXPECT_FALSE(deserializeBytes(odom, kBadEncapsulation, odom_msg));
  CheckedPubSubType<scanfilter_msgs::msg::dds_::LabeledScan_PubSubType> labeled;
  LabeledScanMsg labeled_msg;
  EXPECT_FALSE(deserializeBytes(labeled, kBadEncapsulation, labeled_msg));
}

// The corpus files the fuzzers crashed on: every frame is dropped or read, none throws.
TEST(SampleRegression, CorpusCrashInputsDeserialiseWithoutThrowing) {
  for (const char* target : {"laser_scan_sample_fuzz", "odometry_sample_fuzz", "labeled_scan_sample_fuzz"}) {
    std::ifstream in(std::string(SCANFILTER_SOURCE_DIR) + "/fuzz/corpus/" + target + "/regression-bad-encapsulation",
                     std::ios::binary);
    ASSERT_TRUE(in.good()) << target;
    const std::vector<unsigned char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    // The frames as fuzz/sample_pipeline.cpp splits them.
    for (std::size_t at = 0; at + 2 <= bytes.size();) {
      const std::size_t length = bytes[at] | (static_cast<std::size_t>(bytes[at + 1]) << 8);
      at += 2;
      const std::vector<unsigned char> frame(bytes.begin() + static_cast<long>(at),
                                             bytes.begin() + static_cast<long>(std::min(at + length, bytes.size())));
      at += frame.size();
      CheckedPubSubType<sensor_msgs::msg::dds_::LaserScan_PubSubType> laser;
      CheckedPubSubType<nav_msgs::msg::dds_::Odometry_PubSubType> odom;
      CheckedPubSubType<scanfilter_msgs::msg::dds_::LabeledScan_PubSubType> labeled;
      LaserScanMsg a;
      OdometryMsg b;
      LabeledScanMsg c;
      EXPECT_NO_THROW(deserializeBytes(laser, frame, a)) << target;
      EXPECT_NO_THROW(deserializeBytes(odom, frame, b)) << target;
      EXPECT_NO_THROW(deserializeBytes(labeled, frame, c)) << target;
    }
  }
}

// A LaserScan's range limits become the filter's d_min/d_max: NaN or
// reversed limits are rejected before the scan is converted.
TEST(SampleRegression, LaserScanRangeLimitsChecked) {
  LaserScanMsg msg;
  msg.ranges({1.0f, 2.0f});
  msg.angle_increment(0.1f);
  msg.range_min(0.1f);
  msg.range_max(10.0f);
  EXPECT_FALSE(laserScanRejectionReason(msg).has_value());
  msg.range_max(std::numeric_limits<float>::quiet_NaN());
  EXPECT_EQ(laserScanRejectionReason(msg), "bad_sensor");
  msg.range_max(0.05f);
  EXPECT_EQ(laserScanRejectionReason(msg), "bad_sensor");
  msg.range_max(10.0f);
  msg.angle_min(std::numeric_limits<float>::infinity());
  EXPECT_EQ(laserScanRejectionReason(msg), "zero_increment");
}

// Two beams, 0.1-10 m, a sample every check accepts.
LabeledScanMsg acceptableLabeledScan() {
  LabeledScanMsg msg;
  msg.ranges({1.0, 2.0});
  msg.angle_increment(0.1);
  msg.range_min(0.1);
  msg.range_max(10.0);
  msg.angular_accuracy_deg(0.5);
  return msg;
}

// A pose of 9.3e181 m passed the checks and overflowed the int cell index
// of the penetration grid (UBSan float-cast-overflow); ranges up to a
// float's 3e38 m would too.
TEST(SampleRegression, ImplausiblePoseAndRangeLimitRejected) {
  LabeledScanMsg msg = acceptableLabeledScan();
  EXPECT_FALSE(rejectionReason(msg).has_value());
  msg.pose_x(9.33641e+181);
  EXPECT_EQ(rejectionReason(msg), "implausible_pose");
  msg.pose_x(0.0);
  msg.mount_y(-2e6);
  EXPECT_EQ(rejectionReason(msg), "implausible_pose");
  msg.mount_y(0.0);
  msg.range_max(1e30);
  EXPECT_EQ(rejectionReason(msg), "bad_sensor");
  msg.range_max(10.0);
  msg.angular_accuracy_deg(1e-300);
  EXPECT_EQ(rejectionReason(msg), "bad_sensor");
  msg.angular_accuracy_deg(1e300);
  EXPECT_EQ(rejectionReason(msg), "bad_sensor");
}

TEST(SampleRegression, ImplausibleBeamAnglesRejected) {
  // labeled_scan_sample_fuzz: a step of 1.2e307 rad made angle_min + i·step
  // infinite, the beam's direction NaN, and a NaN point reached the grid.
  LabeledScanMsg msg = acceptableLabeledScan();
  msg.angle_min(-1.5708);
  EXPECT_FALSE(rejectionReason(msg).has_value());
  msg.angle_increment(1.20162e+307);
  EXPECT_EQ(rejectionReason(msg), "implausible_angles");
  msg.angle_increment(0.1);
  msg.angle_min(1e300);
  EXPECT_EQ(rejectionReason(msg), "implausible_angles");
  LaserScanMsg laser;
  laser.ranges({1.0f, 2.0f});
  laser.angle_increment(0.01f);
  laser.range_min(0.1f);
  laser.range_max(10.0f);
  EXPECT_FALSE(laserScanRejectionReason(laser).has_value());
  laser.angle_increment(1e30f);
  EXPECT_EQ(laserScanRejectionReason(laser), "implausible_angles");
}

TEST(SampleRegression, OdometryChecked) {
  OdometryMsg msg;
  msg.pose().pose().orientation().w(1.0);
  EXPECT_FALSE(odometryRejectionReason(msg).has_value());
  msg.pose().pose().orientation().z(std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(odometryRejectionReason(msg), "nan_pose");
  msg.pose().pose().orientation().z(0.0);
  msg.header().stamp().nanosec(2'000'000'000u);
  EXPECT_EQ(odometryRejectionReason(msg), "bad_stamp");
}

// A profiles_file name longer than the file system allows made
// std::filesystem::exists throw filesystem_error out of loadServiceConfig
// (found by penetration_filter_config_fuzz); now it is a located InputError.
TEST(SampleRegression, ServiceConfigProfilesNameTooLong) {
  const std::string path = ::testing::TempDir() + "/name-too-long-" + std::to_string(::getpid()) + ".yaml";
  std::ofstream(path) << "service:\n  profiles_file: '" << std::string(5000, 'a') << "'\n";
  try {
    loadServiceConfig(path, "127.0.0.1:9470", {});
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    // Said as what the file system answered, not as "no such file".
    const std::string what = e.what();
    EXPECT_NE(what.find(":2: service.profiles_file: cannot look at /"), std::string::npos) << what;
    EXPECT_NE(what.find(": File name too long"), std::string::npos) << what;
  }
  std::remove(path.c_str());
}

}  // namespace
}  // namespace scanfilter::dds_io
