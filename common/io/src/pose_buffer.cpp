#include "scanfilter/pose_buffer.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace scanfilter {

bool PoseBuffer::add(Stamp stamp, const Pose2& pose) {
  // A clock that went back further than what is kept (a driver restarted on
  // simulated time, a recording looped) starts over: refusing its samples
  // until it passed the old newest stamp would leave every scan unposed.
  if (!samples_.empty() && samples_.back().stamp.secondsSince(stamp) > keep_) {
    samples_.clear();
    dropped_any_ = false;
  }
  if (!samples_.empty() && stamp <= samples_.back().stamp) return false;
  if (samples_.empty() && !dropped_any_) first_stamp_ = stamp;
  samples_.push_back({stamp, pose});
  while (!samples_.empty() && stamp.secondsSince(samples_.front().stamp) > keep_) {
    samples_.pop_front();
    dropped_any_ = true;
  }
  return true;
}

std::optional<Pose2> PoseBuffer::at(Stamp stamp) const {
  // First sample at or after the stamp.
  const auto after = std::lower_bound(samples_.begin(), samples_.end(), stamp,
                                      [](const Sample& s, Stamp t) { return s.stamp < t; });
  if (after == samples_.end()) return std::nullopt;
  if (after->stamp == stamp) return after->pose;
  if (after == samples_.begin()) return std::nullopt;
  const Sample& b = *after;
  const Sample& a = *(after - 1);
  if (stamp.secondsSince(a.stamp) > max_gap_ || b.stamp.secondsSince(stamp) > max_gap_) return std::nullopt;
  const double t = stamp.secondsSince(a.stamp) / b.stamp.secondsSince(a.stamp);
  const double turn = std::remainder(b.pose.theta - a.pose.theta, 2.0 * std::numbers::pi);
  return Pose2{a.pose.x + t * (b.pose.x - a.pose.x), a.pose.y + t * (b.pose.y - a.pose.y),
               std::remainder(a.pose.theta + t * turn, 2.0 * std::numbers::pi)};
}

}  // namespace scanfilter
