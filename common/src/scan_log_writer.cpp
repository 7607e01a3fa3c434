#include "scanfilter/scan_log_writer.hpp"

#include <cmath>

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

Json scanToJson(const Scan& scan) {
  Json out;
  out["stamp"] = scan.stamp;
  out["pose"] = {scan.pose.x, scan.pose.y, scan.pose.theta};
  out["angle_min"] = scan.angle_min;
  out["angle_increment"] = scan.angle_increment;
  Json ranges = Json::array();
  for (double r : scan.ranges) {
    if (std::isnan(r)) ranges.push_back(nullptr);
    else ranges.push_back(r);
  }
  out["ranges"] = std::move(ranges);
  if (!scan.intensities.empty()) out["intensities"] = scan.intensities;
  if (!scan.truth.empty()) out["truth"] = scan.truth;
  if (!scan.thin_leg_beams.empty()) out["truth_thin_leg"] = scan.thin_leg_beams;
  if (!scan.labels.empty()) out["labels"] = scan.labels;
  return out;
}

ScanLogWriter::ScanLogWriter(const std::string& path, const ScanLogHeader& header)
    : path_(path), out_(path) {
  if (!out_) throw InputError(path, 0, "", "cannot open for writing");
  out_ << headerToJson(header).dump() << '\n';
}

void ScanLogWriter::write(const ScanRecord& record) {
  if (record.original.is_object()) {
    Json line = record.original;
    if (!record.scan.labels.empty()) line["labels"] = record.scan.labels;
    out_ << line.dump() << '\n';
  } else {
    out_ << scanToJson(record.scan).dump() << '\n';
  }
  if (!out_) throw InputError(path_, 0, "", "write failed (disk full?)");
}

void ScanLogWriter::close() {
  out_.close();
  if (out_.fail()) throw InputError(path_, 0, "", "close failed");
}

}  // namespace scanfilter
