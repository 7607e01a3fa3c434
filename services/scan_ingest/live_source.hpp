#pragma once
#include <chrono>
#include <deque>
#include <mutex>
#include <string>

#include "scanfilter/dds/dds_participant.hpp"
#include "scanfilter/dds/scan_message.hpp"
#include "scanfilter/dds/service_metrics.hpp"
#include "scanfilter/dds/typed_reader.hpp"
#include "scanfilter/pose_buffer.hpp"
#include "scanfilter_typesPubSubTypes.h"

namespace scanfilter::ingest {

struct LiveSettings {
  std::string scan_topic = "scan";  // under rt/<ns>/
  std::string odom_topic = "odom";
  dds_io::LaserMount mount;          // the laser's pose on the robot base, upright or upside down
  double max_pose_gap_s = 0.2;       // odometry samples farther than this from the scan stamp: no pose
  double max_pose_wait_s = 0.5;      // how long a scan waits for the odometry after its stamp
  int queue_depth = 50;
  bool reliable = false;             // best effort matches every driver; reliable only reliable ones
};

// A live robot: LaserScan on rt/<ns>/scan and Odometry on rt/<ns>/odom from
// the robot's driver (best effort, as ROS 2 sensor drivers publish). Each
// scan gets the pose interpolated at its stamp; scans whose pose cannot be
// had in time are counted ("no_pose") and dropped, never guessed. Scans that
// waited longer than the odometry is kept (the ingest held while its reader
// downstream was gone) are counted apart ("held_too_long"): their odometry
// was there, and pointing the operator at it would send them the wrong way.
class LiveSource {
 public:
  LiveSource(dds_io::DdsParticipant& participant, const std::string& ns, const LiveSettings& settings,
             dds_io::ServiceMetrics& metrics);

  // Moves every scan that can be posed (or must be dropped) out of the
  // queue; calls publish(scan, sensor, source) for the posed ones, in stamp
  // order (source: the LaserScan fields rt/scan_filtered gives back).
  template <typename Publish>
  void drain(Publish&& publish);

  std::size_t dropped() const { return dropped_; }
  std::size_t droppedHeld() const { return dropped_held_; }
  // The driver's writers matched on rt/<ns>/scan and rt/<ns>/odom.
  int scanWriters() const { return scan_reader_.matchedWriters(); }
  int odometryWriters() const { return odom_reader_.matchedWriters(); }

 private:
  struct Pending {
    Scan scan;
    SensorInfo sensor;
    dds_io::SourceScanMsg source;
    std::chrono::steady_clock::time_point arrived;
  };
  void onScan(dds_io::LaserScanMsg& msg);
  void onOdometry(dds_io::OdometryMsg& msg);
  void dropHeld();  // the oldest pending scan, which outlived its odometry; mutex_ held

  LiveSettings settings_;
  dds_io::ServiceMetrics& metrics_;
  std::mutex mutex_;
  PoseBuffer poses_;
  std::deque<Pending> pending_;
  std::size_t dropped_ = 0;
  std::size_t dropped_held_ = 0;
  dds_io::TypedReader<nav_msgs::msg::dds_::Odometry_PubSubType> odom_reader_;
  dds_io::TypedReader<sensor_msgs::msg::dds_::LaserScan_PubSubType> scan_reader_;
};

template <typename Publish>
void LiveSource::drain(Publish&& publish) {
  std::unique_lock lock(mutex_);
  const auto now = std::chrono::steady_clock::now();
  while (!pending_.empty()) {
    Pending& next = pending_.front();
    if (const auto pose = poses_.at(next.scan.stamp)) {
      next.scan.pose = *pose;
      Pending ready = std::move(next);
      pending_.pop_front();
      lock.unlock();
      publish(ready.scan, ready.sensor, ready.source);
      lock.lock();
      continue;
    }
    const bool may_come = poses_.mayStillPose(next.scan.stamp) &&
                          now - next.arrived < std::chrono::duration<double>(settings_.max_pose_wait_s);
    if (may_come) break;  // odometry for this stamp may still arrive
    if (poses_.forgot(next.scan.stamp)) {
      dropHeld();
      continue;
    }
    pending_.pop_front();
    ++dropped_;
    metrics_.sampleRejected("no_pose");
  }
}

}  // namespace scanfilter::ingest
