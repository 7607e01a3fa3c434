#include "scanfilter/scan_log_writer.hpp"

#include <cmath>
#include <filesystem>

#include "scanfilter/input_error.hpp"

namespace scanfilter {

using Json = nlohmann::ordered_json;

Json headerToJson(const ScanLogHeader& header) {
  const SensorInfo& s = header.sensor;
  Json sensor;
  sensor["mount"] = {s.mount.x, s.mount.y, s.mount.yaw};
  sensor["direction"] = s.direction == BeamDirection::kCcw ? "ccw" : "cw";
  sensor["range_min"] = s.range_min;
  sensor["range_max"] = s.range_max;
  sensor["angular_accuracy_deg"] = s.angular_accuracy_deg;
  Json out;
  out["scanlog"] = header.version;
  out["source"] = header.source;
  out["sensor"] = sensor;
  return out;
}

namespace {

// A range as the format writes it: null for NaN, the strings "inf" / "-inf"
// for infinities (JSON has no such numbers), the number otherwise.
Json rangeToJson(double r) {
  if (std::isnan(r)) return nullptr;
  if (std::isinf(r)) return r > 0 ? "inf" : "-inf";
  return r;
}

// Every key but the stamp.
Json scanToJson(const Scan& scan) {
  Json out;
  out["pose"] = {scan.pose.x, scan.pose.y, scan.pose.theta};
  out["angle_min"] = scan.angle_min;
  out["angle_increment"] = scan.angle_increment;
  Json ranges = Json::array();
  for (double r : scan.rangesAsRecorded()) ranges.push_back(rangeToJson(r));
  out["ranges"] = std::move(ranges);
  if (!scan.intensities.empty()) out["intensities"] = scan.intensities;
  if (!scan.truth.empty()) out["truth"] = scan.truth;
  if (!scan.thin_leg_beams.empty()) out["truth_thin_leg"] = scan.thin_leg_beams;
  if (!scan.truth_cause.empty()) out["truth_cause"] = scan.truth_cause;
  if (!scan.labels.empty()) out["labels"] = scan.labels;
  return out;
}

}  // namespace

std::string scanLine(const ScanRecord& record) {
  Json object = record.original.is_object() ? record.original : scanToJson(record.scan);
  if (!record.scan.labels.empty()) object["labels"] = record.scan.labels;
  object.erase("stamp");
  const std::string rest = object.dump();  // "{...}"
  const std::string stamp = "{\"stamp\":" + record.scan.stamp.toDecimal();
  return rest.size() > 2 ? stamp + "," + rest.substr(1) : stamp + "}";
}

ScanLogWriter::ScanLogWriter(const std::string& path, const ScanLogHeader& header)
    : path_(path), partial_path_(path + ".partial"), out_(partial_path_) {
  if (!out_) throw InputError(path, 0, "", "cannot open for writing");
  out_ << headerToJson(header).dump() << '\n';
}

ScanLogWriter::~ScanLogWriter() {
  if (closed_) return;
  out_.close();
  std::error_code ignored;  // nothing to report from a destructor: the error that got here is
  std::filesystem::remove(partial_path_, ignored);
}

void ScanLogWriter::write(const ScanRecord& record) {
  out_ << scanLine(record) << '\n';
  if (!out_) throw InputError(path_, 0, "", "write failed (disk full?)");
}

void ScanLogWriter::close() {
  out_.close();
  if (out_.fail()) throw InputError(path_, 0, "", "close failed");
  std::error_code error;
  std::filesystem::rename(partial_path_, path_, error);
  if (error) throw InputError(path_, 0, "", "cannot rename " + partial_path_ + " into place: " + error.message());
  closed_ = true;
}

}  // namespace scanfilter
