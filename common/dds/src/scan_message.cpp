#include "scanfilter/dds/scan_message.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>

#include "scanfilter/plausible_bounds.hpp"
#include "scanfilter/point_code.hpp"

namespace scanfilter::dds_io {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kNanosPerSecond = 1e9;
// Δθ the filter config accepts (config/filter.yaml): the obstacle threshold
// is scaled by it, and a Δθ of 1e-300 would scale it beyond an int.
constexpr double kMinAngularAccuracyDeg = 1e-6;
constexpr double kMaxAngularAccuracyDeg = 90.0;

// "No return" exactly as the scan log reader decides it: NaN, ±inf, 0 and
// values outside the sensor's limits.
double returnOrNaN(double r, const SensorInfo& sensor) {
  return (std::isfinite(r) && r != 0.0 && r >= sensor.range_min && r <= sensor.range_max) ? r : kNaN;
}
}  // namespace

TimeMsg toTimeMsg(Stamp stamp) {
  TimeMsg t;
  t.sec(static_cast<int32_t>(stamp.sec()));
  t.nanosec(stamp.nanosec());
  return t;
}

Stamp toStamp(const TimeMsg& t) { return Stamp::fromSecNanosec(t.sec(), t.nanosec()); }

bool isValidTime(const TimeMsg& t) { return t.nanosec() < static_cast<std::uint32_t>(Stamp::kNanosPerSecond); }

double toSeconds(const TimeMsg& t) { return t.sec() + t.nanosec() / kNanosPerSecond; }

TimeMsg wallClockNow() {
  const auto now = std::chrono::system_clock::now().time_since_epoch();
  return toTimeMsg(Stamp::fromNanoseconds(std::chrono::duration_cast<std::chrono::nanoseconds>(now).count()));
}

void setLaserScanGeometry(double angle_min, double angle_increment, std::size_t beams, double sign,
                          double range_min, double range_max, LaserScanMsg& out) {
  out.angle_min(static_cast<float>(sign * angle_min));
  out.angle_increment(static_cast<float>(sign * angle_increment));
  out.angle_max(static_cast<float>(sign * (angle_min + angle_increment * static_cast<double>(beams - 1))));
  out.time_increment(0.0f);
  out.scan_time(0.0f);
  out.range_min(static_cast<float>(range_min));
  out.range_max(static_cast<float>(range_max));
}

void toMessage(const Scan& scan, const SensorInfo& sensor, std::uint64_t sequence, LabeledScanMsg& out) {
  out.header().stamp(toTimeMsg(scan.stamp));
  out.header().frame_id("map");
  out.sequence_number(sequence);
  out.pose_x(scan.pose.x);
  out.pose_y(scan.pose.y);
  out.pose_theta(scan.pose.theta);
  out.mount_x(sensor.mount.x);
  out.mount_y(sensor.mount.y);
  out.mount_yaw(sensor.mount.yaw);
  out.clockwise(sensor.direction == BeamDirection::kCw);
  out.angular_accuracy_deg(sensor.angular_accuracy_deg);
  out.angle_min(scan.angle_min);
  out.angle_increment(scan.angle_increment);
  out.range_min(sensor.range_min);
  out.range_max(sensor.range_max);
  const auto recorded = scan.rangesAsRecorded();
  out.ranges().assign(recorded.begin(), recorded.end());
  out.intensities().assign(scan.intensities.begin(), scan.intensities.end());
  out.labels().assign(scan.labels.begin(), scan.labels.end());
  out.timing().clear();
  out.source_scan(SourceScanMsg{});
}

std::optional<std::string> rejectionReason(const LabeledScanMsg& msg) {
  const std::size_t n = msg.ranges().size();
  if (n == 0) return "empty";
  if (n > kMaxBeamsOnWire) return "too_many_beams";
  if (!isValidTime(msg.header().stamp())) return "bad_stamp";
  if (!msg.intensities().empty() && msg.intensities().size() != n) return "length_mismatch";
  if (!msg.labels().empty() && msg.labels().size() != n) return "length_mismatch";
  if (!std::isfinite(msg.pose_x()) || !std::isfinite(msg.pose_y()) || !std::isfinite(msg.pose_theta()) ||
      !std::isfinite(msg.mount_x()) || !std::isfinite(msg.mount_y()) || !std::isfinite(msg.mount_yaw()))
    return "nan_pose";
  if (!isPlausibleCoordinate(msg.pose_x()) || !isPlausibleCoordinate(msg.pose_y()) ||
      !isPlausibleCoordinate(msg.mount_x()) || !isPlausibleCoordinate(msg.mount_y()))
    return "implausible_pose";
  if (!(msg.angle_increment() != 0.0) || !std::isfinite(msg.angle_increment()) || !std::isfinite(msg.angle_min()))
    return "zero_increment";
  if (!isPlausibleBeamGeometry(msg.angle_min(), msg.angle_increment())) return "implausible_angles";
  if (!(msg.range_max() > msg.range_min()) || !(msg.angular_accuracy_deg() >= kMinAngularAccuracyDeg) ||
      !(msg.range_min() >= 0.0) ||
      !(msg.range_max() <= kMaxPlausibleRange) || !(msg.angular_accuracy_deg() <= kMaxAngularAccuracyDeg))
    return "bad_sensor";
  for (auto code : msg.labels())
    if (!isValidPointCode(code)) return "bad_label";
  return std::nullopt;
}

std::optional<std::string> laserScanRejectionReason(const LaserScanMsg& msg) {
  const std::size_t n = msg.ranges().size();
  if (n == 0) return "empty";
  if (n > kMaxBeamsOnWire) return "too_many_beams";
  if (!msg.intensities().empty() && msg.intensities().size() != n) return "length_mismatch";
  if (!(msg.angle_increment() != 0.0f) || !std::isfinite(msg.angle_increment()) || !std::isfinite(msg.angle_min()))
    return "zero_increment";
  if (!isPlausibleBeamGeometry(msg.angle_min(), msg.angle_increment())) return "implausible_angles";
  // The filter's d_min/d_max come from these: they must name a range.
  if (!(msg.range_min() >= 0.0f) || !(msg.range_max() > msg.range_min()) || !(msg.range_max() <= kMaxPlausibleRange))
    return "bad_sensor";
  if (!isValidTime(msg.header().stamp())) return "bad_stamp";
  return std::nullopt;
}

std::optional<std::string> odometryRejectionReason(const OdometryMsg& msg) {
  const auto& p = msg.pose().pose();
  const auto& q = p.orientation();
  if (!std::isfinite(p.position().x()) || !std::isfinite(p.position().y()) || !std::isfinite(yawOf(q)))
    return "nan_pose";
  if (!isPlausibleCoordinate(p.position().x()) || !isPlausibleCoordinate(p.position().y())) return "implausible_pose";
  if (!isValidTime(msg.header().stamp())) return "bad_stamp";
  return std::nullopt;
}

void fromMessage(const LabeledScanMsg& msg, Scan& scan, SensorInfo& sensor) {
  sensor.mount = {msg.mount_x(), msg.mount_y(), msg.mount_yaw()};
  sensor.direction = msg.clockwise() ? BeamDirection::kCw : BeamDirection::kCcw;
  sensor.range_min = msg.range_min();
  sensor.range_max = msg.range_max();
  sensor.angular_accuracy_deg = msg.angular_accuracy_deg();
  scan.stamp = toStamp(msg.header().stamp());
  scan.pose = {msg.pose_x(), msg.pose_y(), msg.pose_theta()};
  scan.angle_min = msg.angle_min();
  scan.angle_increment = msg.angle_increment();
  scan.recorded_ranges.assign(msg.ranges().begin(), msg.ranges().end());
  scan.ranges.resize(msg.ranges().size());
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) scan.ranges[i] = returnOrNaN(msg.ranges()[i], sensor);
  scan.intensities.assign(msg.intensities().begin(), msg.intensities().end());
  scan.labels.assign(msg.labels().begin(), msg.labels().end());
  scan.truth.clear();
  scan.thin_leg_beams.clear();
  scan.truth_cause.clear();
}

namespace {

// The frame, angles, times and limits of the LaserScan the scan came in.
void copySourceFields(const SourceScanMsg& source, LaserScanMsg& out) {
  out.header().frame_id(source.frame_id());
  out.angle_min(source.angle_min());
  out.angle_max(source.angle_max());
  out.angle_increment(source.angle_increment());
  out.time_increment(source.time_increment());
  out.scan_time(source.scan_time());
  out.range_min(source.range_min());
  out.range_max(source.range_max());
}

// A log's scan has no LaserScan of its own: ROS angles grow counter-clockwise,
// so a clockwise sensor's beam at angle a is at -a.
void deriveLogFields(const LabeledScanMsg& msg, const std::string& frame_id, LaserScanMsg& out) {
  out.header().frame_id(frame_id);
  setLaserScanGeometry(msg.angle_min(), msg.angle_increment(), msg.ranges().size(), msg.clockwise() ? -1.0 : 1.0,
                       msg.range_min(), msg.range_max(), out);
}

}  // namespace

void toFilteredLaserScan(const LabeledScanMsg& msg, const std::string& frame_id, RemovedBeamValue removed,
                         LaserScanMsg& out) {
  const std::size_t n = msg.ranges().size();
  out.header().stamp(msg.header().stamp());
  if (msg.source_scan().present()) copySourceFields(msg.source_scan(), out);
  else deriveLogFields(msg, frame_id, out);
  const float removed_value = removed == RemovedBeamValue::kNaN ? std::numeric_limits<float>::quiet_NaN()
                                                                : std::numeric_limits<float>::infinity();
  out.ranges().resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto code = msg.labels().empty() ? PointCode::kValid : static_cast<PointCode>(msg.labels()[i]);
    const bool is_removed = code == PointCode::kJump || code == PointCode::kMisdetected;
    // A float that came in as a LaserScan range went to double exactly and
    // comes back exactly.
    out.ranges()[i] = is_removed ? removed_value : static_cast<float>(msg.ranges()[i]);
  }
  out.intensities().assign(msg.intensities().begin(), msg.intensities().end());
}

SourceScanMsg sourceScanOf(const LaserScanMsg& msg) {
  SourceScanMsg source;
  source.present(true);
  source.frame_id(msg.header().frame_id());
  source.angle_min(msg.angle_min());
  source.angle_max(msg.angle_max());
  source.angle_increment(msg.angle_increment());
  source.time_increment(msg.time_increment());
  source.scan_time(msg.scan_time());
  source.range_min(msg.range_min());
  source.range_max(msg.range_max());
  return source;
}

void fromLaserScan(const LaserScanMsg& msg, const LaserMount& mount, Scan& scan, SensorInfo& sensor) {
  sensor.mount = mount.pose;
  // Upside down, the sensor's counter-clockwise sweep is clockwise about the
  // base's z axis: the angles stay as the sensor gives them.
  sensor.direction = mount.upside_down ? BeamDirection::kCw : BeamDirection::kCcw;
  sensor.range_min = msg.range_min();
  sensor.range_max = msg.range_max();
  sensor.angular_accuracy_deg = std::abs(msg.angle_increment()) * 180.0 / std::numbers::pi;
  scan.stamp = toStamp(msg.header().stamp());
  scan.angle_min = msg.angle_min();
  scan.angle_increment = msg.angle_increment();
  scan.recorded_ranges.assign(msg.ranges().begin(), msg.ranges().end());
  scan.ranges.resize(msg.ranges().size());
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) scan.ranges[i] = returnOrNaN(msg.ranges()[i], sensor);
  scan.intensities.assign(msg.intensities().begin(), msg.intensities().end());
  if (scan.intensities.size() != scan.ranges.size()) scan.intensities.clear();
  scan.labels.clear();
  scan.truth.clear();
  scan.thin_leg_beams.clear();
  scan.truth_cause.clear();
}

double yawOf(const geometry_msgs::msg::dds_::Quaternion_& q) {
  return std::atan2(2.0 * (q.w() * q.z() + q.x() * q.y()), 1.0 - 2.0 * (q.y() * q.y() + q.z() * q.z()));
}

geometry_msgs::msg::dds_::Quaternion_ quaternionOfYaw(double yaw) {
  geometry_msgs::msg::dds_::Quaternion_ q;
  q.x(0.0);
  q.y(0.0);
  q.z(std::sin(yaw / 2.0));
  q.w(std::cos(yaw / 2.0));
  return q;
}

void stampStage(LabeledScanMsg& msg, const std::string& stage, const TimeMsg& received) {
  scanfilter_msgs::msg::dds_::StageTiming_ timing;
  timing.stage(stage);
  timing.received(received);
  timing.sent(wallClockNow());
  msg.timing().push_back(timing);
}

}  // namespace scanfilter::dds_io
