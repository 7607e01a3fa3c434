#include "scanfilter/mines_log_reader.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "scanfilter/input_error.hpp"
#include "scanfilter/plausible_bounds.hpp"

namespace scanfilter {

namespace {

constexpr std::size_t kFieldCount = 707;
constexpr std::size_t kTimeField = 0;
constexpr std::size_t kLeftTicksField = 2;
constexpr std::size_t kRightTicksField = 3;
constexpr std::size_t kFirstRangeField = 24;
constexpr std::int64_t kNanosPerMicro = 1000;
// Stamps in µs beyond this do not fit a Stamp's nanoseconds (about ±292 years).
constexpr long long kMaxMicroseconds = std::numeric_limits<std::int64_t>::max() / kNanosPerMicro;
constexpr double kMillimetres = 1e-3;
constexpr double kDeg = std::numbers::pi / 180.0;

bool isInteger(const std::string& s) {
  long long v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return ec == std::errc() && end == s.data() + s.size();
}

}  // namespace

bool MinesLogReader::looksLikeMinesLine(const std::string& line) {
  const auto tokens = splitFields(line);
  return tokens.size() == kFieldCount && isInteger(tokens[kTimeField]);
}

MinesLogReader::MinesLogReader(const std::string& path, const MinesRobotModel& model, bool warn_stamps)
    : lines_(path), stamp_order_(path, "timestamp_us", warn_stamps), model_(model) {
  header_.source = kSourcePrefix + path;
  header_.sensor.direction = BeamDirection::kCcw;
  header_.sensor.mount.x = model.laser_offset;
  header_.sensor.range_min = model.no_return_below;
  header_.sensor.range_max = model.range_max;
  // As for CARMEN logs, Δθ of eq. (5) defaults to the beam step.
  header_.sensor.angular_accuracy_deg = model.field_of_view_deg / (model.beams - 1);
}

long long MinesLogReader::integerField(const std::vector<std::string>& tokens, std::size_t index,
                                       const char* field) const {
  long long value = 0;
  const std::string& t = tokens[index];
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
  if (ec != std::errc() || end != t.data() + t.size())
    throw InputError(lines_.path(), lines_.lineNumber(), field,
                     "'" + t + "' (field " + std::to_string(index) + ") is not an integer");
  return value;
}

void MinesLogReader::integrateOdometry(long long left_ticks, long long right_ticks) {
  if (have_ticks_) {
    const double metres_per_tick = 2.0 * std::numbers::pi * model_.wheel_radius / model_.ticks_per_revolution;
    // In double: the difference of two arbitrary 64-bit counters can overflow.
    const double left = (static_cast<double>(left_ticks) - static_cast<double>(left_ticks_)) * metres_per_tick;
    const double right = (static_cast<double>(right_ticks) - static_cast<double>(right_ticks_)) * metres_per_tick;
    const double forward = 0.5 * (left + right);
    const double turn = (right - left) / (2.0 * model_.half_axle);
    pose_.x += forward * std::cos(pose_.theta + 0.5 * turn);
    pose_.y += forward * std::sin(pose_.theta + 0.5 * turn);
    pose_.theta += turn;
  }
  have_ticks_ = true;
  left_ticks_ = left_ticks;
  right_ticks_ = right_ticks;
}

bool MinesLogReader::next(ScanRecord& record) {
  std::string line;
  std::vector<std::string> tokens;
  do {
    if (!lines_.next(line)) return false;
    tokens = splitFields(line);
  } while (tokens.empty());
  if (tokens.size() != kFieldCount)
    throw InputError(lines_.path(), lines_.lineNumber(), "fields",
                     std::to_string(tokens.size()) + " values; a Mines URG-04LX line has " + std::to_string(kFieldCount));
  Scan& scan = record.scan;
  scan = Scan{};
  record.original = nullptr;
  record.line = lines_.lineNumber();
  const long long micros = integerField(tokens, kTimeField, "timestamp_us");
  if (micros > kMaxMicroseconds || micros < -kMaxMicroseconds)
    throw InputError(lines_.path(), lines_.lineNumber(), "timestamp_us",
                     "'" + tokens[kTimeField] + "' is out of range for a stamp (|µs| <= " +
                         std::to_string(kMaxMicroseconds) + ")");
  scan.stamp = Stamp::fromNanoseconds(micros * kNanosPerMicro);
  stamp_order_.check(scan.stamp, record.line);
  integrateOdometry(integerField(tokens, kLeftTicksField, "left_ticks"),
                    integerField(tokens, kRightTicksField, "right_ticks"));
  if (!isPlausibleCoordinate(pose_.x) || !isPlausibleCoordinate(pose_.y))
    throw InputError(lines_.path(), lines_.lineNumber(), "left_ticks/right_ticks",
                     "dead-reckoned pose more than " + std::to_string(static_cast<long>(kMaxPlausibleCoordinate)) +
                         " m from the start; corrupt tick counts");
  scan.pose = pose_;
  scan.angle_min = model_.angle_min_deg * kDeg;
  scan.angle_increment = model_.field_of_view_deg / (model_.beams - 1) * kDeg;
  scan.ranges.resize(static_cast<std::size_t>(model_.beams));
  scan.recorded_ranges.resize(scan.ranges.size());
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    const double r = static_cast<double>(integerField(tokens, kFirstRangeField + i, "range_mm")) * kMillimetres;
    scan.recorded_ranges[i] = r;
    scan.ranges[i] = r < model_.no_return_below || r > model_.range_max ? std::numeric_limits<double>::quiet_NaN() : r;
  }
  return true;
}

}  // namespace scanfilter
