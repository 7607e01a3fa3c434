#include "scanfilter/carmen_log_reader.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include <spdlog/spdlog.h>

#include "scanfilter/input_error.hpp"
#include "scanfilter/plausible_bounds.hpp"

namespace scanfilter {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kFlaserFieldOfView = std::numbers::pi;  // 180°
// Fields after the ranges of a FLASER line: x y theta odom_x odom_y odom_theta
// ipc_timestamp ipc_hostname logger_timestamp.
constexpr std::size_t kFlaserTrailingFields = 9;
// Fields after ranges (and remissions) of ROBOTLASER1: laser pose 3, robot pose 3,
// tv rv forward_safety_dist side_safety_dist, ipc_timestamp ipc_hostname logger_timestamp.
constexpr std::size_t kRobotLaserTrailingFields = 13;
constexpr std::size_t kRobotLaserHeadFields = 9;  // name .. num_readings
constexpr double kMinResolution = 1e-8;                   // rad
constexpr double kMaxResolution = std::numbers::pi / 2;  // rad: 90 degrees

// A count read from a line: a whole number from 0 up to the fields the line
// has (a larger one cannot be right, and converting it could overflow).
bool isCountWithin(double value, std::size_t fields) {
  return value >= 0.0 && value == std::floor(value) && value <= static_cast<double>(fields);
}

bool isScanLine(const std::string& line) {
  return line.rfind("FLASER ", 0) == 0 || line.rfind("ROBOTLASER1 ", 0) == 0;
}

}  // namespace

CarmenLogReader::CarmenLogReader(const std::string& path, const ScanSourceOptions& options)
    : lines_(path), stamp_order_(path, "ipc_timestamp", options.warn_stamps) {
  header_.source = "CARMEN log " + path;
  header_.sensor.direction = BeamDirection::kCcw;
  header_.sensor.range_max = options.carmen_range_max;
  // PARAM lines precede the first scan; read up to it to fill the header.
  std::string line;
  while (lines_.next(line)) {
    if (isScanLine(line)) {
      pending_ = line;
      pending_line_ = lines_.lineNumber();
      break;
    }
    const auto tokens = splitFields(line);
    if (tokens.size() < 3 || tokens[0] != "PARAM") continue;
    current_line_ = lines_.lineNumber();
    if (tokens[1] == "robot_frontlaser_offset")
      header_.sensor.mount.x = number(tokens, 2, "robot_frontlaser_offset");
    if (tokens[1] == "robot_front_laser_max")
      header_.sensor.range_max = number(tokens, 2, "robot_front_laser_max");
  }
  // A file that is no log at all ends up here (openScanSource reads whatever
  // is neither a scan log nor a Mines log as CARMEN): name all three.
  if (!pending_)
    throw InputError(path, 0, "",
                     "no FLASER or ROBOTLASER1 line: not a CARMEN laser log (nor a scan log, whose first line is a "
                     "JSON object, nor a Mines URG-04LX log, 707 numbers a line)");
  // The angular accuracy defaults to the beam step of the first scan.
  current_line_ = pending_line_;
  Scan first;
  const auto tokens = splitFields(*pending_);
  if (tokens[0] == "FLASER") parseFlaser(tokens, first);
  else parseRobotLaser(tokens, first);
  header_.sensor.angular_accuracy_deg = std::abs(first.angle_increment) * 180.0 / std::numbers::pi;
}

void CarmenLogReader::fail(const std::string& field, const std::string& problem) const {
  throw InputError(lines_.path(), current_line_, field, problem);
}

double CarmenLogReader::number(const std::vector<std::string>& tokens, std::size_t index,
                               const char* field) const {
  if (index >= tokens.size())
    fail(field, "missing: line has " + std::to_string(tokens.size()) + " fields");
  const std::string& t = tokens[index];
  double value = 0.0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
  if (ec != std::errc() || end != t.data() + t.size() || !std::isfinite(value))
    fail(std::string(field) + " (field " + std::to_string(index + 1) + ")",
         "expected a finite number, got \"" + t + "\"");
  return value;
}

Stamp CarmenLogReader::stamp(const std::vector<std::string>& tokens, std::size_t index) const {
  // The decimal text itself, not a double: the stamp must survive to the nanosecond.
  number(tokens, index, "ipc_timestamp");  // same checks and message as every other number
  const auto stamp = Stamp::parseDecimal(tokens[index]);
  if (!stamp) fail("ipc_timestamp (field " + std::to_string(index + 1) + ")", "out of range: \"" + tokens[index] + "\"");
  return *stamp;
}

void CarmenLogReader::setRanges(const std::vector<std::string>& tokens, std::size_t first,
                                std::size_t count, Scan& scan) const {
  scan.ranges.resize(count);
  scan.recorded_ranges.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const double r = number(tokens, first + i, "range");
    if (r < 0.0) fail("range " + std::to_string(i), "is negative (" + tokens[first + i] + ")");
    const bool no_return = r < header_.sensor.range_min || r >= header_.sensor.range_max || r == 0.0;
    scan.ranges[i] = no_return ? kNaN : r;
    // CARMEN writes its maximum for "no return within range": REP 117's +inf.
    scan.recorded_ranges[i] = r >= header_.sensor.range_max ? std::numeric_limits<double>::infinity() : r;
  }
}

void CarmenLogReader::checkPlausiblePose(const Pose2& pose) const {
  if (!isPlausibleCoordinate(pose.x) || !isPlausibleCoordinate(pose.y))
    fail("x/y", "pose more than " + std::to_string(static_cast<long>(kMaxPlausibleCoordinate)) +
                    " m from the origin; corrupt data");
}

void CarmenLogReader::parseFlaser(const std::vector<std::string>& tokens, Scan& scan) const {
  const double n_value = number(tokens, 1, "num_readings");
  if (n_value < 1.0 || !isCountWithin(n_value, tokens.size()))
    fail("num_readings", "expected a positive integer up to the line's field count, got \"" + tokens[1] + "\"");
  const auto n = static_cast<std::size_t>(n_value);
  if (tokens.size() != 2 + n + kFlaserTrailingFields)
    fail("FLASER", "has " + std::to_string(tokens.size()) + " fields; " + std::to_string(n) +
                       " readings need " + std::to_string(2 + n + kFlaserTrailingFields));
  setRanges(tokens, 2, n, scan);
  const std::size_t pose = 2 + n;
  scan.pose = {number(tokens, pose, "x"), number(tokens, pose + 1, "y"), number(tokens, pose + 2, "theta")};
  checkPlausiblePose(scan.pose);
  scan.stamp = stamp(tokens, pose + 6);
  const double steps = n % 2 == 1 && n > 1 ? static_cast<double>(n - 1) : static_cast<double>(n);
  scan.angle_min = -kFlaserFieldOfView / 2.0;
  scan.angle_increment = kFlaserFieldOfView / steps;
}

void CarmenLogReader::parseRobotLaser(const std::vector<std::string>& tokens, Scan& scan) const {
  const double start_angle = number(tokens, 2, "start_angle");
  const double resolution = number(tokens, 4, "angular_resolution");
  // Δθ defaults to this step; the filter accepts 0 < Δθ <= 90 degrees.
  if (!(std::abs(resolution) >= kMinResolution && std::abs(resolution) <= kMaxResolution))
    fail("angular_resolution", "expected a step of 1e-8 to pi/2 rad, got \"" + tokens[4] + "\"");
  const double n_value = number(tokens, 8, "num_readings");
  if (n_value < 1.0 || !isCountWithin(n_value, tokens.size()))
    fail("num_readings", "expected a positive integer up to the line's field count, got \"" + tokens[8] + "\"");
  const auto n = static_cast<std::size_t>(n_value);
  std::size_t after = kRobotLaserHeadFields + n;
  if (tokens.size() < after + kRobotLaserTrailingFields)
    fail("ROBOTLASER1", "has " + std::to_string(tokens.size()) + " fields; too few for " +
                            std::to_string(n) + " readings");
  setRanges(tokens, kRobotLaserHeadFields, n, scan);
  // Some CARMEN versions insert num_remissions [remissions] after the ranges.
  if (tokens.size() > after + kRobotLaserTrailingFields) {
    const double remissions_value = number(tokens, after, "num_remissions");
    if (!isCountWithin(remissions_value, tokens.size()))
      fail("num_remissions", "expected an integer >= 0 up to the line's field count, got \"" + tokens[after] + "\"");
    const auto remissions = static_cast<std::size_t>(remissions_value);
    after += 1 + remissions;
    if (tokens.size() != after + kRobotLaserTrailingFields)
      fail("ROBOTLASER1", "field count does not match num_readings and num_remissions");
  }
  // The laser pose is given directly, so it is the pose and the mount is zero.
  scan.pose = {number(tokens, after, "laser_pose_x"), number(tokens, after + 1, "laser_pose_y"),
               number(tokens, after + 2, "laser_pose_theta")};
  checkPlausiblePose(scan.pose);
  scan.stamp = stamp(tokens, after + 10);
  scan.angle_min = start_angle;
  scan.angle_increment = resolution;
}

bool CarmenLogReader::readScanLine(std::string& line) {
  if (pending_) {
    line = std::move(*pending_);
    pending_.reset();
    current_line_ = pending_line_;
    return true;
  }
  while (lines_.next(line)) {
    if (isScanLine(line)) {
      current_line_ = lines_.lineNumber();
      return true;
    }
  }
  return false;
}

bool CarmenLogReader::next(ScanRecord& record) {
  std::string line;
  if (!readScanLine(line)) return false;
  record = ScanRecord{};
  record.line = current_line_;
  const auto tokens = splitFields(line);
  if (tokens[0] == "FLASER") parseFlaser(tokens, record.scan);
  else parseRobotLaser(tokens, record.scan);
  stamp_order_.check(record.scan.stamp, current_line_);
  return true;
}

}  // namespace scanfilter
