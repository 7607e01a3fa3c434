#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "scanfilter/scan.hpp"
#include "scanfilter/sensor_info.hpp"
#include "scanfilter_types.h"

namespace scanfilter::dds_io {

using LabeledScanMsg = scanfilter_msgs::msg::dds_::LabeledScan_;
using LaserScanMsg = sensor_msgs::msg::dds_::LaserScan_;
using OdometryMsg = nav_msgs::msg::dds_::Odometry_;
using TimeMsg = builtin_interfaces::msg::dds_::Time_;

// Upper bound on beams accepted from the wire; larger samples are rejected.
inline constexpr std::size_t kMaxBeamsOnWire = 1u << 16;

TimeMsg toTimeMsg(double seconds);
double toSeconds(const TimeMsg& t);
// Wall-clock now, for the stage timing trail.
TimeMsg wallClockNow();

// A scan with its sensor as a LabeledScan (labels copied when present).
void toMessage(const Scan& scan, const SensorInfo& sensor, std::uint64_t sequence, LabeledScanMsg& out);

// Why a sample from the wire cannot be filtered, as a metric label
// ("length_mismatch", "nan_pose", "zero_increment", "too_many_beams",
// "empty", "bad_label"), or nothing when it is fine.
std::optional<std::string> rejectionReason(const LabeledScanMsg& msg);

// The scan and sensor in a (valid) LabeledScan; ranges outside the sensor's
// limits become NaN exactly as the scan log reader makes them.
void fromMessage(const LabeledScanMsg& msg, Scan& scan, SensorInfo& sensor);

// REP 117 LaserScan of a labelled scan: removed beams (jump, misdetected) are
// +inf, no-return beams keep their value; angles counter-clockwise in the
// sensor frame as ROS expects.
void toFilteredLaserScan(const LabeledScanMsg& msg, const std::string& frame_id, LaserScanMsg& out);

// A ROS LaserScan as a Scan (counter-clockwise angles; NaN, ±inf and values
// outside the message's range limits are no return) and the sensor it
// implies, given where the sensor sits on the robot.
void fromLaserScan(const LaserScanMsg& msg, const SensorMount& mount, Scan& scan, SensorInfo& sensor);
// Heading of a ROS quaternion about z.
double yawOf(const geometry_msgs::msg::dds_::Quaternion_& q);
// A ROS quaternion for a heading about z.
geometry_msgs::msg::dds_::Quaternion_ quaternionOfYaw(double yaw);

// Appends this stage's received/sent times to the sample's timing trail.
void stampStage(LabeledScanMsg& msg, const std::string& stage, const TimeMsg& received);

}  // namespace scanfilter::dds_io
