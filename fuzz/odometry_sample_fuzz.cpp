// A driver's Odometry as scan_ingest's live source receives it (rt/<ns>/odom):
// raw CDR bytes, validated, into the pose buffer, and a scan posed at every
// stamp seen and between them.
#include "sample_pipeline.hpp"
#include "scanfilter/pose_buffer.hpp"
#include "scanfilter_typesPubSubTypes.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace scanfilter;
  // The live source's defaults (services/scan_ingest/live_source.hpp).
  constexpr double kMaxPoseGap = 0.2;
  constexpr double kKeepSeconds = 4.5;
  PoseBuffer poses(kMaxPoseGap, kKeepSeconds);
  dds_io::OdometryMsg odom;
  std::vector<Stamp> stamps;
  for (const auto frame : fuzz::splitFrames(data, size)) {
    if (!fuzz::deserialize<nav_msgs::msg::dds_::Odometry_PubSubType>(frame, odom)) continue;
    if (dds_io::odometryRejectionReason(odom)) continue;
    const auto& p = odom.pose().pose();
    const Stamp stamp = dds_io::toStamp(odom.header().stamp());
    poses.add(stamp, {p.position().x(), p.position().y(), dds_io::yawOf(p.orientation())});
    stamps.push_back(stamp);
  }
  for (std::size_t i = 0; i < stamps.size(); ++i) {
    poses.at(stamps[i]);
    poses.mayStillPose(stamps[i]);
    if (i > 0) poses.at(Stamp::fromNanoseconds(stamps[i - 1].nanoseconds() / 2 + stamps[i].nanoseconds() / 2));
  }
  return 0;
}
