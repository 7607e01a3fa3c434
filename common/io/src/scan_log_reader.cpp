#include "scanfilter/scan_log_reader.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <string_view>

#include "scanfilter/artefact_cause.hpp"
#include "scanfilter/input_error.hpp"
#include "scanfilter/plausible_bounds.hpp"
#include "scanfilter/point_code.hpp"

namespace scanfilter {

namespace {

using Json = nlohmann::ordered_json;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Validates fields of one JSON line and reports problems with file and line.
class FieldChecker {
 public:
  FieldChecker(const std::string& file, std::size_t line) : file_(file), line_(line) {}

  [[noreturn]] void fail(const std::string& field, const std::string& problem) const {
    throw InputError(file_, line_, field, problem);
  }

  const Json& require(const Json& object, const char* key) const {
    const auto it = object.find(key);
    if (it == object.end()) fail(key, "missing");
    return *it;
  }

  double finiteNumber(const Json& value, const std::string& field) const {
    if (!value.is_number()) fail(field, "expected a number, got " + describe(value));
    const double x = value.get<double>();
    if (!std::isfinite(x)) fail(field, "expected a finite number, got " + describe(value));
    return x;
  }

  std::array<double, 3> triple(const Json& value, const std::string& field) const {
    if (!value.is_array() || value.size() != 3)
      fail(field, "expected an array of 3 numbers [x, y, theta], got " + describe(value));
    return {finiteNumber(value[0], field + "[0]"), finiteNumber(value[1], field + "[1]"),
            finiteNumber(value[2], field + "[2]")};
  }

  static std::string describe(const Json& value) {
    std::string text = value.dump();
    constexpr std::size_t kMaxShown = 60;
    if (text.size() > kMaxShown) text = text.substr(0, kMaxShown) + "...";
    return text;
  }

 private:
  const std::string& file_;
  std::size_t line_;
};

// nlohmann says "[json.exception.parse_error.101] parse error at line 1,
// column 1067: syntax error ...": its line is the text given, one line of
// the file. Said as the column, and a line that ends inside its object as
// what it most often is.
std::string parseProblem(const nlohmann::json::parse_error& e, const std::string& text) {
  const std::string what = e.what();
  const auto detail = what.find(": ");
  std::string problem = "malformed JSON at column " + std::to_string(e.byte) + ": " +
                        (detail == std::string::npos ? what : what.substr(detail + 2));
  if (e.byte > text.size()) problem += " (the line ends inside its object: a file cut short?)";
  return problem;
}

Json parseLine(const std::string& text, const std::string& file, std::size_t line) {
  try {
    Json object = Json::parse(text);
    if (!object.is_object()) throw InputError(file, line, "", "expected a JSON object");
    return object;
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(file, line, "", parseProblem(e, text));
  } catch (const nlohmann::json::exception& e) {
    // out_of_range.406: a number beyond a double (1e400), found by scan_log_reader_fuzz.
    throw InputError(file, line, "", std::string("unreadable JSON: ") + e.what());
  }
}

// The value a range string names: "NaN"/"nan", "inf"/"Infinity" (+inf,
// REP 117's "no return within range") or "-inf"; nothing for other strings.
std::optional<double> namedRange(const Json& value) {
  if (!value.is_string()) return std::nullopt;
  const auto& s = value.get_ref<const std::string&>();
  if (s == "NaN" || s == "nan") return kNaN;
  if (s == "inf" || s == "Infinity") return std::numeric_limits<double>::infinity();
  if (s == "-inf") return -std::numeric_limits<double>::infinity();
  return std::nullopt;
}

// The text of the number under a top-level key of a JSON object that has
// already parsed: JSON numbers reach us as doubles, and a stamp must not.
std::string_view topLevelNumberText(std::string_view json, std::string_view key) {
  int depth = 0;
  for (std::size_t i = 0; i < json.size(); ++i) {
    const char c = json[i];
    if (c == '{' || c == '[') ++depth;
    else if (c == '}' || c == ']') --depth;
    if (c != '"') continue;
    const std::size_t start = ++i;
    while (i < json.size() && json[i] != '"') i += json[i] == '\\' ? 2 : 1;
    const std::string_view text = json.substr(start, i - start);
    std::size_t colon = json.find_first_not_of(" \t\r", i + 1);
    if (depth != 1 || text != key || colon == std::string_view::npos || json[colon] != ':') continue;
    const std::size_t begin = json.find_first_not_of(" \t\r", colon + 1);
    const std::size_t end = json.find_first_not_of("+-0123456789.eE", begin);
    return json.substr(begin, end == std::string_view::npos ? std::string_view::npos : end - begin);
  }
  return {};
}

// The codes a per-beam array may hold: 0 to count - 1.
struct CodeKind {
  int count;
  const char* one;   // for the errors: "expected <one> 0-<count - 1>"
  const char* many;  // "expected an array of <many>"
};
constexpr CodeKind kPointCodes{kPointCodeCount, "a point code", "point codes"};
constexpr CodeKind kArtefactCauseCodes{kArtefactCauseCount, "an artefact cause", "artefact causes"};

std::vector<std::uint8_t> parseCodes(const Json& array, const char* key, std::size_t expected, CodeKind kind,
                                     const FieldChecker& check) {
  if (!array.is_array()) check.fail(key, std::string("expected an array of ") + kind.many);
  if (array.size() != expected)
    check.fail(key, "has " + std::to_string(array.size()) + " entries, ranges has " +
                        std::to_string(expected) + "; expected equal lengths");
  std::vector<std::uint8_t> codes(expected);
  for (std::size_t i = 0; i < expected; ++i) {
    const Json& v = array[i];
    // As int64: a huge code read as int would wrap to a valid one.
    if (!v.is_number_integer() || v.get<std::int64_t>() < 0 || v.get<std::int64_t>() >= kind.count)
      check.fail(std::string(key) + "[" + std::to_string(i) + "]",
                 std::string("expected ") + kind.one + " 0-" + std::to_string(kind.count - 1) + ", got " +
                     FieldChecker::describe(v));
    codes[i] = static_cast<std::uint8_t>(v.get<int>());
  }
  return codes;
}

}  // namespace

ScanLogReader::ScanLogReader(const std::string& path, bool warn_stamps)
    : lines_(path), stamp_order_(path, "stamp", warn_stamps) {
  parseHeader();
}

void ScanLogReader::parseHeader() {
  std::string text;
  if (!lines_.next(text)) throw InputError(lines_.path(), 1, "", "empty file: expected a header line");
  const FieldChecker check(lines_.path(), lines_.lineNumber());
  const Json object = parseLine(text, lines_.path(), lines_.lineNumber());
  const Json& version = check.require(object, "scanlog");
  if (!version.is_number_integer() || version.get<std::int64_t>() != 1)
    check.fail("scanlog", "unsupported version " + FieldChecker::describe(version) + "; expected 1");
  header_.version = 1;
  if (const auto it = object.find("source"); it != object.end() && it->is_string())
    header_.source = it->get<std::string>();

  const Json& sensor = check.require(object, "sensor");
  if (!sensor.is_object()) check.fail("sensor", "expected an object");
  const auto mount = check.triple(check.require(sensor, "mount"), "sensor.mount");
  if (!isPlausibleCoordinate(mount[0]) || !isPlausibleCoordinate(mount[1]))
    check.fail("sensor.mount", "is more than " + std::to_string(static_cast<long>(kMaxPlausibleCoordinate)) +
                                   " m from the robot; corrupt data");
  header_.sensor.mount = {mount[0], mount[1], mount[2]};
  const Json& direction = check.require(sensor, "direction");
  if (direction == "ccw") {
    header_.sensor.direction = BeamDirection::kCcw;
  } else if (direction == "cw") {
    header_.sensor.direction = BeamDirection::kCw;
  } else {
    check.fail("sensor.direction", "expected \"ccw\" or \"cw\", got " + FieldChecker::describe(direction));
  }
  SensorInfo& s = header_.sensor;
  s.range_min = check.finiteNumber(check.require(sensor, "range_min"), "sensor.range_min");
  s.range_max = check.finiteNumber(check.require(sensor, "range_max"), "sensor.range_max");
  if (s.range_min < 0.0)
    check.fail("sensor.range_min", "is negative (" + FieldChecker::describe(sensor["range_min"]) + "); expected >= 0");
  if (s.range_max > kImplausibleRange)
    check.fail("sensor.range_max", "is beyond any indoor sensor; expected <= " +
                                       std::to_string(static_cast<int>(kImplausibleRange)) + " m");
  if (!(s.range_max > s.range_min))
    check.fail("sensor.range_max", "must exceed range_min (" + std::to_string(s.range_min) + ")");
  s.angular_accuracy_deg =
      check.finiteNumber(check.require(sensor, "angular_accuracy_deg"), "sensor.angular_accuracy_deg");
  // The filter config's bounds on Δθ (config/filter.yaml): the obstacle
  // threshold is scaled by it, and 1e-300 would overflow that count.
  if (!(s.angular_accuracy_deg >= 1e-6 && s.angular_accuracy_deg <= 90.0))
    check.fail("sensor.angular_accuracy_deg",
               "expected 1e-6 <= value <= 90 (degrees), got " + FieldChecker::describe(sensor["angular_accuracy_deg"]));
}

bool ScanLogReader::next(ScanRecord& record) {
  std::string text;
  do {
    if (!lines_.next(text)) return false;
  } while (text.find_first_not_of(" \t") == std::string::npos);  // blank lines carry nothing
  record.line = lines_.lineNumber();
  record.original = parseLine(text, lines_.path(), record.line);
  parseScan(record.original, topLevelNumberText(text, "stamp"), record.scan);
  return true;
}

void ScanLogReader::parseScan(const Json& object, std::string_view stamp_text, Scan& scan) {
  const FieldChecker check(lines_.path(), lines_.lineNumber());
  scan = Scan{};
  check.finiteNumber(check.require(object, "stamp"), "stamp");
  const auto stamp = Stamp::parseDecimal(stamp_text);
  if (!stamp) check.fail("stamp", "\"" + std::string(stamp_text) + "\" is out of range for a stamp in nanoseconds");
  scan.stamp = *stamp;
  stamp_order_.check(scan.stamp, lines_.lineNumber());
  const auto pose = check.triple(check.require(object, "pose"), "pose");
  if (!isPlausibleCoordinate(pose[0]) || !isPlausibleCoordinate(pose[1]))
    check.fail("pose", "is more than " + std::to_string(static_cast<long>(kMaxPlausibleCoordinate)) +
                           " m from the origin; corrupt data");
  scan.pose = {pose[0], pose[1], pose[2]};
  scan.angle_min = check.finiteNumber(check.require(object, "angle_min"), "angle_min");
  scan.angle_increment = check.finiteNumber(check.require(object, "angle_increment"), "angle_increment");
  if (scan.angle_increment == 0.0) check.fail("angle_increment", "is 0; expected a non-zero step");
  if (!isPlausibleBeamGeometry(scan.angle_min, scan.angle_increment))
    check.fail("angle_increment", "or angle_min is beyond a believable scan (|angle_min| <= 4π, |step| <= π/2 rad)");

  const Json& ranges = check.require(object, "ranges");
  if (!ranges.is_array()) check.fail("ranges", "expected an array");
  if (ranges.empty()) check.fail("ranges", "is empty; a scan needs at least one beam");
  if (ranges.size() > kMaxBeams)
    check.fail("ranges", "has " + std::to_string(ranges.size()) + " beams; at most " +
                             std::to_string(kMaxBeams) + " are accepted");
  const std::size_t n = ranges.size();
  const SensorInfo& sensor = header_.sensor;
  scan.ranges.resize(n);
  scan.recorded_ranges.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Json& v = ranges[i];
    const std::string field = "ranges[" + std::to_string(i) + "]";
    const auto named = v.is_null() ? std::optional<double>(kNaN) : namedRange(v);
    if (named) {
      scan.ranges[i] = kNaN;
      scan.recorded_ranges[i] = *named;
      continue;
    }
    if (!v.is_number()) check.fail(field, "expected a number or null, got " + FieldChecker::describe(v));
    const double r = v.get<double>();
    if (r < 0.0) check.fail(field, "is negative (" + FieldChecker::describe(v) + "); expected >= 0 or null");
    if (r > kImplausibleRange)
      check.fail(field, FieldChecker::describe(v) + " m is beyond any indoor sensor; expected <= " +
                            std::to_string(static_cast<int>(kImplausibleRange)) + " m or null");
    // 0 and values outside the sensor's limits are "no return" by the format.
    scan.ranges[i] = (r == 0.0 || r < sensor.range_min || r > sensor.range_max) ? kNaN : r;
    scan.recorded_ranges[i] = r;
  }

  if (const auto it = object.find("intensities"); it != object.end() && !it->is_null()) {
    if (!it->is_array() || it->size() != n)
      check.fail("intensities", "has " + std::to_string(it->is_array() ? it->size() : 0) +
                                    " entries, ranges has " + std::to_string(n) + "; expected equal lengths");
    scan.intensities.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      scan.intensities[i] = (*it)[i].is_null() ? 0.0
                                               : check.finiteNumber((*it)[i], "intensities[" + std::to_string(i) + "]");
  }
  if (const auto it = object.find("truth"); it != object.end())
    scan.truth = parseCodes(*it, "truth", n, kPointCodes, check);
  if (const auto it = object.find("labels"); it != object.end())
    scan.labels = parseCodes(*it, "labels", n, kPointCodes, check);
  if (const auto it = object.find("truth_cause"); it != object.end())
    scan.truth_cause = parseCodes(*it, "truth_cause", n, kArtefactCauseCodes, check);
  if (const auto it = object.find("truth_thin_leg"); it != object.end()) {
    if (!it->is_array()) check.fail("truth_thin_leg", "expected an array of beam indices");
    for (std::size_t k = 0; k < it->size(); ++k) {
      const Json& v = (*it)[k];
      if (!v.is_number_unsigned() || v.get<std::size_t>() >= n)
        check.fail("truth_thin_leg[" + std::to_string(k) + "]",
                   "expected a beam index below " + std::to_string(n) + ", got " + FieldChecker::describe(v));
      scan.thin_leg_beams.push_back(v.get<std::uint32_t>());
    }
  }
}

}  // namespace scanfilter
