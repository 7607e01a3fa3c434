#include "live_source.hpp"

#include "scanfilter/dds/stream_qos.hpp"
#include "scanfilter/dds/topic_names.hpp"

namespace scanfilter::ingest {

namespace {
// Odometry is kept this many pose gaps back: enough to pose late scans.
constexpr double kOdometryKeepFactor = 20.0;

eprosima::fastdds::dds::DataReaderQos readerQos(const LiveSettings& settings) {
  auto qos = dds_io::sensorDataReaderQos(settings.queue_depth);
  if (settings.reliable) qos.reliability().kind = eprosima::fastdds::dds::RELIABLE_RELIABILITY_QOS;
  return qos;
}
}  // namespace

LiveSource::LiveSource(dds_io::DdsParticipant& participant, const std::string& ns, const LiveSettings& settings,
                       dds_io::ServiceMetrics& metrics)
    : settings_(settings),
      odometry_keep_s_(settings.max_pose_gap_s * kOdometryKeepFactor + settings.max_pose_wait_s),
      metrics_(metrics),
      poses_(settings.max_pose_gap_s, odometry_keep_s_),
      odom_reader_(participant, dds_io::rosTopic(ns, settings.odom_topic), readerQos(settings),
                   [this](dds_io::OdometryMsg& msg) { onOdometry(msg); }),
      scan_reader_(participant, dds_io::rosTopic(ns, settings.scan_topic), readerQos(settings),
                   [this](dds_io::LaserScanMsg& msg) { onScan(msg); }) {}

void LiveSource::onOdometry(dds_io::OdometryMsg& msg) {
  if (const auto reason = dds_io::odometryRejectionReason(msg)) {
    metrics_.sampleRejected(*reason);
    return;
  }
  const auto& p = msg.pose().pose();
  std::lock_guard lock(mutex_);
  poses_.add(dds_io::toStamp(msg.header().stamp()), {p.position().x(), p.position().y(), dds_io::yawOf(p.orientation())});
}

void LiveSource::onScan(dds_io::LaserScanMsg& msg) {
  metrics_.scanReceived();
  if (const auto reason = dds_io::laserScanRejectionReason(msg)) {
    metrics_.sampleRejected(*reason);
    return;
  }
  Pending pending;
  dds_io::fromLaserScan(msg, settings_.mount, pending.scan, pending.sensor);
  pending.source = dds_io::sourceScanOf(msg);
  pending.arrived = Clock::now();
  std::lock_guard lock(mutex_);
  // While the ingest holds (its reader downstream gone) nothing drains the
  // queue: what can no longer be posed goes now (and, should the odometry
  // stop too, what waited longer than odometry is kept), so an outage of
  // hours does not fill the memory with scans.
  const auto too_long = std::chrono::duration<double>(odometry_keep_s_);
  while (!pending_.empty() && holding(pending.arrived) &&
         (poses_.forgot(pending_.front().scan.stamp) || pending.arrived - pending_.front().arrived > too_long))
    dropHeld();
  pending_.push_back(std::move(pending));
}

void LiveSource::dropHeld() {
  pending_.pop_front();
  ++dropped_held_;
  metrics_.sampleRejected("held_too_long");
}

}  // namespace scanfilter::ingest
