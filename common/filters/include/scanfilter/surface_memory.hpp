#pragma once
#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "scanfilter/beam_mask.hpp"
#include "scanfilter/mirror_crossing.hpp"
#include "scanfilter/mirror_ghost_params.hpp"
#include "scanfilter/sparse_surfaces.hpp"
#include "scanfilter/stamp.hpp"
#include "scanfilter/straight_segments.hpp"

namespace scanfilter {

// Parameters of the surface memory (config/filter.yaml, penetration_filter:
// surface_memory, documents each; docs/beyond-the-paper.md, 24).
struct SurfaceMemoryParams {
  double lifetime = 20.0;                   // s a stretch of surface not seen again is remembered; 0: off
  double min_interval = 0.25;               // s between frames whose surfaces are remembered
  double min_beam_surface_angle_deg = 45.0;  // surfaces the beam meets at a shallower angle are not remembered
  double surface_margin = 0.20;             // m, a return this near a remembered line lies on it
  double surface_margin_per_m = 0.02;       // m per m of range added to it
  double end_margin = 0.10;                 // m, a beam crossing a segment this near a seen end does not count
  double merge_angle_deg = 10.0;            // degrees, a surface seen again: directions within this
  double merge_offset = 0.30;               // m, ... and the new segment's ends this near the remembered line
  std::size_t max_segments = 2000;          // the oldest go first beyond this (stamps that do not advance)
  double head_on_deg = 5.0;                 // degrees off a segment's normal where a mirror or pane returns the beam
  int head_on_through_beams = 2;            // beams seen through it there, none on it: it is gone; 0: never
  // Panes and mirrors remembered longer (Beyond the paper 34).
  double specular_lifetime = 120.0;         // s a confirmed pane or mirror is remembered; <= lifetime: lifetime
  // A sparse surface no frame confirmed as a pane or a mirror outlives the
  // cache it was found in by little (Beyond the paper 40).
  double sparse_lifetime = 4.0;             // s an unconfirmed sparse surface is remembered
  double specular_confirm_distance = 0.10;  // m, a return this near a segment's line lies on it when confirming
  double specular_min_pass_share = 0.5;     // of the beams meeting it off the lobe, the share that must pass
  // The aligned frames' drift, not the raw odometry's (Beyond the paper 41).
  double drift_margin_per_m = 0.005;        // m of a pane's surface margin per m driven since it was seen
  double drift_margin_deg_per_m = 0.25;     // ... and this heading drift per m driven, times the return's range
  // Ghosts found as mirror images of what the cache holds (Beyond the paper
  // 35): configured here, beside the panes and mirrors it needs; read by
  // the penetration filter's MirrorGhostCheck.
  MirrorGhostParams mirror_ghosts;
  StraightSegmentParams segments;
  // Surfaces the cache holds a return at a time, found by the penetration
  // filter (sparse_surfaces.hpp) and remembered here too.
  SparseSurfaceParams sparse_surfaces;
};

// Beyond the paper: the flat surfaces that judged frames saw well, remembered
// longer than step 2's cache. Mirrors and panes return directly only near
// normal incidence, so the cache often no longer holds the one in front of a
// ghost; a segment does not thicken as cells do
// (docs/accuracy-investigations.md, "Where step 2 loses"). A kept return
// that lies beyond a remembered segment, on the far side of its line from
// the sensor by more than the margin, with the beam crossing the segment
// inside its ends, was seen through a surface.
//
// What is remembered: segments of the kept returns that the beam to their
// middle meets at `min_beam_surface_angle_deg` or more (no grazing walls,
// whose returns are displaced, and no trails of mixed returns, which run
// along the beam), across the narrow holes the frame saw through where the
// cache holds the surface (a pane returns the beam only now and then:
// StraightSegmentParams::max_gap), and the lines of the cache's sparse cells
// that PenetrationFilter finds (rememberSegments, sparse_surfaces.hpp; at
// their own angle). A surface seen again replaces what was
// remembered of it: the newest frame puts it where it is now (drifting
// odometry moves old segments). Over the stretch the new frame saw, the
// segment is as new; the remembered stretches beyond it stay, on the new
// line, as old as they were, except past an end the new frame saw past. A
// segment the sensor's path crosses is forgotten: nothing solid stood
// there; so is one a judged frame sees through head-on
// (forgetSeenThroughHeadOn: a door that opened).
class SurfaceMemory {
 public:
  explicit SurfaceMemory(const SurfaceMemoryParams& params);

  bool enabled() const { return params_.lifetime > 0.0; }
  void clear();
  // Forgets what was last seen more than its lifetime before `now` (a
  // confirmed pane or mirror: specular_lifetime), and what the sensor's path
  // since the last call crossed; adds that path to the distance driven (the
  // drift margin's clock).
  void forget(const Eigen::Vector2d& origin, Stamp now);
  // True when the return at p, seen from origin at `now`, lies beyond a
  // remembered surface (one seen within its lifetime: judging without
  // forgetting first still ignores older ones), by more than the surface
  // margin (a pane's or a mirror's growing with the path driven since it
  // was seen: driftMargin).
  bool liesBeyondASurface(const Eigen::Vector2d& origin, const Eigen::Vector2d& p, Stamp now) const;
  // Whether pred holds for a crossing of the beam from origin to p with the
  // line of a confirmed pane or mirror (one seen within its lifetime), on
  // the remembered stretch or anywhere past it, p lying beyond that line by
  // min_depth or more, plus the pane's drift margin (driftMargin: where an
  // old one may have moved). Not the surface margin: the caller's test of
  // the return's image brings its own tolerance. Stops at the first, in the
  // memory's order, for which pred holds. The crossing counts as on the
  // stretch only inside its end margins, as for liesBeyondASurface
  // (MirrorCrossing::within_segment; past_end says how far past the
  // stretch's nearer end it lies, the end margins counted as on it); it
  // names the segment (MirrorCrossing::surface, an index below size()).
  bool anyMirrorCrossed(const Eigen::Vector2d& origin, const Eigen::Vector2d& p, Stamp now, double min_depth,
                        const std::function<bool(const MirrorCrossing&)>& pred) const;
  // Confirms the sparse segments (rememberSegments) this frame faces as
  // panes or mirrors: it sees returns on them within the specular lobe
  // (head_on_deg of the foot of its perpendicular, + specular_confirm_distance),
  // and outside the lobe at least specular_min_pass_share of the beams that
  // meet them pass through (2 or more: a segment lying wholly in the lobe
  // confirms nothing), where a row of chair legs returns most of them; a
  // glossy surface returns some at any angle (Beyond the paper 35). A
  // confirmed one is remembered specular_lifetime, and stays confirmed:
  // what merges with it on its line is that surface
  // (docs/beyond-the-paper.md, 34).
  // `returns`: every beam with a return. A no-op with the rule off.
  void confirmPanesAndMirrors(std::span<const Eigen::Vector2d> points, const BeamMask& returns,
                              const Eigen::Vector2d& origin);
  // Forgets the segments a frame saw through head-on. A mirror or a pane
  // returns the beam within head_on_deg of its normal (its specular lobe),
  // so a frame whose beams there pass through it, none ending on it, shows
  // that nothing stands there now: a door that opened, a person who walked
  // off. Without this, returns behind such a segment are deleted until it
  // expires. `returns`: every beam with a return, whatever its label.
  void forgetSeenThroughHeadOn(std::span<const Eigen::Vector2d> points, const BeamMask& returns,
                               const Eigen::Vector2d& origin);
  // Remembers the straight surfaces of one frame's usable returns (on a
  // full turn, across the scan's seam too; across the gaps that
  // `surface_across_gap` vouches for, straightSegments). False when the
  // frame came sooner than min_interval after the last one remembered, and
  // nothing was.
  bool remember(std::span<const Eigen::Vector2d> points, const BeamMask& usable, const Eigen::Vector2d& origin,
                Stamp stamp, bool full_turn = false, const SurfaceAcrossGap& surface_across_gap = {});
  // Remembers segments found otherwise (sparseSurfaces), seen from `origin`
  // at `stamp`; those the beam to their middle meets at less than
  // `min_beam_surface_angle_deg` are left out.
  void rememberSegments(std::span<const StraightSegment> found, const Eigen::Vector2d& origin, Stamp stamp,
                        double min_beam_surface_angle_deg);
  std::size_t size() const { return segments_.size(); }

  // For breakdowns (bench/misdetected_error_breakdown): what the memory
  // holds within `radius` of p, on a segment's stretch, at `now`.
  struct Held {
    bool alive = false;           // seen within its lifetime
    bool pane_or_mirror = false;  // confirmed (of the live ones, if any)
  };
  std::optional<Held> heldNear(const Eigen::Vector2d& p, Stamp now, double radius) const;

 private:
  struct Segment {
    Eigen::Vector2d a;
    Eigen::Vector2d unit;    // from a along the segment
    Eigen::Vector2d normal;  // unit, to its left
    double length = 0.0;
    Eigen::Vector2d lo, hi;  // bounding box
    Stamp last_seen;
    // How far inside each end (a, then the other) a beam must cross it:
    // end_margin at an end a frame saw, 0 where it joins a stretch seen at
    // another time (end_margin again once that stretch is dropped).
    double margin_a = 0.0;
    double margin_b = 0.0;
    bool sparse = false;               // found as a line of single cached returns (rememberSegments)
    bool pane_or_mirror = false;       // a sparse one a frame confirmed (confirmPanesAndMirrors)
    double path_when_seen = 0.0;       // m the sensor had driven when it was last seen

    Eigen::Vector2d b() const { return a + unit * length; }
    // Whether a point `along` the segment from a lies inside its end margins.
    bool insideEnds(double along) const { return along > margin_a && along < length - margin_b; }
    // Where the line from p0 to p1 crosses this segment's line, as a
    // distance along it from a; nullopt when both lie on one side.
    std::optional<double> crossingAlong(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1) const;
  };
  // A segment of the judged frame and whether the frame saw past its ends.
  struct Fresh {
    Segment segment;
    bool a_seen_past = false;
    bool b_seen_past = false;
  };
  // From a to b; `direction_if_a_point` (a unit vector) when they coincide.
  Segment segmentBetween(const Eigen::Vector2d& a, const Eigen::Vector2d& b, Stamp last_seen, double margin_a,
                         double margin_b, const Eigen::Vector2d& direction_if_a_point) const;
  std::vector<Fresh> facingSegments(std::span<const StraightSegment> found, const Eigen::Vector2d& origin,
                                    Stamp stamp, double min_beam_surface_angle_deg) const;
  // Each as a surface seen again (merged with what it overlaps) or new.
  void mergeIn(const std::vector<Fresh>& fresh_segments);
  bool seenAgain(const Segment& now, const Segment& old) const;
  // The new segment and what is remembered beyond it, on one line.
  std::vector<Segment> merged(const Fresh& now, const std::vector<Segment>& olds) const;
  bool beamPassesThrough(const Segment& s, const Eigen::Vector2d& origin, const Eigen::Vector2d& p,
                         double surface_margin) const;
  double surfaceMargin(double range) const;
  // The margin's growth for a pane or a mirror: the drift of the path
  // driven since it was seen (0 for any other segment).
  double driftMargin(const Segment& s, double range) const;
  double lifetimeOf(const Segment& s) const;
  // Seen within its lifetime.
  bool alive(const Segment& s, Stamp now) const { return now.secondsSince(s.last_seen) <= lifetimeOf(s); }
  // The margin a return at `range` must lie off the segment's line by to lie beyond it.
  double marginOf(const Segment& s, double range) const;
  bool confirmedHeadOn(const Segment& s, std::span<const Eigen::Vector2d> points, const BeamMask& returns,
                       const Eigen::Vector2d& origin) const;
  bool seenThroughHeadOn(const Segment& s, std::span<const Eigen::Vector2d> points, const BeamMask& returns,
                         const Eigen::Vector2d& origin) const;
  void keepWithinBound();
  // Erases the segments `gone` says, then endWhereJoinsWent.
  void drop(const std::function<bool(const Segment&)>& gone);
  // Gives back the end margin where a piece joined one of `dropped`.
  void endWhereJoinsWent(const std::vector<Segment>& dropped);

  SurfaceMemoryParams params_;
  std::vector<Segment> segments_;
  std::optional<Stamp> last_remembered_;
  std::optional<Eigen::Vector2d> last_origin_;
  double drift_heading_per_m_;  // tan(drift_margin_deg_per_m)
  double path_ = 0.0;           // m the sensor has driven since clear(), counted in kPathStep steps
  std::optional<Eigen::Vector2d> path_anchor_;  // where the sensor was when path_ last grew
  // The path grows once the sensor is this far from where it last grew, so
  // that the frames' alignment jitter at a standstill adds no distance.
  static constexpr double kPathStep = 0.05;  // m
  // A frame confirms a pane or a mirror only when at least this many of its
  // beams pass through it outside the specular lobe.
  static constexpr int kMinBeamsThroughOffLobe = 2;
};

}  // namespace scanfilter
