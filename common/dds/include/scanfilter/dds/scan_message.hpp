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
using SourceScanMsg = scanfilter_msgs::msg::dds_::SourceScan_;

// What rt/scan_filtered puts in place of a removed beam: NaN (REP 117: an
// erroneous measurement) or +inf ("no return within range"; a costmap would
// clear free space through it, so only for consumers that need it).
enum class RemovedBeamValue { kNaN, kInfinity };

// Upper bound on beams accepted from the wire; larger samples are rejected.
inline constexpr std::size_t kMaxBeamsOnWire = 1u << 16;

// A stamp and ROS time, both ways, exact to the nanosecond.
TimeMsg toTimeMsg(Stamp stamp);
Stamp toStamp(const TimeMsg& t);
// A ROS time with nanosec >= 1e9 is malformed: it names no stamp.
bool isValidTime(const TimeMsg& t);
// Wall-clock times as seconds, for latency arithmetic only (never a scan stamp).
double toSeconds(const TimeMsg& t);
// Wall-clock now, for the stage timing trail.
TimeMsg wallClockNow();

// A LaserScan's angles and range limits for a scan recorded from angle_min
// in steps of angle_increment over `beams` beams; `sign` -1 turns clockwise
// angles into ROS's counter-clockwise ones. Times 0: a log has none.
void setLaserScanGeometry(double angle_min, double angle_increment, std::size_t beams, double sign,
                          double range_min, double range_max, LaserScanMsg& out);

// A scan with its sensor as a LabeledScan (ranges as recorded, labels copied
// when present, no source LaserScan).
void toMessage(const Scan& scan, const SensorInfo& sensor, std::uint64_t sequence, LabeledScanMsg& out);

// Why a sample from the wire cannot be filtered, as a metric label
// ("length_mismatch", "nan_pose", "implausible_pose" (beyond
// kMaxPlausibleCoordinate), "zero_increment", "implausible_angles" (beyond
// kMaxPlausibleAngle or kMaxPlausibleAngleStep), "too_many_beams", "empty",
// "bad_sensor" (range limits or Δθ), "bad_label", "bad_stamp"), or nothing
// when it is fine.
std::optional<std::string> rejectionReason(const LabeledScanMsg& msg);
// The same for a driver's LaserScan ("empty", "too_many_beams",
// "length_mismatch", "zero_increment", "implausible_angles", "bad_sensor", "bad_stamp") and
// Odometry ("nan_pose", "implausible_pose", "bad_stamp"): scan_ingest's live source checks every
// sample with these before it converts it.
std::optional<std::string> laserScanRejectionReason(const LaserScanMsg& msg);
std::optional<std::string> odometryRejectionReason(const OdometryMsg& msg);

// The scan and sensor in a (valid) LabeledScan; ranges outside the sensor's
// limits become NaN exactly as the scan log reader makes them (the recorded
// values are kept in recorded_ranges).
void fromMessage(const LabeledScanMsg& msg, Scan& scan, SensorInfo& sensor);

// REP 117 LaserScan of a labelled scan: removed beams (jump, misdetected)
// become `removed`, every other beam leaves bit-identical to how it came (no
// returns and out-of-limit readings included). A scan that came as a
// LaserScan keeps its stamp, frame_id, angles, times and limits exactly; one
// from a log gets `frame_id` and counter-clockwise angles.
void toFilteredLaserScan(const LabeledScanMsg& msg, const std::string& frame_id, RemovedBeamValue removed,
                         LaserScanMsg& out);

// How the sensor sits on the robot: its pose on the base and whether it is
// mounted upside down (roll π: its counter-clockwise beams turn clockwise
// about the base's z axis).
struct LaserMount {
  SensorMount pose;
  bool upside_down = false;
};

// A ROS LaserScan as a Scan (NaN, ±inf and values outside the message's
// range limits are no return; the values as they came in recorded_ranges)
// and the sensor it implies, given how the sensor sits on the robot.
void fromLaserScan(const LaserScanMsg& msg, const LaserMount& mount, Scan& scan, SensorInfo& sensor);
// The LaserScan's fields rt/scan_filtered must give back unchanged.
SourceScanMsg sourceScanOf(const LaserScanMsg& msg);
// Heading of a ROS quaternion about z.
double yawOf(const geometry_msgs::msg::dds_::Quaternion_& q);
// A ROS quaternion for a heading about z.
geometry_msgs::msg::dds_::Quaternion_ quaternionOfYaw(double yaw);

// Appends this stage's received/sent times to the sample's timing trail.
void stampStage(LabeledScanMsg& msg, const std::string& stage, const TimeMsg& received);

}  // namespace scanfilter::dds_io
