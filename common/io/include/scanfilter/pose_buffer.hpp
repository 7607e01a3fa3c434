#pragma once
#include <deque>
#include <optional>

#include "scanfilter/scan.hpp"

namespace scanfilter {

// Recent odometry poses by stamp, to pose a scan at its own stamp: the pose
// is interpolated between the two odometry samples around it (heading along
// the shorter arc). A scan with no sample within `max_gap` seconds on each
// side gets no pose: it is counted and dropped by the caller, never guessed.
class PoseBuffer {
 public:
  explicit PoseBuffer(double max_gap, double keep_seconds) : max_gap_(max_gap), keep_(keep_seconds) {}

  // Adds a sample; samples must come in stamp order (older ones are ignored,
  // but one older by more than keep_seconds starts the buffer over: the
  // odometry's clock went back).
  bool add(Stamp stamp, const Pose2& pose);

  // The pose at `stamp`, or nothing when the samples around it are missing
  // or farther than max_gap.
  std::optional<Pose2> at(Stamp stamp) const;

  // True when a later sample may still arrive that would pose `stamp`: none
  // has arrived yet, or the newest is older than it. (Odometry and scans come
  // on separate streams; the first scan often arrives before any odometry.)
  bool mayStillPose(Stamp stamp) const { return samples_.empty() || samples_.back().stamp < stamp; }

  // True when the samples that would pose `stamp` were there and have been
  // dropped as older than keep_seconds. After a long gap in the odometry
  // that is true too: the caller tells a scan that waited (it held) apart.
  bool forgot(Stamp stamp) const {
    return dropped_any_ && stamp >= first_stamp_ && !samples_.empty() && stamp < samples_.front().stamp;
  }

  std::size_t size() const { return samples_.size(); }

 private:
  struct Sample {
    Stamp stamp;
    Pose2 pose;
  };
  double max_gap_;
  double keep_;
  std::deque<Sample> samples_;
  Stamp first_stamp_;         // of the first sample ever added
  bool dropped_any_ = false;  // whether a sample was dropped for its age
};

}  // namespace scanfilter
