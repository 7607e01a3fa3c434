#pragma once
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "scanfilter/beam_mask.hpp"
#include "scanfilter/stamp.hpp"
#include "scanfilter/straight_segments.hpp"

namespace scanfilter {

// Parameters of the surface memory (config/filter.yaml, penetration_filter:
// surface_memory, documents each; docs/accuracy.md, Beyond the paper 24).
struct SurfaceMemoryParams {
  double lifetime = 20.0;           // s a surface not seen again is remembered; 0: off
  double min_interval = 0.25;       // s between frames whose surfaces are remembered
  double min_incidence_deg = 45.0;  // degrees, surfaces seen at a shallower angle are not remembered
  double behind_margin = 0.20;      // m, a return must lie this far beyond a remembered line
  double behind_margin_per_m = 0.02;  // m per m of range added to it
  double end_margin = 0.10;         // m, a beam crossing a remembered segment this near its end does not count
  double merge_angle_deg = 10.0;    // degrees, a surface seen again: directions within this
  double merge_offset = 0.30;       // m, ... and the new segment's ends this near the remembered line
  StraightSegmentParams segments;
};

// Beyond the paper: the flat surfaces that judged frames saw well, remembered
// longer than step 2's cache. Mirrors and panes return directly only near
// normal incidence, so the cache often no longer holds the one behind a
// ghost; a segment does not thicken as cells do (docs/accuracy.md, "Where
// step 2 loses"). A kept return that lies beyond a remembered segment, on
// the far side of its line from the sensor by more than the margin, with the
// beam crossing the segment inside its ends, was seen through a surface.
//
// What is remembered: segments of the kept returns, seen at `min_incidence_deg`
// or steeper (no grazing walls, whose returns are displaced, and no trails of
// mixed returns, which run along the beam). A surface seen again replaces
// what was remembered of it: the newest frame puts it where it is now
// (drifting odometry moves old segments), over the extent of both, except
// past an end the new frame saw past. A segment the sensor's path crosses is
// forgotten: nothing solid stood there.
class SurfaceMemory {
 public:
  explicit SurfaceMemory(const SurfaceMemoryParams& params) : params_(params) {}

  bool enabled() const { return params_.lifetime > 0.0; }
  void clear();
  // Forgets what is older than the lifetime, and what the sensor's path
  // since the last call crossed.
  void forget(const Eigen::Vector2d& origin, Stamp now);
  // True when the return at p, seen from origin at `now`, lies beyond a
  // remembered surface (one seen again within the lifetime: judging without
  // forgetting first still ignores older ones).
  bool seenThrough(const Eigen::Vector2d& origin, const Eigen::Vector2d& p, Stamp now) const;
  // Remembers the straight surfaces of one frame's usable returns.
  void remember(std::span<const Eigen::Vector2d> points, const BeamMask& usable, const Eigen::Vector2d& origin,
                Stamp stamp);
  std::size_t size() const { return segments_.size(); }

 private:
  struct Segment {
    Eigen::Vector2d a;
    Eigen::Vector2d unit;    // from a along the segment
    Eigen::Vector2d normal;  // unit, to its left
    double length = 0.0;
    Eigen::Vector2d lo, hi;  // bounding box
    Stamp stamp;             // when it was last seen
  };
  static Segment segmentBetween(const Eigen::Vector2d& a, const Eigen::Vector2d& b, Stamp stamp);
  std::vector<Segment> freshSegments(std::span<const Eigen::Vector2d> points, const BeamMask& usable,
                                     const Eigen::Vector2d& origin, Stamp stamp,
                                     std::vector<std::pair<bool, bool>>& seen_past) const;
  bool seenAgain(const Segment& now, const Segment& old) const;
  Segment merged(const Segment& now, std::pair<bool, bool> seen_past, const std::vector<Segment>& olds) const;
  bool crosses(const Segment& s, const Eigen::Vector2d& origin, const Eigen::Vector2d& p, double margin) const;

  SurfaceMemoryParams params_;
  std::vector<Segment> segments_;
  std::optional<Stamp> last_remembered_;
  std::optional<Eigen::Vector2d> last_origin_;
};

}  // namespace scanfilter
