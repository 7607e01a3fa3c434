#include "scanfilter/surface_memory.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace scanfilter {

namespace {
double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

// Where the line from p0 to p1 crosses the segment's line, as a fraction of
// the way from p0; nullopt when both lie on one side.
template <typename S>
std::optional<double> crossingFraction(const S& s, const Eigen::Vector2d& p0, const Eigen::Vector2d& p1) {
  const double d0 = s.normal.dot(p0 - s.a), d1 = s.normal.dot(p1 - s.a);
  if ((d0 > 0.0) == (d1 > 0.0)) return std::nullopt;
  return d0 / (d0 - d1);
}
}  // namespace

void SurfaceMemory::clear() {
  segments_.clear();
  last_remembered_.reset();
  last_origin_.reset();
}

void SurfaceMemory::forget(const Eigen::Vector2d& origin, Stamp now) {
  std::erase_if(segments_, [&](const Segment& s) { return now.secondsSince(s.stamp) > params_.lifetime; });
  if (last_origin_) {
    const Eigen::Vector2d from = *last_origin_;
    std::erase_if(segments_, [&](const Segment& s) {
      const std::optional<double> t = crossingFraction(s, from, origin);
      if (!t) return false;
      const double along = s.unit.dot(from + (origin - from) * *t - s.a);
      return along >= 0.0 && along <= s.length;
    });
  }
  last_origin_ = origin;
}

bool SurfaceMemory::crosses(const Segment& s, const Eigen::Vector2d& origin, const Eigen::Vector2d& p,
                            double margin) const {
  const std::optional<double> t = crossingFraction(s, origin, p);
  if (!t || std::abs(s.normal.dot(p - s.a)) < margin) return false;  // on its line: noise and pose error
  const double along = s.unit.dot(origin + (p - origin) * *t - s.a);
  return along > params_.end_margin && along < s.length - params_.end_margin;
}

bool SurfaceMemory::seenThrough(const Eigen::Vector2d& origin, const Eigen::Vector2d& p, Stamp now) const {
  const double margin = params_.behind_margin + params_.behind_margin_per_m * (p - origin).norm();
  const Eigen::Vector2d lo = origin.cwiseMin(p), hi = origin.cwiseMax(p);
  return std::any_of(segments_.begin(), segments_.end(), [&](const Segment& s) {
    const bool boxes_meet = (s.hi.array() >= lo.array()).all() && (s.lo.array() <= hi.array()).all();
    return boxes_meet && now.secondsSince(s.stamp) <= params_.lifetime && crosses(s, origin, p, margin);
  });
}

SurfaceMemory::Segment SurfaceMemory::segmentBetween(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                                     Stamp stamp) {
  const double length = (b - a).norm();
  const Eigen::Vector2d unit = (b - a) / length;
  return {a, unit, {-unit.y(), unit.x()}, length, a.cwiseMin(b), a.cwiseMax(b), stamp};
}

std::vector<SurfaceMemory::Segment> SurfaceMemory::freshSegments(
    std::span<const Eigen::Vector2d> points, const BeamMask& usable, const Eigen::Vector2d& origin, Stamp stamp,
    std::vector<std::pair<bool, bool>>& seen_past) const {
  const double min_sin = std::sin(radians(params_.min_incidence_deg));
  std::vector<Segment> fresh;
  for (const StraightSegment& s : straightSegments(points, usable, origin, params_.segments)) {
    const Segment segment = segmentBetween(s.a, s.b, stamp);
    const Eigen::Vector2d to_middle = ((s.a + s.b) / 2 - origin).normalized();
    // The sine of the angle between the beam to its middle and the surface.
    if (std::abs(to_middle.x() * segment.unit.y() - to_middle.y() * segment.unit.x()) < min_sin) continue;
    fresh.push_back(segment);
    seen_past.emplace_back(s.a_seen_past, s.b_seen_past);
  }
  return fresh;
}

bool SurfaceMemory::seenAgain(const Segment& now, const Segment& old) const {
  if (std::abs(now.unit.dot(old.unit)) < std::cos(radians(params_.merge_angle_deg))) return false;
  const Eigen::Vector2d now_b = now.a + now.unit * now.length;
  if (std::abs(old.normal.dot(now.a - old.a)) > params_.merge_offset ||
      std::abs(old.normal.dot(now_b - old.a)) > params_.merge_offset)
    return false;
  const double t0 = old.unit.dot(now.a - old.a), t1 = old.unit.dot(now_b - old.a);
  return std::min(std::max(t0, t1), old.length) > std::max(std::min(t0, t1), 0.0);  // they overlap
}

SurfaceMemory::Segment SurfaceMemory::merged(const Segment& now, std::pair<bool, bool> seen_past,
                                             const std::vector<Segment>& olds) const {
  // Through the new segment's middle (the latest pose), in the direction of
  // all of them weighted by length (a short new piece is the least sure of
  // its direction), over the extent of all.
  Eigen::Vector2d direction = now.unit * now.length;
  for (const Segment& old : olds) direction += (old.unit.dot(now.unit) >= 0.0 ? old.unit : -old.unit) * old.length;
  direction.normalize();
  const Eigen::Vector2d middle = now.a + now.unit * (now.length / 2);
  const double now_a = direction.dot(now.a - middle), now_b = direction.dot(now.a + now.unit * now.length - middle);
  double lo = std::min(now_a, now_b), hi = std::max(now_a, now_b);
  for (const Segment& old : olds)
    for (const Eigen::Vector2d& end : {old.a, Eigen::Vector2d(old.a + old.unit * old.length)}) {
      lo = std::min(lo, direction.dot(end - middle));
      hi = std::max(hi, direction.dot(end - middle));
    }
  // Where the new frame saw past an end, the surface ends there now.
  if (seen_past.first) (now_a < now_b ? lo : hi) = now_a;
  if (seen_past.second) (now_b < now_a ? lo : hi) = now_b;
  return segmentBetween(middle + direction * lo, middle + direction * hi, now.stamp);
}

void SurfaceMemory::remember(std::span<const Eigen::Vector2d> points, const BeamMask& usable,
                             const Eigen::Vector2d& origin, Stamp stamp) {
  // A stamp that did not advance is no clock (as in step 2's cache): remembered.
  if (last_remembered_) {
    const double since = stamp.secondsSince(*last_remembered_);
    if (since > 0.0 && since < params_.min_interval) return;
  }
  last_remembered_ = stamp;
  std::vector<std::pair<bool, bool>> seen_past;
  std::vector<Segment> fresh = freshSegments(points, usable, origin, stamp, seen_past);
  for (std::size_t k = 0; k < fresh.size(); ++k) {
    std::vector<Segment> olds;
    std::erase_if(segments_, [&](const Segment& old) {
      if (!seenAgain(fresh[k], old)) return false;
      olds.push_back(old);
      return true;
    });
    if (!olds.empty()) fresh[k] = merged(fresh[k], seen_past[k], olds);
  }
  segments_.insert(segments_.end(), fresh.begin(), fresh.end());
}

}  // namespace scanfilter
