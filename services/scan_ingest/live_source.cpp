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
      metrics_(metrics),
      poses_(settings.max_pose_gap_s, settings.max_pose_gap_s * kOdometryKeepFactor + settings.max_pose_wait_s),
      odom_reader_(participant, dds_io::rosTopic(ns, settings.odom_topic), readerQos(settings),
                   [this](dds_io::OdometryMsg& msg) { onOdometry(msg); }),
      scan_reader_(participant, dds_io::rosTopic(ns, settings.scan_topic), readerQos(settings),
                   [this](dds_io::LaserScanMsg& msg) { onScan(msg); }) {}

void LiveSource::onOdometry(dds_io::OdometryMsg& msg) {
  const auto& p = msg.pose().pose();
  if (!std::isfinite(p.position().x()) || !std::isfinite(p.position().y())) {
    metrics_.sampleRejected("nan_pose");
    return;
  }
  std::lock_guard lock(mutex_);
  if (!dds_io::isValidTime(msg.header().stamp())) {
    metrics_.sampleRejected("bad_stamp");
    return;
  }
  poses_.add(dds_io::toStamp(msg.header().stamp()), {p.position().x(), p.position().y(), dds_io::yawOf(p.orientation())});
}

void LiveSource::onScan(dds_io::LaserScanMsg& msg) {
  metrics_.scanReceived();
  const std::size_t n = msg.ranges().size();
  if (n == 0 || n > dds_io::kMaxBeamsOnWire) {
    metrics_.sampleRejected(n == 0 ? "empty" : "too_many_beams");
    return;
  }
  if (!msg.intensities().empty() && msg.intensities().size() != n) {
    metrics_.sampleRejected("length_mismatch");
    return;
  }
  if (!(msg.angle_increment() != 0.0f) || !std::isfinite(msg.angle_increment())) {
    metrics_.sampleRejected("zero_increment");
    return;
  }
  if (!dds_io::isValidTime(msg.header().stamp())) {
    metrics_.sampleRejected("bad_stamp");
    return;
  }
  Pending pending;
  dds_io::fromLaserScan(msg, settings_.mount, pending.scan, pending.sensor);
  pending.source = dds_io::sourceScanOf(msg);
  pending.arrived = std::chrono::steady_clock::now();
  std::lock_guard lock(mutex_);
  pending_.push_back(std::move(pending));
}

}  // namespace scanfilter::ingest
