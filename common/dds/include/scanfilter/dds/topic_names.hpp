#pragma once
#include <string>

namespace scanfilter::dds_io {

// ROS 2 topic names on the wire: "rt/" + optional namespace + name, so
// /robot1/scan in ROS 2 is rt/robot1/scan here.
inline std::string rosTopic(const std::string& ns, const std::string& name) {
  return ns.empty() ? "rt/" + name : "rt/" + ns + "/" + name;
}

// The pipeline's topics.
inline constexpr const char* kPosedScanTopic = "posed_scan";          // ingest -> jump filter
inline constexpr const char* kJumpFilteredTopic = "jump_filtered_scan";  // jump -> penetration filter
inline constexpr const char* kLabeledScanTopic = "labeled_scan";      // penetration filter -> users
inline constexpr const char* kFilteredLaserScanTopic = "scan_filtered";  // REP 117 LaserScan for ROS tools

}  // namespace scanfilter::dds_io
