#pragma once
#include <optional>
#include <string>

namespace scanfilter::dds_io {

// ROS 2 topic names on the wire: "rt/" + optional namespace + name, so
// /robot1/scan in ROS 2 is rt/robot1/scan here.
inline std::string rosTopic(const std::string& ns, const std::string& name) {
  return ns.empty() ? "rt/" + name : "rt/" + ns + "/" + name;
}

// What is wrong with a topic namespace as a ROS name (spaces, '#', a leading
// or trailing '/'), for the config key and the --namespace option alike.
inline std::optional<std::string> topicNamespaceProblem(const std::string& ns) {
  const bool bad = ns.find_first_of(" \t#") != std::string::npos ||
                   (!ns.empty() && (ns.front() == '/' || ns.back() == '/'));
  if (!bad) return std::nullopt;
  return "expected a ROS name without spaces or leading/trailing '/', got \"" + ns + "\"";
}

// The pipeline's topics.
inline constexpr const char* kPosedScanTopic = "posed_scan";          // ingest -> jump filter
inline constexpr const char* kJumpFilteredTopic = "jump_filtered_scan";  // jump -> penetration filter
inline constexpr const char* kLabeledScanTopic = "labeled_scan";      // penetration filter -> users
inline constexpr const char* kFilteredLaserScanTopic = "scan_filtered";  // REP 117 LaserScan for ROS tools

}  // namespace scanfilter::dds_io
