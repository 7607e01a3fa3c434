#pragma once
// A well-formed LabeledScan for the DDS test tools that write into the
// pipeline (bad_sample_sender, scan_injector): a full turn of kRoomScanBeams
// beams, every one a return at 2 m, stamped `stamp` and as sent by `stage`.
#include <cstdint>
#include <numbers>

#include "scanfilter/dds/scan_message.hpp"

namespace scanfilter::dds_io::test {

inline constexpr int kRoomScanBeams = 360;

inline LabeledScanMsg roomScanMessage(std::uint64_t sequence, Stamp stamp, const char* stage) {
  Scan scan;
  scan.stamp = stamp;
  scan.angle_increment = 2.0 * std::numbers::pi / kRoomScanBeams;
  scan.ranges.assign(kRoomScanBeams, 2.0);
  SensorInfo sensor;
  sensor.range_min = 0.15;
  sensor.range_max = 6.0;
  LabeledScanMsg msg;
  toMessage(scan, sensor, sequence, msg);
  stampStage(msg, stage, wallClockNow());
  return msg;
}

}  // namespace scanfilter::dds_io::test
