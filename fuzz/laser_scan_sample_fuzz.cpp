// A driver's LaserScan as scan_ingest's live source receives it (rt/<ns>/scan):
// raw CDR bytes, validated and converted, posed, published, and through the
// rest of the pipeline. Odd frames are read upside down (both mounts exist).
#include "sample_pipeline.hpp"
#include "scanfilter_typesPubSubTypes.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace scanfilter;
  fuzz::ServiceChain chain;
  dds_io::LaserScanMsg laser;
  dds_io::LabeledScanMsg msg;
  std::uint64_t sequence = 0;
  for (const auto frame : fuzz::splitFrames(data, size)) {
    if (!fuzz::deserialize<sensor_msgs::msg::dds_::LaserScan_PubSubType>(frame, laser)) continue;
    if (dds_io::laserScanRejectionReason(laser)) continue;
    dds_io::LaserMount mount;
    mount.pose = {0.1, 0.0, 0.0};
    mount.upside_down = sequence % 2 == 1;
    Scan scan;
    SensorInfo sensor;
    dds_io::fromLaserScan(laser, mount, scan, sensor);
    scan.pose = {0.05 * static_cast<double>(sequence), 0.0, 0.0};  // as PoseBuffer would give it
    const dds_io::TimeMsg received = dds_io::wallClockNow();
    dds_io::toMessage(scan, sensor, sequence++, msg);
    msg.source_scan(dds_io::sourceScanOf(laser));
    dds_io::stampStage(msg, "scan_ingest", received);
    fuzz::serialize<scanfilter_msgs::msg::dds_::LabeledScan_PubSubType>(msg);
    chain.onPosedScan(msg);
  }
  return 0;
}
