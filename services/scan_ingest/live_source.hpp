#pragma once
#include <atomic>
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
  using Clock = std::chrono::steady_clock;
  // Whether publish() has been blocked longer than a scan may wait for its
  // odometry: the ingest holds (its reader downstream gone). mutex_ held.
  bool holding(Clock::time_point now) const {
    return publishing_ && now - publishing_since_ > std::chrono::duration<double>(settings_.max_pose_wait_s);
  }
  // Whether a scan arrived before a hold ended, or during one; a scan the
  // odometry never covered, or whose odometry went back in time, did not.
  bool waitedThroughHold(const Pending& pending, Clock::time_point now) const {
    return holding(now) || pending.arrived <= last_hold_end_;
  }
  void dropHeld();  // the oldest pending scan, which outlived its odometry; mutex_ held

  LiveSettings settings_;
  double odometry_keep_s_;  // odometry is kept this many seconds of its stamps back
  dds_io::ServiceMetrics& metrics_;
  std::mutex mutex_;
  PoseBuffer poses_;
  std::deque<Pending> pending_;
  bool publishing_ = false;             // drain() is in publish(), which may hold
  Clock::time_point publishing_since_;  // when that publish() began
  Clock::time_point last_hold_end_;     // when the last publish() that held returned
  std::size_t dropped_ = 0;
  std::atomic<std::size_t> dropped_held_{0};  // counted on a Fast DDS thread, read on the main one
  dds_io::TypedReader<nav_msgs::msg::dds_::Odometry_PubSubType> odom_reader_;
  dds_io::TypedReader<sensor_msgs::msg::dds_::LaserScan_PubSubType> scan_reader_;
};

template <typename Publish>
void LiveSource::drain(Publish&& publish) {
  std::unique_lock lock(mutex_);
  auto now = Clock::now();
  while (!pending_.empty()) {
    Pending& next = pending_.front();
    if (const auto pose = poses_.at(next.scan.stamp)) {
      next.scan.pose = *pose;
      Pending ready = std::move(next);
      pending_.pop_front();
      publishing_ = true;
      publishing_since_ = now;
      lock.unlock();
      publish(ready.scan, ready.sensor, ready.source);
      lock.lock();
      publishing_ = false;
      now = Clock::now();
      if (now - publishing_since_ > std::chrono::duration<double>(settings_.max_pose_wait_s)) last_hold_end_ = now;
      continue;
    }
    const bool may_come = poses_.mayStillPose(next.scan.stamp) &&
                          now - next.arrived < std::chrono::duration<double>(settings_.max_pose_wait_s);
    if (may_come) break;  // odometry for this stamp may still arrive
    if (poses_.forgot(next.scan.stamp) && waitedThroughHold(next, now)) {
      dropHeld();
      continue;
    }
    pending_.pop_front();
    ++dropped_;
    metrics_.sampleRejected("no_pose");
  }
}

}  // namespace scanfilter::ingest
