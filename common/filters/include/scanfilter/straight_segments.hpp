#pragma once
#include <functional>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "scanfilter/beam_mask.hpp"

namespace scanfilter {

// A stretch of surface that one frame saw as a straight line of returns: the
// least-squares line through them, cut at the projections of the first and
// the last return.
struct StraightSegment {
  Eigen::Vector2d a;
  Eigen::Vector2d b;
  // Whether the frame saw past the end at a (at b): the next beam's return,
  // a usable one, lies farther from the sensor by more than
  // StraightSegmentParams::end_step, so the surface ends there rather than
  // leaving the view, turning a corner or hiding behind something nearer.
  bool a_seen_past = false;
  bool b_seen_past = false;
};

struct StraightSegmentParams {
  double max_spacing = 0.15;    // m, neighbouring returns farther apart break a run
  double max_deviation = 0.03;  // m, a run is split at the return farthest off its chord, if farther
  int min_returns = 6;          // fewer make no segment
  double min_length = 0.30;     // m, shorter make no segment
  double end_step = 0.15;       // m, see StraightSegment::a_seen_past
  // m, how far apart two returns a run joins across a gap may lie (see
  // straightSegments); 0: runs never cross a gap.
  double max_gap = 0.30;
};

// Whether a surface stands between two returns of a run, where the frame
// itself saw through (evidence from elsewhere, such as step 2's cache).
using SurfaceAcrossGap = std::function<bool(const Eigen::Vector2d& from, const Eigen::Vector2d& to)>;

// The straight segments among the usable returns, in beam order (split and
// fit): runs of neighbouring beams whose returns lie within max_spacing of
// each other, split recursively where a return lies more than max_deviation
// off the chord, each piece fitted by least squares. `points` are the
// returns in any one frame of reference (NaN without a return), `origin` the
// sensor in the same frame. On a full turn (`full_turn`) the last beam
// neighbours the first, so a surface across the scan's seam is one segment.
//
// A run also continues across a gap: beams that saw through it (returning
// farther than the returns either side by more than end_step) or gave no
// usable return, up to the first usable return within max_gap of the run's
// last, when `surface_across_gap` says a surface stands between the two. A
// pane or a mirror returns the beam only now and then, even near its
// normal, so one frame sees it with holes; an opening is not a surface
// seen from elsewhere.
std::vector<StraightSegment> straightSegments(std::span<const Eigen::Vector2d> points, const BeamMask& usable,
                                              const Eigen::Vector2d& origin, const StraightSegmentParams& params,
                                              bool full_turn = false, const SurfaceAcrossGap& surface_across_gap = {});

}  // namespace scanfilter
